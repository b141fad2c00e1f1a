#include "reference_cloud.hpp"

#include <memory>

#include "antipode/geometry/preprocess.hpp"

namespace antipode::training {

CloudPtr prepared_reference(const Cloud& cloud) {
  return std::make_shared<Cloud>(
      voxelize(remove_non_finite(cloud), PreprocessOptions{}.voxel_size_m));
}

}  // namespace antipode::training
