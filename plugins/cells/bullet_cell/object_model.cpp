#include "object_model.hpp"

namespace antipode::cells {

void centre_on_mass(TriangleMesh& visual, std::vector<TriangleMesh>& hulls) {
  const Eigen::Affine3f shift(Eigen::Translation3f(-visual.volume_centroid().cast<float>()));
  visual.transform(shift);
  for (auto& hull : hulls) hull.transform(shift);
}

}  // namespace antipode::cells
