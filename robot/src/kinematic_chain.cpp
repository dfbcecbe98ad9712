#include "covopt/robot/kinematic_chain.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <console_bridge/console.h>
#include <kdl/frames.hpp>
#include <kdl/joint.hpp>
#include <kdl/rigidbodyinertia.hpp>
#include <kdl/rotationalinertia.hpp>
#include <kdl/segment.hpp>
#include <urdf_model/model.h>
#include <urdf_parser/urdf_parser.h>

#include "chain_impl.hpp"

namespace covopt::robot {

const char* ToString(JointType type) noexcept {
  switch (type) {
    case JointType::kRevolute: return "revolute";
    case JointType::kContinuous: return "continuous";
    case JointType::kPrismatic: return "prismatic";
    case JointType::kFixed: return "fixed";
  }
  return "unknown";
}

namespace {

/// Collects console_bridge's messages while urdfdom parses, instead of printing them; the
/// parse then fails with what urdfdom said. console_bridge's handler is process-global, so
/// parses are serialised.
class CollectingOutputHandler : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char* /*filename*/,
           int /*line*/) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) errors.push_back(text);
  }
  std::vector<std::string> errors;
};

std::mutex& ParseMutex() {
  static std::mutex mutex;
  return mutex;
}

urdf::ModelInterfaceSharedPtr ParseUrdf(const std::string& text, const std::string& source) {
  CollectingOutputHandler handler;
  urdf::ModelInterfaceSharedPtr model;
  std::string exception_text;
  {
    const std::lock_guard<std::mutex> lock(ParseMutex());
    const console_bridge::LogLevel previous_level = console_bridge::getLogLevel();
    console_bridge::useOutputHandler(&handler);
    console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_ERROR);
    try {
      model = urdf::parseURDF(text);
    } catch (const std::exception& e) {
      exception_text = e.what();
    }
    console_bridge::restorePreviousOutputHandler();
    console_bridge::setLogLevel(previous_level);
  }
  if (model) return model;
  std::string what = exception_text;
  for (const std::string& error : handler.errors) what += (what.empty() ? "" : "; ") + error;
  if (what.empty()) what = "not a valid URDF document";
  // urdfdom's messages may span lines; ours is one line.
  std::replace(what.begin(), what.end(), '\n', ' ');
  throw std::invalid_argument(source + ": malformed URDF: " + what);
}

KDL::Vector ToKdl(const urdf::Vector3& v) { return KDL::Vector(v.x, v.y, v.z); }

KDL::Rotation ToKdl(const urdf::Rotation& r) { return KDL::Rotation::Quaternion(r.x, r.y, r.z, r.w); }

KDL::Frame ToKdl(const urdf::Pose& pose) {
  return KDL::Frame(ToKdl(pose.rotation), ToKdl(pose.position));
}

/// The link's <inertial> as KDL's rigid-body inertia about the link frame's origin, as
/// kdl_parser converts it: the tensor, given about the centre of mass in the <inertial>
/// origin's orientation, is rotated into the link frame.
KDL::RigidBodyInertia ToKdl(const urdf::Link& link, const std::string& source) {
  if (!link.inertial) return KDL::RigidBodyInertia::Zero();
  const urdf::Inertial& in = *link.inertial;
  for (const double value : {in.mass, in.ixx, in.ixy, in.ixz, in.iyy, in.iyz, in.izz}) {
    if (!std::isfinite(value)) {
      throw std::invalid_argument(source + ": link '" + link.name +
                                  "': <inertial> has a non-finite mass or inertia");
    }
  }
  if (in.mass < 0) {
    std::ostringstream message;
    message << source << ": link '" << link.name << "': mass must be >= 0 kg (got " << in.mass
            << ")";
    throw std::invalid_argument(message.str());
  }
  const KDL::Frame origin = ToKdl(in.origin);
  const KDL::RotationalInertia about_com_in_inertial_axes(in.ixx, in.iyy, in.izz, in.ixy, in.ixz,
                                                          in.iyz);
  const KDL::RigidBodyInertia rotated =
      origin.M * KDL::RigidBodyInertia(0.0, KDL::Vector::Zero(), about_com_in_inertial_axes);
  return KDL::RigidBodyInertia(in.mass, origin.p, rotated.getRotationalInertia());
}

