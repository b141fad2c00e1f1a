#pragma once
// Drawing clouds and grippers into an OpenCV image through an OrthoView.

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "antipode/core/cloud.hpp"
#include "antipode/core/hand.hpp"
#include "antipode/geometry/hand_body.hpp"
#include "ortho_view.hpp"

namespace antipode::pictures {

/// Draws the points far to near (so nearer ones cover farther ones), shaded by depth. With
/// `object_of_point` (one entry per point), the points of object k take object_colour(k).
void draw_cloud(cv::Mat& image, const OrthoView& view, const Cloud& cloud,
                const std::vector<std::int32_t>& object_of_point = {});

/// Draws `points_m` (the view's frame) far to near in `colour`, darker with distance: a
/// second layer over a cloud, e.g. a cell's true surfaces.
void draw_points(cv::Mat& image, const OrthoView& view,
                 const std::vector<Eigen::Vector3f>& points_m, const cv::Scalar& colour);

/// A colour per object id, eight that tell apart, repeating; grey for -1 (no object).
cv::Scalar object_colour(std::int32_t id);

/// Draws the outline of `box` (in the frame X_FrameHand places).
void draw_box(cv::Mat& image, const OrthoView& view, const HandBox& box,
              const Eigen::Isometry3d& X_FrameHand, const cv::Scalar& colour, int thickness);

/// Draws the hand's fingers and palm as box outlines.
void draw_hand(cv::Mat& image, const OrthoView& view, const HandBody& body, const Hand& hand,
               const cv::Scalar& colour, int thickness);

/// The mean of the cloud's points (the origin for an empty cloud).
Eigen::Vector3d centroid(const Cloud& cloud);

/// "Up" in pictures of `cloud`: -y for a cloud in frame "sensor", +z otherwise.
Eigen::Vector3d default_up(const Cloud& cloud);

/// A view of `target` from the cloud's first sensor (from +z when it has none), `extent_m`
/// from the centre to the picture's edge.
OrthoView view_from_sensor(const Cloud& cloud, const Eigen::Vector3d& target,
                           const Eigen::Vector3d& up, double extent_m, int size_px);

/// Writes `image` to the PNG `file` atomically (see atomic_file.hpp); throws antipode::Error.
void write_png(const std::string& file, const cv::Mat& image);

/// Writes `text` at the top left of `image`, one line per item.
void caption(cv::Mat& image, const std::vector<std::string>& lines);

}  // namespace antipode::pictures
