#include "object_model.hpp"

#include <cmath>

namespace antipode::cells {

namespace {

// The centre of mass, as centre_on_mass() says. A closed surface's volume centroid lies inside
// its bounding box; the signed volume of an open scan wound both ways cancels to nearly nothing,
// and its "centroid" lands anywhere (40 cm away for a 7 cm can, which then falls off the table).
Eigen::Vector3d mass_centre(const TriangleMesh& visual, const std::vector<TriangleMesh>& hulls) {
  const Eigen::AlignedBox3d box = visual.bounds().cast<double>();
  Eigen::Vector3d centroid = visual.volume_centroid();
  if (centroid.allFinite() && box.contains(centroid)) return centroid;
  double weight = 0.0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const TriangleMesh& hull : hulls) {
    const double volume = std::abs(hull.volume());
    weight += volume;
    sum += volume * hull.volume_centroid();
  }
  return weight > 0.0 ? Eigen::Vector3d(sum / weight) : box.center();
}

}  // namespace

void centre_on_mass(TriangleMesh& visual, std::vector<TriangleMesh>& hulls) {
  const Eigen::Affine3f shift(Eigen::Translation3f(-mass_centre(visual, hulls).cast<float>()));
  visual.transform(shift);
  for (auto& hull : hulls) hull.transform(shift);
}

}  // namespace antipode::cells
