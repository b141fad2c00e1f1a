#pragma once
// Drawing clouds and grippers into an OpenCV image through an OrthoView.

#include <vector>

#include <opencv2/core.hpp>

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"
#include "antipode/geometry/hand_body.hpp"
#include "ortho_view.hpp"

namespace antipode::pictures {

/// Draws the points far to near (so nearer ones cover farther ones), shaded by depth.
void draw_cloud(cv::Mat& image, const OrthoView& view, const Cloud& cloud);

/// Draws the hand's fingers and palm as box outlines.
void draw_hand(cv::Mat& image, const OrthoView& view, const HandBody& body, const Hand& hand,
               const cv::Scalar& colour, int thickness);

}  // namespace antipode::pictures
