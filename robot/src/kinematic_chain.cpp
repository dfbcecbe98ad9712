#include "covopt/robot/kinematic_chain.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <fstream>
#include <iterator>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>
#include <console_bridge/console.h>
#include <kdl/frames.hpp>
#include <kdl/joint.hpp>
#include <kdl/rigidbodyinertia.hpp>
#include <kdl/rotationalinertia.hpp>
#include <kdl/segment.hpp>
#include <urdf_model/model.h>
#include <urdf_parser/urdf_parser.h>

#include "chain_impl.hpp"
#include "covopt/internal/text.hpp"
#include "urdf_parse.hpp"

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

namespace internal {
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

}  // namespace

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
  // urdfdom 3 logs an error for a value it cannot read (mass="nan") and may still return a
  // model with 0 in its place: any error refuses the URDF.
  if (model && handler.errors.empty()) return model;
  const ModelReleaser release{model.get()};
  std::string what = exception_text;
  for (const std::string& error : handler.errors) what += (what.empty() ? "" : "; ") + error;
  if (what.empty()) what = "not a valid URDF document";
  // urdfdom's messages may span lines; ours is one line.
  std::replace(what.begin(), what.end(), '\n', ' ');
  throw std::invalid_argument(source + ": malformed URDF: " + what);
}

}  // namespace internal

using internal::ModelReleaser;
using internal::ParseUrdf;

