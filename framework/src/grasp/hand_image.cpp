#include "antipode/grasp/hand_image.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/objdetect.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "antipode/core/error.hpp"

namespace antipode {
namespace {

cv::HOGDescriptor make_hog(const HandImageOptions& o) {
  const int block = o.block_cells * o.cell_px;
  return cv::HOGDescriptor(cv::Size(o.cols(), o.rows()), cv::Size(block, block),
                           cv::Size(o.cell_px, o.cell_px), cv::Size(o.cell_px, o.cell_px), o.bins);
}

std::vector<float> compute_hog(const cv::HOGDescriptor& hog, const HandImage& image,
                               const HandImageOptions& options) {
  if (image.rows != options.rows() || image.cols != options.cols() ||
      image.pixels.size() != static_cast<std::size_t>(image.rows) * static_cast<std::size_t>(image.cols)) {
    throw Error("HOG descriptor: the image is " + std::to_string(image.rows) + " x " +
                std::to_string(image.cols) + ", the options describe " +
                std::to_string(options.rows()) + " x " + std::to_string(options.cols()));
  }
  // A read-only view of the pixels: compute() does not write its input.
  const cv::Mat mat(image.rows, image.cols, CV_8UC1, const_cast<std::uint8_t*>(image.pixels.data()));
  std::vector<float> descriptor;
  hog.compute(mat, descriptor);
  return descriptor;
}

}  // namespace

std::size_t HandImageOptions::descriptor_size() const {
  const auto blocks_along = static_cast<std::size_t>(cells_along - block_cells + 1);
  const auto blocks_across = static_cast<std::size_t>(cells_across - block_cells + 1);
  return blocks_along * blocks_across * static_cast<std::size_t>(block_cells * block_cells) *
         static_cast<std::size_t>(bins);
}

void HandImageOptions::validate() const {
  const auto check = [](int value, const char* name) {
    if (value < 1) {
      throw Error(std::string("hand image: ") + name + " must be at least 1, got " +
                  std::to_string(value));
    }
  };
  check(cells_along, "cells_along");
  check(cells_across, "cells_across");
  check(cell_px, "cell_px");
  check(block_cells, "block_cells");
  check(bins, "bins");
  if (block_cells > cells_along || block_cells > cells_across) {
    throw Error("hand image: block_cells (" + std::to_string(block_cells) +
                ") exceeds cells_along or cells_across");
  }
}

HandImage hand_image(const Cloud& cloud, const Hand& hand, const HandGeometry& geometry,
                     const HandImageOptions& options) {
  options.validate();
  geometry.validate();
  HandImage image;
  image.rows = options.rows();
  image.cols = options.cols();
  image.pixels.assign(static_cast<std::size_t>(image.rows) * static_cast<std::size_t>(image.cols), 0);
  const Eigen::Isometry3d X_HandFrame = hand.X_FrameHand.inverse();
  const double row_per_m = image.rows / geometry.depth_m;
  const double col_per_m = image.cols / geometry.max_aperture_m;
  const double half_aperture_m = geometry.max_aperture_m / 2.0;
  for (const std::int32_t i : hand.closing_points) {
    if (i < 0 || static_cast<std::size_t>(i) >= cloud.size()) {
      throw Error("hand image: closing point " + std::to_string(i) + " is outside the cloud of " +
                  std::to_string(cloud.size()) + " points");
    }
    const Eigen::Vector3d p = X_HandFrame * cloud.points_m[static_cast<std::size_t>(i)].cast<double>();
    const int row = std::clamp(static_cast<int>(std::floor(p.x() * row_per_m)), 0, image.rows - 1);
    const int col = std::clamp(static_cast<int>(std::floor((p.y() + half_aperture_m) * col_per_m)),
                               0, image.cols - 1);
    image.pixels[static_cast<std::size_t>(row) * static_cast<std::size_t>(image.cols) +
                 static_cast<std::size_t>(col)] = 255;
  }
  return image;
}

std::vector<float> hog_descriptor(const HandImage& image, const HandImageOptions& options) {
  options.validate();
  return compute_hog(make_hog(options), image, options);
}

std::vector<std::vector<float>> hand_descriptors(const HandSet& set, const HandGeometry& geometry,
                                                 const HandImageOptions& options, int threads) {
  options.validate();
  geometry.validate();
  if (threads < 0) throw Error("hand descriptors: threads must be >= 0, got " + std::to_string(threads));
  std::vector<std::vector<float>> descriptors(set.hands.size());
  if (set.hands.empty()) return descriptors;
  if (set.cloud == nullptr) throw Error("hand descriptors: the hand set has no cloud");
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, set.hands.size(), 32),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        const cv::HOGDescriptor hog = make_hog(options);
                        for (std::size_t h = range.begin(); h != range.end(); ++h) {
                          descriptors[h] = compute_hog(
                              hog, hand_image(*set.cloud, set.hands[h], geometry, options), options);
                        }
                      });
  });
  return descriptors;
}

}  // namespace antipode
