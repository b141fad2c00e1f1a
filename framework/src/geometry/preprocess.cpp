#include "antipode/geometry/preprocess.hpp"

#include <cmath>
#include <sstream>

#include "antipode/core/error.hpp"

namespace antipode {
namespace {

std::string describe(const Eigen::Vector3f& min, const Eigen::Vector3f& max) {
  std::ostringstream text;
  text.precision(3);
  text << "[" << min.x() << ", " << min.y() << ", " << min.z() << "] .. [" << max.x() << ", "
       << max.y() << ", " << max.z() << "]";
  return text.str();
}

std::string bounding_box(const Cloud& cloud) {
  Eigen::Vector3f min = cloud.points_m.front();
  Eigen::Vector3f max = min;
  for (const auto& p : cloud.points_m) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  return describe(min, max);
}

void check_options(const PreprocessOptions& options) {
  if (options.workspace) options.workspace->validate("workspace");
  if (!(options.voxel_size_m >= 0.0f) || !std::isfinite(options.voxel_size_m)) {
    throw Error("preprocess: voxel size must be >= 0, got " + std::to_string(options.voxel_size_m));
  }
}

}  // namespace

Cloud preprocess(const Cloud& cloud, const PreprocessOptions& options) {
  check_options(options);
  if (cloud.empty()) throw Error("the cloud has no points");
  Cloud out = remove_non_finite(cloud);
  if (out.empty()) {
    throw Error("the cloud has no finite point (all " + std::to_string(cloud.size()) +
                " are NaN or infinite)");
  }
  if (options.workspace) {
    const std::string box = bounding_box(out);
    out = crop(out, *options.workspace);
    if (out.empty()) {
      throw Error("no point of the cloud lies in the workspace " +
                  describe(options.workspace->min_m, options.workspace->max_m) +
                  " (the cloud spans " + box + " in frame '" + cloud.frame + "')");
    }
  }
  if (options.voxel_size_m > 0.0f) out = voxelize(out, options.voxel_size_m);
  return out;
}

}  // namespace antipode
