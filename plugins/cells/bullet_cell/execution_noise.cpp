#include "execution_noise.hpp"

#include "antipode/core/random.hpp"

namespace antipode::cells {

namespace {
// The cell's seeded streams: 1 and 2 place the scene, 1000 + k render capture k.
constexpr std::uint64_t kExecutionStream = 3;
}  // namespace

Eigen::Isometry3d executed_pose(const Eigen::Isometry3d& X_BaseHand, const ExecutionNoise& noise,
                                std::uint64_t cell_seed, int attempt) {
  if (noise.none()) return X_BaseHand;
  RandomStream random = RandomStream(cell_seed)
                            .derive(kExecutionStream)
                            .derive(noise.seed)
                            .derive(std::uint64_t(attempt));
  Eigen::Vector3d offset_m, rotation_rad;
  for (int i = 0; i < 3; ++i) offset_m[i] = noise.position_m * random.normal();
  for (int i = 0; i < 3; ++i) rotation_rad[i] = noise.rotation_rad * random.normal();
  Eigen::Isometry3d X = X_BaseHand;
  X.translation() += offset_m;
  if (rotation_rad.norm() > 0.0)
    X.linear() =
        Eigen::AngleAxisd(rotation_rad.norm(), rotation_rad.normalized()).toRotationMatrix() *
        X_BaseHand.linear();
  return X;
}

}  // namespace antipode::cells