JointType ToJointType(const urdf::Joint& joint, const std::string& source) {
  switch (joint.type) {
    case urdf::Joint::REVOLUTE: return JointType::kRevolute;
    case urdf::Joint::CONTINUOUS: return JointType::kContinuous;
    case urdf::Joint::PRISMATIC: return JointType::kPrismatic;
    case urdf::Joint::FIXED: return JointType::kFixed;
    default: break;
  }
  const char* type_name = joint.type == urdf::Joint::FLOATING ? "floating"
                          : joint.type == urdf::Joint::PLANAR ? "planar"
                                                              : "unknown";
  throw std::invalid_argument(source + ": joint '" + joint.name + "' has type '" + type_name +
                              "', which is not supported (revolute, continuous, prismatic, "
                              "fixed)");
}

/// The KDL joint as kdl_parser builds it: the axis through the joint origin, in the parent
/// link's frame. Rotor inertia, damping and stiffness are 0 (URDF has no rotor inertia).
KDL::Joint ToKdlJoint(const urdf::Joint& joint, JointType type) {
  const KDL::Frame parent_to_joint = ToKdl(joint.parent_to_joint_origin_transform);
  if (type == JointType::kFixed) return KDL::Joint(joint.name, KDL::Joint::Fixed);
  const KDL::Vector axis = parent_to_joint.M * ToKdl(joint.axis);
  return KDL::Joint(joint.name, parent_to_joint.p, axis,
                    type == JointType::kPrismatic ? KDL::Joint::TransAxis : KDL::Joint::RotAxis);
}

/// The rigid-body inertia, about `link`'s frame, of `link` and every link below it except
/// `skip` (the next link on the chain), its joints held at position 0. `locked` collects the
/// movable joints so held.
KDL::RigidBodyInertia SubtreeInertia(const urdf::Link& link, const urdf::Link* skip,
                                     bool include_own, const std::string& source,
                                     std::vector<std::string>& locked) {
  KDL::RigidBodyInertia total = include_own ? ToKdl(link, source) : KDL::RigidBodyInertia::Zero();
  for (const urdf::LinkSharedPtr& child : link.child_links) {
    if (!child || child.get() == skip) continue;
    const urdf::Joint& joint = *child->parent_joint;
    if (joint.type != urdf::Joint::FIXED) locked.push_back(joint.name);
    // At position 0 every joint's motion is the identity: the child frame is the origin.
    total = total + ToKdl(joint.parent_to_joint_origin_transform) *
                        SubtreeInertia(*child, nullptr, true, source, locked);
  }
  return total;
}

std::string KnownLinks(const urdf::ModelInterface& model) {
  std::string names;
  std::size_t count = 0;
  for (const auto& [name, link] : model.links_) {
    if (count == 12) {
      names += ", ...";
      break;
    }
    names += (count++ == 0 ? "" : ", ") + name;
  }
  return names;
}