namespace {

KDL::Vector ToKdl(const urdf::Vector3& v) { return KDL::Vector(v.x, v.y, v.z); }

KDL::Rotation ToKdl(const urdf::Rotation& r) { return KDL::Rotation::Quaternion(r.x, r.y, r.z, r.w); }

KDL::Frame ToKdl(const urdf::Pose& pose) {
  return KDL::Frame(ToKdl(pose.rotation), ToKdl(pose.position));
}

using internal::Refuse;

/// An origin's coordinates within ±kMaxLengthM and a finite rotation.
void CheckPose(const urdf::Pose& pose, const std::string& where, const std::string& field) {
  const std::array<std::pair<const char*, double>, 3> xyz{
      {{"x", pose.position.x}, {"y", pose.position.y}, {"z", pose.position.z}}};
  for (const auto& [axis, value] : xyz) {
    if (!(std::abs(value) <= kMaxLengthM)) {
      Refuse(where, field + " xyz " + axis, value, "a finite length within ±1000 m");
    }
  }
  for (const double value : {pose.rotation.x, pose.rotation.y, pose.rotation.z, pose.rotation.w}) {
    if (!std::isfinite(value)) Refuse(where, field + " rotation", value, "finite rpy angles");
  }
}

/// The tensor's entries within ±kMaxInertiaKgM2, its principal moments >= 0 and obeying the
/// triangle inequality (internal::CheckPrincipalMoments).
void CheckInertiaTensor(const urdf::Inertial& in, const std::string& where) {
  const std::array<std::pair<const char*, double>, 6> entries{
      {{"ixx", in.ixx}, {"ixy", in.ixy}, {"ixz", in.ixz}, {"iyy", in.iyy}, {"iyz", in.iyz}, {"izz", in.izz}}};
  for (const auto& [field, value] : entries) {
    if (!(std::abs(value) <= kMaxInertiaKgM2)) {
      Refuse(where, std::string("<inertia> ") + field, value, "a finite number within ±1e12 kg m²");
    }
  }
  Eigen::Matrix3d tensor;
  tensor << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  internal::CheckPrincipalMoments(tensor, where, "<inertia>");
}

/// The link's <inertial> as KDL's rigid-body inertia about the link frame's origin, as
/// kdl_parser converts it: the tensor, given about the centre of mass in the <inertial>
/// origin's orientation, is rotated into the link frame.
KDL::RigidBodyInertia ToKdl(const urdf::Link& link, const std::string& source) {
  if (!link.inertial) return KDL::RigidBodyInertia::Zero();
  const urdf::Inertial& in = *link.inertial;
  const std::string where = source + ": link '" + link.name + "'";
  if (!(in.mass >= 0.0 && in.mass <= kMaxLinkMassKg)) {
    Refuse(where, "<mass> value", in.mass, "a mass in [0, 1e6] kg");
  }
  CheckInertiaTensor(in, where);
  CheckPose(in.origin, where, "<inertial> <origin>");
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
KDL::Joint ToKdlJoint(const urdf::Joint& joint, JointType type, const std::string& source) {
  const KDL::Frame parent_to_joint = ToKdl(joint.parent_to_joint_origin_transform);
  if (type == JointType::kFixed) return KDL::Joint(joint.name, KDL::Joint::Fixed);
  // Scaled by its largest component first: the norm of (1e308, 1e308, 0) does not overflow.
  Eigen::Vector3d typed(joint.axis.x, joint.axis.y, joint.axis.z);
  const double largest = typed.cwiseAbs().maxCoeff();
  if (!(largest > 0.0) || !std::isfinite(largest)) {
    std::ostringstream message;
    message << source << ": joint '" << joint.name << "': <axis xyz> = (" << typed[0] << ", " << typed[1]
            << ", " << typed[2] << ") is not allowed (a finite, non-zero vector)";
    throw std::invalid_argument(message.str());
  }
  typed = (typed / largest).normalized();
  const KDL::Vector axis = parent_to_joint.M * KDL::Vector(typed[0], typed[1], typed[2]);
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

/// The joint's <limit>, checked (module docs of JointLimits for what 0 means).
JointLimits ToLimits(const urdf::Joint& joint, JointType type, const std::string& source,
                     std::vector<std::string>& warnings) {
  JointLimits limits;
  if (type == JointType::kFixed || !joint.limits) return limits;
  const std::string where = source + ": joint '" + joint.name + "'";
  const urdf::JointLimits& typed = *joint.limits;
  if (!(typed.velocity >= 0.0) || !std::isfinite(typed.velocity)) {
    Refuse(where, "<limit velocity>", typed.velocity, "a finite speed >= 0; 0 means no limit given");
  }
  limits.has_velocity = typed.velocity > 0.0;
  limits.velocity = typed.velocity;
  if (type == JointType::kContinuous) return limits;
  if (!std::isfinite(typed.lower) || !std::isfinite(typed.upper) || typed.lower > typed.upper) {
    std::ostringstream allowed;
    allowed << "lower <= upper, finite; upper = " << typed.upper;
    Refuse(where, "<limit lower>", typed.lower, allowed.str());
  }
  limits.has_position = typed.lower < typed.upper;
  limits.lower = typed.lower;
  limits.upper = typed.upper;
  if (!limits.has_position) {
    warnings.push_back("joint '" + joint.name + "' has no position range in the URDF (lower = upper): its "
                       "positions are not checked against limits");
  }
  return limits;
}

/// Refuses a URDF in which a link has two parents (its joints form a cycle: the walk to the
/// root would never end), or that has more than kMaxUrdfLinks links.
void CheckTree(const urdf::ModelInterface& model, const std::string& source) {
  if (model.links_.size() > kMaxUrdfLinks) {
    throw std::invalid_argument(source + ": " + std::to_string(model.links_.size()) +
                                " links is not allowed (at most 10000)");
  }
  std::map<std::string, std::string> parent_joint;  // child link -> joint
  for (const auto& [name, joint] : model.joints_) {
    if (!joint) continue;
    if (joint->child_link_name == joint->parent_link_name) {
      throw std::invalid_argument(source + ": joint '" + name + "' makes link '" + joint->child_link_name +
                                  "' its own parent (the joints form a cycle)");
    }
    const auto [it, inserted] = parent_joint.emplace(joint->child_link_name, name);
    if (!inserted) {
      throw std::invalid_argument(source + ": link '" + joint->child_link_name + "' has two parents (joints '" +
                                  it->second + "' and '" + name +
                                  "'): the joints form a cycle; a URDF must be a tree");
    }
  }
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
  CheckTree(model, source);
  const std::string base = spec.base_link.empty() ? model.getRoot()->name : spec.base_link;
  if (spec.tip_link.empty()) {
    throw std::invalid_argument(source + ": tip link: give the link that hits (links: " +
                                KnownLinks(model) + ")");
  }
  for (const auto& [role, name] : {std::pair{"base", base}, std::pair{"tip", spec.tip_link}}) {
    if (!model.getLink(name)) {
      throw std::invalid_argument(source + ": " + role + " link '" +
                                  covopt::internal::EscapeControlCharacters(name) +  // one line, whole
                                  "' is not in the URDF (links: " + KnownLinks(model) + ")");
    }
  }
  // Walk from the tip up to the base; the base must be on the way.
  std::vector<urdf::LinkConstSharedPtr> path;  // tip first, base excluded
  urdf::LinkConstSharedPtr link = model.getLink(spec.tip_link);
  while (link && link->name != base) {
    path.push_back(link);
    link = link->getParent();
    if (path.size() > model.links_.size()) {  // each link has one parent (CheckTree): a cycle
      throw std::invalid_argument(source + ": the joints above link '" + spec.tip_link +
                                  "' form a cycle; a URDF must be a tree");
    }
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
    CheckPose(joint.parent_to_joint_origin_transform, source + ": joint '" + joint.name + "'", "<origin>");
    impl->joints.push_back({joint.name, type, joint.parent_link_name, joint.child_link_name,
                            ToLimits(joint, type, source, impl->warnings)});
    if (type != JointType::kFixed) impl->joint_names.push_back(joint.name);
    // The link's own inertia plus everything hanging off it that is not the chain's next
    // link (beyond the tip: all of it), rigidly attached as at joint position 0.
    const urdf::Link* next = k + 1 < path.size() ? path[k + 1].get() : nullptr;
    const KDL::RigidBodyInertia inertia = SubtreeInertia(*child, next, true, source, locked);
    impl->moving_mass_kg += inertia.getMass();
    if (next == nullptr) impl->bare_tip_inertia = inertia;
    impl->chain.addSegment(KDL::Segment(child->name, ToKdlJoint(joint, type, source),
                                        ToKdl(joint.parent_to_joint_origin_transform), inertia));
  }
  if (impl->joint_names.empty()) {
    throw std::invalid_argument(source + ": the chain " + base + " -> " + spec.tip_link +
                                " has no movable joint (base and tip are the same link, or only fixed "
                                "joints lie between them): give a tip below a revolute, continuous or "
                                "prismatic joint");
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
  const ModelReleaser release{model.get()};
  return KinematicChain(BuildChain(*model, spec, source_name));
}

KinematicChain KinematicChain::FromUrdfFile(const std::filesystem::path& path,
                                            const ChainSpec& spec) {
  return FromUrdfString(internal::ReadBoundedFile(path, kMaxUrdfBytes, "URDF file"), spec, path.string());
}

namespace internal {

void Refuse(const std::string& where, const std::string& field, double value, const std::string& allowed) {
  std::ostringstream message;
  message << where << ": " << field << " = " << value << " is not allowed (" << allowed << ")";
  throw std::invalid_argument(message.str());
}

void CheckPrincipalMoments(const Eigen::Matrix3d& tensor, const std::string& where, const std::string& field) {
  const Eigen::Vector3d moments =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(tensor, Eigen::EigenvaluesOnly).eigenvalues();
  const double tolerance = 1e-6 * std::max(std::abs(moments[0]), std::abs(moments[2]));
  if (moments[0] < -tolerance) {
    Refuse(where, field + " smallest principal moment", moments[0],
           "an inertia tensor must be positive semi-definite: principal moments >= 0 kg m²");
  }
  if (moments[0] + moments[1] < moments[2] - tolerance) {
    std::ostringstream allowed;
    allowed << "principal moments must obey the triangle inequality; the other two are " << moments[0]
            << " and " << moments[1] << " kg m², whose sum is smaller";
    Refuse(where, field + " largest principal moment", moments[2], allowed.str());
  }
}

std::string ReadBounded(std::istream& in, std::size_t limit_bytes, const std::string& source,
                        const std::string& what) {
  std::string text;
  std::array<char, 1 << 16> buffer{};
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    text.append(buffer.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > limit_bytes) {
      throw std::invalid_argument(source + ": larger than " + std::to_string(limit_bytes >> 20) +
                                  " MiB, the limit for a " + what);
    }
  }
  if (in.bad()) throw std::invalid_argument(source + ": cannot read the " + what);
  return text;
}

std::string ReadBoundedFile(const std::filesystem::path& path, std::size_t limit_bytes,
                            const std::string& what) {
  const std::string source = path.string();
  std::error_code error;
  if (!std::filesystem::exists(path, error)) throw std::invalid_argument(source + ": no such " + what);
  if (std::filesystem::is_directory(path, error)) {
    throw std::invalid_argument(source + ": is a directory, not a " + what);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(source + ": cannot read the " + what);
  return ReadBounded(in, limit_bytes, source, what);
}

}  // namespace internal

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
const Payload& KinematicChain::payload() const noexcept { return impl_->payload; }

KinematicChain KinematicChain::WithPayload(const Payload& payload) const {
  CheckPayload(payload);
  auto impl = std::make_shared<Impl>(*impl_);
  impl->payload = payload;
  // The tip segment's inertia is about the tip link's frame (as the URDF's link inertia); the
  // payload is given about its centre of mass in that frame. Without a payload the segment
  // gets the URDF's inertia back, bit for bit.
  KDL::RigidBodyInertia inertia = impl->bare_tip_inertia;
  if (!payload.empty()) {
    const Eigen::Matrix3d& tensor = payload.inertia_kg_m2;
    const Eigen::Vector3d& com = payload.center_of_mass_m;
    inertia = inertia + KDL::RigidBodyInertia(payload.mass_kg, KDL::Vector(com.x(), com.y(), com.z()),
                                              KDL::RotationalInertia(tensor(0, 0), tensor(1, 1), tensor(2, 2),
                                                                     tensor(0, 1), tensor(0, 2), tensor(1, 2)));
  }
  impl->chain.getSegment(impl->chain.getNrOfSegments() - 1).setInertia(inertia);
  return KinematicChain(std::move(impl));
}
const std::vector<std::string>& KinematicChain::locked_joint_names() const noexcept {
  return impl_->lumped_joint_names;
}
const std::vector<std::string>& KinematicChain::warnings() const noexcept { return impl_->warnings; }

}  // namespace covopt::robot
