#include "antipode/robot/robot_model.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <mutex>
#include <sstream>
#include <utility>

#include <console_bridge/console.h>
#include <tinyxml2.h>
#include <urdf_parser/urdf_parser.h>
#include <kdl/joint.hpp>
#include <kdl/segment.hpp>

#include "antipode/core/error.hpp"
#include "kinematic_chain_impl.hpp"

namespace antipode {

struct RobotModel::Impl {
  std::string source;
  urdf::ModelInterfaceSharedPtr urdf;
};

namespace {

// urdfdom reports why a file is invalid through console_bridge; this handler keeps the
// first error instead of printing it.
class FirstError : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR && first.empty()) first = text;
  }
  std::string first;
};

// urdfdom reads with TinyXML, whose parser recurses once per nested element: 100,000 nested
// elements overflow the stack. tinyxml2 stops at TINYXML2_MAX_ELEMENT_DEPTH (100; a URDF
// nests 5) and says where, so the description is checked with it first.
void check_xml(const std::string& xml, const std::string& source) {
  tinyxml2::XMLDocument document;
  if (document.Parse(xml.data(), xml.size()) == tinyxml2::XML_SUCCESS) return;
  const std::string why = document.ErrorID() == tinyxml2::XML_ELEMENT_DEPTH_EXCEEDED
                              ? "elements nested deeper than " +
                                    std::to_string(TINYXML2_MAX_ELEMENT_DEPTH) +
                                    " levels, at line " + std::to_string(document.ErrorLineNum())
                              : std::string(document.ErrorStr());
  throw Error(source + ": not XML a robot description can be: " + why, {},
              "check the file against the URDF specification");
}

urdf::ModelInterfaceSharedPtr parse_urdf(const std::string& xml, const std::string& source) {
  check_xml(xml, source);
  static std::mutex console_mutex;  // console_bridge's handler is process-wide
  const std::lock_guard<std::mutex> lock(console_mutex);
  FirstError errors;
  console_bridge::useOutputHandler(&errors);
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml);
  console_bridge::restorePreviousOutputHandler();
  if (!model) {
    std::string why = errors.first.empty() ? "not a valid URDF robot" : errors.first;
    std::replace(why.begin(), why.end(), '\n', ' ');
    throw Error(source + ": " + why, {}, "check the file against the URDF specification");
  }
  if (!model->getRoot()) throw Error(source + ": the robot has no link");
  return model;
}

KDL::Vector to_kdl(const urdf::Vector3& v) { return KDL::Vector(v.x, v.y, v.z); }

KDL::Frame to_kdl(const urdf::Pose& p) {
  return KDL::Frame(
      KDL::Rotation::Quaternion(p.rotation.x, p.rotation.y, p.rotation.z, p.rotation.w),
      to_kdl(p.position));
}

// The KDL joint of `j`, placed at its origin in the parent link's frame (kdl_parser's
// convention: the axis is expressed in the parent frame).
KDL::Joint to_kdl_joint(const urdf::Joint& j, const std::string& source) {
  const KDL::Frame origin = to_kdl(j.parent_to_joint_origin_transform);
  switch (j.type) {
    case urdf::Joint::FIXED:
      return KDL::Joint(j.name, KDL::Joint::Fixed);
    case urdf::Joint::REVOLUTE:
    case urdf::Joint::CONTINUOUS:
      return KDL::Joint(j.name, origin.p, origin.M * to_kdl(j.axis), KDL::Joint::RotAxis);
    case urdf::Joint::PRISMATIC:
      return KDL::Joint(j.name, origin.p, origin.M * to_kdl(j.axis), KDL::Joint::TransAxis);
    default:
      throw Error(source + ": joint '" + j.name +
                  "' is floating or planar, which a kinematic chain cannot hold");
  }
}

// The joint's limits; throws antipode::Error, naming `source` and the joint, for limits no
// position satisfies (lower above upper, or not numbers): every planner and solver would
// otherwise search an empty space and report only that it found nothing.
JointLimits limits_of(const urdf::Joint& j, const std::string& source) {
  JointLimits l;
  if (j.type == urdf::Joint::CONTINUOUS || !j.limits) {
    l.lower = -std::numeric_limits<double>::infinity();
    l.upper = std::numeric_limits<double>::infinity();
  } else {
    l.lower = j.limits->lower;
    l.upper = j.limits->upper;
  }
  if (j.limits) l.velocity = j.limits->velocity;
  if (std::isnan(l.lower) || std::isnan(l.upper) || l.lower > l.upper)
    throw Error(source + ": joint '" + j.name + "' has its lower limit (" +
                std::to_string(l.lower) + ") above its upper limit (" + std::to_string(l.upper) +
                ") or not a number; swap them");
  return l;
}

void require_link(const urdf::ModelInterface& model, const std::string& name,
                  const std::string& source) {
  if (model.getLink(name)) return;
  std::vector<std::string> names;
  for (const auto& entry : model.links_) names.push_back(entry.first);
  throw Error(source + ": no link '" + name + "'" + did_you_mean(name, names));
}

}  // namespace