std::shared_ptr<const KinematicChain::Impl> BuildChain(const urdf::ModelInterface& model,
                                                       const ChainSpec& spec,
                                                       const std::string& source) {
  if (!model.getRoot()) throw std::invalid_argument(source + ": malformed URDF: no root link");
  const std::string base = spec.base_link.empty() ? model.getRoot()->name : spec.base_link;
  if (spec.tip_link.empty()) {
    throw std::invalid_argument(source + ": tip link: give the link that hits (links: " +
                                KnownLinks(model) + ")");
  }
  for (const auto& [role, name] : {std::pair{"base", base}, std::pair{"tip", spec.tip_link}}) {
    if (!model.getLink(name)) {
      throw std::invalid_argument(source + ": " + role + " link '" + name +
                                  "' is not in the URDF (links: " + KnownLinks(model) + ")");
    }
  }
  // Walk from the tip up to the base; the base must be on the way.
  std::vector<urdf::LinkConstSharedPtr> path;  // tip first, base excluded
  urdf::LinkConstSharedPtr link = model.getLink(spec.tip_link);
  while (link && link->name != base) {
    path.push_back(link);
    link = link->getParent();
  }
  if (!link) {
    throw std::invalid_argument(source + ": base link '" + base + "' is not an ancestor of tip link '" +
                                spec.tip_link + "' (the chain must run from the base down to the tip)");
  }
  std::reverse(path.begin(), path.end());

  auto impl = std::make_shared<KinematicChain::Impl>();
  impl->robot_name = model.getName();
  impl->source_name = source;
  impl->base_link = base;
  impl->tip_link = spec.tip_link;
  std::vector<std::string> locked;
  for (std::size_t k = 0; k < path.size(); ++k) {
    const urdf::LinkConstSharedPtr& child = path[k];
    const urdf::Joint& joint = *child->parent_joint;
    const JointType type = ToJointType(joint, source);
    impl->joints.push_back({joint.name, type, joint.parent_link_name, joint.child_link_name});
    if (type != JointType::kFixed) impl->joint_names.push_back(joint.name);
    // The link's own inertia plus everything hanging off it that is not the chain's next
    // link (beyond the tip: all of it), rigidly attached as at joint position 0.
    const urdf::Link* next = k + 1 < path.size() ? path[k + 1].get() : nullptr;
    const KDL::RigidBodyInertia inertia = SubtreeInertia(*child, next, true, source, locked);
    impl->moving_mass_kg += inertia.getMass();
    impl->chain.addSegment(KDL::Segment(child->name, ToKdlJoint(joint, type),
                                        ToKdl(joint.parent_to_joint_origin_transform), inertia));
  }
  if (!locked.empty()) {
    std::string names;
    for (const std::string& name : locked) names += (names.empty() ? "" : ", ") + name;
    impl->warnings.push_back(
        "the links beyond or beside the chain " + base + " -> " + spec.tip_link +
        " count as rigid payload with their joints locked at 0 (" + names +
        "): the reflected mass is that of the robot with those joints held; make the tip "
        "the last link to move them");
  }
  impl->lumped_joint_names = std::move(locked);
  return impl;
}

}  // namespace

KinematicChain KinematicChain::FromUrdfString(const std::string& urdf_text, const ChainSpec& spec,
                                              const std::string& source_name) {
  const urdf::ModelInterfaceSharedPtr model = ParseUrdf(urdf_text, source_name);
  return KinematicChain(BuildChain(*model, spec, source_name));
}

KinematicChain KinematicChain::FromUrdfFile(const std::filesystem::path& path,
                                            const ChainSpec& spec) {
  const std::string source = path.string();
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    throw std::invalid_argument(source + ": no such URDF file");
  }
  if (std::filesystem::is_directory(path, error)) {
    throw std::invalid_argument(source + ": is a directory, not a URDF file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(source + ": cannot read the URDF file");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::invalid_argument(source + ": cannot read the URDF file");
  return FromUrdfString(text, spec, source);
}

const std::string& KinematicChain::robot_name() const noexcept { return impl_->robot_name; }
const std::string& KinematicChain::base_link() const noexcept { return impl_->base_link; }
const std::string& KinematicChain::tip_link() const noexcept { return impl_->tip_link; }
const std::string& KinematicChain::source_name() const noexcept { return impl_->source_name; }
const std::vector<ChainJoint>& KinematicChain::joints() const noexcept { return impl_->joints; }
const std::vector<std::string>& KinematicChain::joint_names() const noexcept {
  return impl_->joint_names;
}
std::size_t KinematicChain::joint_count() const noexcept { return impl_->joint_names.size(); }
double KinematicChain::moving_mass_kg() const noexcept { return impl_->moving_mass_kg; }
const std::vector<std::string>& KinematicChain::locked_joint_names() const noexcept {
  return impl_->lumped_joint_names;
}
const std::vector<std::string>& KinematicChain::warnings() const noexcept { return impl_->warnings; }

}  // namespace covopt::robot
