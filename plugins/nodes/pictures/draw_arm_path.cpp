#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "antipode/bt/action_node.hpp"
#include "antipode/core/parameters.hpp"
#include "antipode/core/trajectory.hpp"
#include "antipode/interfaces/hand_set.hpp"
#include "antipode/robot/robot_file.hpp"
#include "antipode/robot/robot_model.hpp"
#include "draw.hpp"
#include "picture_nodes.hpp"

namespace antipode::pictures {
namespace {

Eigen::VectorXd at_fraction(const Trajectory& t, double s) {
  const double index = s * double(t.positions_rad.size() - 1);
  const std::size_t i = std::min(std::size_t(index), t.positions_rad.size() - 1);
  const std::size_t j = std::min(i + 1, t.positions_rad.size() - 1);
  const Eigen::VectorXd qi = joint_vector(t.positions_rad[i]);
  return qi + (joint_vector(t.positions_rad[j]) - qi) * (index - double(i));
}

// Where along the motion the k-th of `poses` drawn arms stands: 0 (start) to 1 (grasp).
double fraction(int k, int poses) { return poses == 1 ? 1.0 : double(k) / (poses - 1); }

// The index of the first of `links` (a chain, base to tip) that a moving joint carries.
std::size_t first_moving_link(const RobotModel& robot, const std::vector<std::string>& links) {
  for (std::size_t i = 0; i < links.size(); ++i) {
    bool moving = false;
    robot.parent_link(links[i], nullptr, &moving);
    if (moving) return i;
  }
  return links.size();
}

// The link's primitives: cylinders as thick strokes along their axes, spheres as discs,
// boxes as outlines.
void draw_link(cv::Mat& image, const OrthoView& view, const std::vector<CollisionPrimitive>& shapes,
               const Eigen::Isometry3d& X_BaseLink, const cv::Scalar& colour) {
  for (const CollisionPrimitive& p : shapes) {
    const Eigen::Isometry3d X = X_BaseLink * p.X_LinkShape;
    switch (p.kind) {
      case CollisionPrimitive::Kind::kCylinder: {
        const Eigen::Vector3d half(0, 0, p.size_m.y() / 2);
        const ProjectedPoint a = view.project(X * half), b = view.project(X * -half);
        const int width = std::max(1, int(std::lround(2 * p.size_m.x() * view.px_per_m())));
        cv::line(image, {int(a.u_px), int(a.v_px)}, {int(b.u_px), int(b.v_px)}, colour, width,
                 cv::LINE_AA);
        break;
      }
      case CollisionPrimitive::Kind::kSphere: {
        const ProjectedPoint c = view.project(X.translation());
        cv::circle(image, {int(c.u_px), int(c.v_px)}, int(p.size_m.x() * view.px_per_m()), colour,
                   1, cv::LINE_AA);
        break;
      }
      case CollisionPrimitive::Kind::kBox:
        draw_box(image, view, {-p.size_m / 2, p.size_m / 2}, X, colour, 1);
        break;
    }
  }
}

/// Draws a planned arm motion over the scene: the arm at evenly spaced points of the
/// trajectory (light blue at the start to dark red at the grasp), the links before the first
/// moving joint in grey, the
/// observed points and the grasp's hand, from the arm's side and from above.
class DrawArmPath final : public bt::SyncActionNode {
 public:
  using SyncActionNode::SyncActionNode;
  static bt::NodeManifest manifest() {
    return {"DrawArmPath",
            bt::NodeCategory::kAction,
            {bt::input_port<HandSetPtr>("grasps", "a selection: its cloud and first grasp"),
             bt::input_port<Trajectory>("trajectory", "the arm's motion (PlanReach)"),
             bt::input_port<std::string>("robot", "the robot file (robots/*/*.yaml)"),
             bt::input_port<std::string>("file", std::string(), "output PNG file; empty = none"),
             bt::input_port<int>("poses", 6, "arm poses drawn along the motion"),
             bt::input_port<int>("size_px", 600, "side of each of the two square views")},
            0,
            0,
            "Draws a planned arm motion over the scene into a PNG.",
            {}};
  }