RobotModel::RobotModel(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

RobotModel RobotModel::parse(const std::string& urdf_xml, const std::string& source) {
  auto impl = std::make_shared<Impl>();
  impl->source = source;
  impl->urdf = parse_urdf(urdf_xml, source);
  return RobotModel(std::move(impl));
}

RobotModel RobotModel::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open the robot description");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw Error(path + ": cannot read the robot description");
  return parse(text.str(), path);
}

const std::string& RobotModel::name() const { return impl_->urdf->getName(); }
const std::string& RobotModel::source() const { return impl_->source; }
const std::string& RobotModel::root_link() const { return impl_->urdf->getRoot()->name; }

std::vector<std::string> RobotModel::link_names() const {
  std::vector<std::string> names;
  for (const auto& entry : impl_->urdf->links_) names.push_back(entry.first);
  return names;  // a std::map: sorted
}

std::vector<std::string> RobotModel::joint_names() const {
  std::vector<std::string> names;
  for (const auto& entry : impl_->urdf->joints_) names.push_back(entry.first);
  return names;
}

bool RobotModel::has_link(const std::string& name) const {
  return static_cast<bool>(impl_->urdf->getLink(name));
}

KinematicChain RobotModel::chain(const std::string& base, const std::string& tip) const {
  const urdf::ModelInterface& model = *impl_->urdf;
  require_link(model, base, impl_->source);
  require_link(model, tip, impl_->source);
  // The links from the tip up to the base.
  std::vector<urdf::LinkConstSharedPtr> path;
  for (urdf::LinkConstSharedPtr link = model.getLink(tip); link->name != base;) {
    path.push_back(link);
    link = link->getParent();
    if (!link) {
      std::string message = impl_->source;
      message.append(": link '").append(tip).append("' is not below '").append(base);
      message.append("', so no chain joins them");
      throw Error(message);
    }
  }
  auto impl = std::make_shared<KinematicChain::Impl>();
  impl->base_link = base;
  impl->tip_link = tip;
  for (auto it = path.rbegin(); it != path.rend(); ++it) {
    const urdf::Joint& joint = *(*it)->parent_joint;
    const KDL::Joint kdl_joint = to_kdl_joint(joint, impl_->source);
    impl->chain.addSegment(
        KDL::Segment((*it)->name, kdl_joint, to_kdl(joint.parent_to_joint_origin_transform)));
    if (joint.type == urdf::Joint::FIXED) continue;
    impl->joint_names.push_back(joint.name);
    impl->limits.push_back(limits_of(joint, impl_->source));
  }
  impl->evaluator = std::make_shared<const ChainEvaluator>(impl->chain, impl->limits);
  return KinematicChain(std::move(impl));
}

std::string RobotModel::parent_link(const std::string& link, std::string* joint,
                                    bool* moving) const {
  require_link(*impl_->urdf, link, impl_->source);
  const urdf::LinkConstSharedPtr l = impl_->urdf->getLink(link);
  const urdf::JointConstSharedPtr j = l->parent_joint;
  if (joint != nullptr) *joint = j ? j->name : "";
  if (moving != nullptr) *moving = j && j->type != urdf::Joint::FIXED;
  return j ? j->parent_link_name : "";
}

std::vector<CollisionPrimitive> RobotModel::collision_shapes(const std::string& link) const {
  require_link(*impl_->urdf, link, impl_->source);
  std::vector<CollisionPrimitive> shapes;
  for (const urdf::CollisionSharedPtr& c : impl_->urdf->getLink(link)->collision_array) {
    if (!c || !c->geometry) continue;
    CollisionPrimitive p;
    const urdf::Pose& o = c->origin;
    p.X_LinkShape.linear() =
        Eigen::Quaterniond(o.rotation.w, o.rotation.x, o.rotation.y, o.rotation.z)
            .toRotationMatrix();
    p.X_LinkShape.translation() = Eigen::Vector3d(o.position.x, o.position.y, o.position.z);
    switch (c->geometry->type) {
      case urdf::Geometry::BOX: {
        const auto& box = static_cast<const urdf::Box&>(*c->geometry);
        p.kind = CollisionPrimitive::Kind::kBox;
        p.size_m = Eigen::Vector3d(box.dim.x, box.dim.y, box.dim.z);
        break;
      }
      case urdf::Geometry::CYLINDER: {
        const auto& cylinder = static_cast<const urdf::Cylinder&>(*c->geometry);
        p.kind = CollisionPrimitive::Kind::kCylinder;
        p.size_m = Eigen::Vector3d(cylinder.radius, cylinder.length, 0.0);
        break;
      }
      case urdf::Geometry::SPHERE: {
        p.kind = CollisionPrimitive::Kind::kSphere;
        p.size_m.x() = static_cast<const urdf::Sphere&>(*c->geometry).radius;
        break;
      }
      default:
        throw Error(impl_->source + ": link '" + link +
                    "' has a mesh collision shape; use boxes, cylinders and spheres");
    }
    shapes.push_back(p);
  }
  return shapes;
}

}  // namespace antipode
