#include "antipode/core/hand_geometry.hpp"

#include <string>

#include "antipode/core/error.hpp"

namespace antipode {
namespace {

void require_positive(double value, const char* field) {
  if (!(value > 0.0)) {
    throw Error(std::string("hand geometry: ") + field + " must be > 0, got " +
                std::to_string(value));
  }
}

}  // namespace

void HandGeometry::validate() const {
  require_positive(finger_width_m, "finger_width_m");
  require_positive(outer_diameter_m, "outer_diameter_m");
  require_positive(depth_m, "depth_m");
  require_positive(height_m, "height_m");
  require_positive(init_bite_m, "init_bite_m");
  require_positive(min_aperture_m, "min_aperture_m");
  require_positive(max_aperture_m, "max_aperture_m");
  if (!(palm_thickness_m >= 0.0 && palm_thickness_m < 1.0)) {
    throw Error("hand geometry: palm_thickness_m must be in [0, 1), got " +
                std::to_string(palm_thickness_m));
  }
  if (min_aperture_m >= max_aperture_m) {
    throw Error("hand geometry: min_aperture_m (" + std::to_string(min_aperture_m) +
                ") must be smaller than max_aperture_m (" + std::to_string(max_aperture_m) + ")");
  }
  if (max_aperture_m + 2.0 * finger_width_m > outer_diameter_m + 1e-3) {
    throw Error("hand geometry: max_aperture_m + 2 * finger_width_m exceeds outer_diameter_m");
  }
  if (init_bite_m >= depth_m) {
    throw Error("hand geometry: init_bite_m must be smaller than depth_m");
  }
}

}  // namespace antipode