 protected:
  bt::Status tick() override {
    const std::string file = get_input<std::string>("file");
    if (file.empty()) return bt::Status::kSuccess;
    const HandSetPtr set = get_input<HandSetPtr>("grasps");
    const Trajectory& trajectory = get_input_ref<Trajectory>("trajectory");
    if (!set->cloud) fail("grasps", "the hand set has no cloud to draw");
    if (trajectory.empty()) fail("trajectory", "the trajectory is empty");
    const int size_px = get_input<int>("size_px"), poses = get_input<int>("poses");
    if (size_px < 64 || size_px > 4096) fail("size_px", "size_px must be in [64, 4096]");
    if (poses < 1 || poses > 50) fail("poses", "poses must be in [1, 50]");
    const RobotFile robot_file =
        read_robot_file(resolve_path(get_input<std::string>("robot"), where().file));
    const RobotModel robot = RobotModel::load(robot_file.urdf_path);
    const KinematicChain arm = robot.chain(robot.root_link(), robot_file.arm_tip);
    if (trajectory.joint_names != arm.joint_names())
      fail("trajectory", "the trajectory's joints are not those of " + robot_file.name + "'s arm");

    // The views centre between the arm's first moving link (its shoulder) and the grasp.
    const std::vector<std::string> links = arm.link_names();
    const std::size_t first_moving = first_moving_link(robot, links);
    const Eigen::Isometry3d X_end = arm.forward(at_fraction(trajectory, 1.0));
    const Eigen::Vector3d shoulder =
        arm.link_poses(at_fraction(trajectory, 0.0))[first_moving].translation();
    const Eigen::Vector3d centre = 0.5 * (X_end.translation() + shoulder);
    const OrthoView side(Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(), centre, 0.75, size_px);
    const OrthoView above(-Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(), centre, 0.75,
                          size_px);
    // The links' shapes, and their poses at each drawn point of the motion (the fixed links
    // before the first moving joint are the same in all).
    std::vector<std::vector<CollisionPrimitive>> shapes;
    for (const std::string& link : links) shapes.push_back(robot.collision_shapes(link));
    std::vector<std::vector<Eigen::Isometry3d>> X_BaseLink;
    for (int k = 0; k < poses; ++k)
      X_BaseLink.push_back(arm.link_poses(at_fraction(trajectory, fraction(k, poses))));

    cv::Mat image(size_px, 2 * size_px, CV_8UC3, cv::Scalar(255, 255, 255));
    cv::Mat left = image(cv::Rect(0, 0, size_px, size_px));
    cv::Mat right = image(cv::Rect(size_px, 0, size_px, size_px));
    for (auto* panel : {&left, &right}) {
      const OrthoView& view = panel == &left ? side : above;
      draw_cloud(*panel, view, *set->cloud);
      for (std::size_t i = 0; i < first_moving; ++i)
        draw_link(*panel, view, shapes[i], X_BaseLink[0][i], cv::Scalar(150, 150, 150));
      for (int k = 0; k < poses; ++k) {
        const double s = fraction(k, poses);
        const cv::Scalar colour(230 - 200 * s, 180 - 150 * s, 60 + 140 * s);  // BGR
        for (std::size_t i = first_moving; i < links.size(); ++i)
          draw_link(*panel, view, shapes[i], X_BaseLink[std::size_t(k)][i], colour);
      }
      Hand grasp;
      grasp.X_FrameHand = X_end;
      draw_hand(*panel, view, make_hand_body(set->geometry), grasp, cv::Scalar(40, 170, 40), 2);
    }
    caption(image, {"arm motion, " + std::to_string(trajectory.positions_rad.size()) +
                    " waypoints (light: start, dark: at the grasp); left: from the side, "
                    "right: from above"});
    write_png(file, image);
    log("arm motion drawn to " + file);
    return bt::Status::kSuccess;
  }
};

}  // namespace

void register_draw_arm_path(bt::NodeRegistry& registry) { registry.register_node<DrawArmPath>(); }

}  // namespace antipode::pictures
