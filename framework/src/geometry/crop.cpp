#include "antipode/core/error.hpp"
#include "antipode/geometry/preprocess.hpp"
#include "cloud_select.hpp"

namespace antipode {

void AxisBox::validate(const char* what) const {
  if (!min_m.allFinite() || !max_m.allFinite()) {
    throw Error(std::string(what) + ": corners must be finite");
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (min_m[axis] > max_m[axis]) {
      throw Error(std::string(what) + ": min " + "xyz"[axis] + " (" + std::to_string(min_m[axis]) +
                  ") is above max " + "xyz"[axis] + " (" + std::to_string(max_m[axis]) + ")");
    }
  }
}

Cloud remove_non_finite(const Cloud& cloud) {
  return geometry::select_points(cloud, [](const Eigen::Vector3f& p) { return p.allFinite(); });
}

Cloud crop(const Cloud& cloud, const AxisBox& box) {
  return geometry::select_points(cloud,
                                 [&box](const Eigen::Vector3f& p) { return box.contains(p); });
}

}  // namespace antipode
