#include "cell_arm.hpp"

#include <algorithm>
#include <cmath>

#include <btBulletCollisionCommon.h>

#include "antipode/core/error.hpp"
#include "bullet_convert.hpp"

namespace antipode::cells {

struct CellArm::Impl {
  CellArmOptions options;
  KinematicChain chain;
  struct Shape {
    std::size_t link = 0;  // index into the chain's links
    std::string name;
    Eigen::Isometry3d X_LinkShape;
    std::unique_ptr<btCollisionShape> shape;
  };
  std::vector<Shape> shapes;
};

namespace {

std::unique_ptr<btCollisionShape> bullet_shape(const CollisionPrimitive& p) {
  std::unique_ptr<btCollisionShape> shape;
  switch (p.kind) {
    case CollisionPrimitive::Kind::kBox:
      shape = std::make_unique<btBoxShape>(to_bullet(Eigen::Vector3d(p.size_m / 2.0)));
      break;
    case CollisionPrimitive::Kind::kCylinder:
      shape = std::make_unique<btCylinderShapeZ>(
          to_bullet(Eigen::Vector3d(p.size_m.x(), p.size_m.x(), p.size_m.y() / 2.0)));
      break;
    case CollisionPrimitive::Kind::kSphere:
      shape = std::make_unique<btSphereShape>(btScalar(p.size_m.x()));
      break;
  }
  shape->setMargin(0.0f);
  return shape;
}

}  // namespace

CellArm::CellArm(const CellArmOptions& options) : impl_(std::make_unique<Impl>()) {
  impl_->options = options;
  const RobotModel robot = RobotModel::load(options.robot_file);
  impl_->chain = robot.chain(robot.root_link(), options.tip);
  const std::vector<std::string> links = impl_->chain.link_names();
  // Links from the first moving joint to the tip move with the arm. The fingers are not on
  // the chain: the cell's gripper model stands for them.
  bool moving = false;
  for (std::size_t i = 0; i < links.size(); ++i) {
    bool joint_moves = false;
    robot.parent_link(links[i], nullptr, &joint_moves);
    moving = moving || joint_moves;
    if (!moving) continue;
    for (const CollisionPrimitive& p : robot.collision_shapes(links[i]))
      impl_->shapes.push_back({i, links[i], p.X_LinkShape, bullet_shape(p)});
  }
  const std::vector<std::string>& joints = impl_->chain.joint_names();
  if (options.home_rad.size() != joints.size())
    throw HomeError("home_rad: " + std::to_string(options.home_rad.size()) + " values for the " +
                    std::to_string(joints.size()) + " joints of the arm (" + joints.front() +
                    " ... " + joints.back() + ")");
  if (!check_trajectory({joints, {options.home_rad}, {0}}).empty())
    throw HomeError("home_rad: a value is outside its joint's limits (or not finite)");
}

CellArm::~CellArm() = default;
CellArm::CellArm(CellArm&&) noexcept = default;
CellArm& CellArm::operator=(CellArm&&) noexcept = default;

const std::vector<std::string>& CellArm::joint_names() const { return impl_->chain.joint_names(); }

JointState CellArm::home() const { return {joint_names(), impl_->options.home_rad}; }

std::string CellArm::check_trajectory(const Trajectory& t) const {
  if (t.joint_names != joint_names()) return "the trajectory's joints are not the arm's";
  if (t.times_s.size() != t.positions_rad.size())
    return "the trajectory has " + std::to_string(t.times_s.size()) + " times for " +
           std::to_string(t.positions_rad.size()) + " waypoints";
  const auto& limits = impl_->chain.limits();
  for (std::size_t w = 0; w < t.positions_rad.size(); ++w) {
    const std::vector<double>& q = t.positions_rad[w];
    if (q.size() != joint_names().size())
      return "waypoint " + std::to_string(w) + " has " + std::to_string(q.size()) + " values for " +
             std::to_string(joint_names().size()) + " joints";
    for (std::size_t j = 0; j < q.size(); ++j)
      if (!std::isfinite(q[j]) || q[j] < limits[j].lower - 1e-6 || q[j] > limits[j].upper + 1e-6)
        return "waypoint " + std::to_string(w) + ": " + joint_names()[j] + " is outside its limits";
  }
  return "";
}

std::optional<ArmContact> CellArm::first_contact(const Trajectory& t,
                                                 const PhysicsWorld& world) const {
  const auto touched = [&](const Eigen::VectorXd& q) -> std::optional<ArmContact> {
    const std::vector<Eigen::Isometry3d> X_BaseLink = impl_->chain.link_poses(q);
    for (const Impl::Shape& s : impl_->shapes) {
      for (int id : world.overlapping(X_BaseLink[s.link] * s.X_LinkShape, *s.shape)) {
        if (world.role(id) == BodyRole::kGripper) continue;
        return ArmContact{s.name, world.name(id), 0};
      }
    }
    return std::nullopt;
  };
  if (t.empty()) return std::nullopt;
  if (auto contact = touched(joint_vector(t.positions_rad.front()))) return contact;
  // Each segment from its start (already checked) to its end, every check_step_rad.
  for (std::size_t w = 1; w < t.positions_rad.size(); ++w) {
    const Eigen::VectorXd from = joint_vector(t.positions_rad[w - 1]);
    const Eigen::VectorXd to = joint_vector(t.positions_rad[w]);
    const double largest = (to - from).cwiseAbs().maxCoeff();
    const int steps = std::max(1, int(std::ceil(largest / impl_->options.check_step_rad)));
    for (int k = 1; k <= steps; ++k) {
      if (auto contact = touched(from + (to - from) * (double(k) / steps))) {
        contact->segment = w - 1;
        return contact;
      }
    }
  }
  return std::nullopt;
}

Eigen::Isometry3d CellArm::tip_pose(const std::vector<double>& q_rad) const {
  return impl_->chain.forward(joint_vector(q_rad));
}

}  // namespace antipode::cells
