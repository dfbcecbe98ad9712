#include "covopt/robot/link_kinematics.hpp"

#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <kdl/chaindynparam.hpp>
#include <kdl/frames.hpp>
#include <kdl/jntarray.hpp>
#include <kdl/jntspaceinertiamatrix.hpp>

#include "chain_impl.hpp"

namespace covopt::robot {

namespace {

Eigen::Vector3d ToEigen(const KDL::Vector& v) { return {v.x(), v.y(), v.z()}; }

Eigen::Matrix3d ToEigen(const KDL::Rotation& r) {
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m(i, j) = r(i, j);
  }
  return m;
}

/// [r]×: [r]× x = r × x.
Eigen::Matrix3d Skew(const Eigen::Vector3d& r) {
  Eigen::Matrix3d s;
  s << 0.0, -r.z(), r.y(), r.z(), 0.0, -r.x(), -r.y(), r.x(), 0.0;
  return s;
}

}  // namespace

/// One link (KDL segment) at the current sample, base frame.
struct LinkState {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d origin_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_m_per_s = Eigen::Vector3d::Zero();  ///< of the frame's origin
  Eigen::Vector3d angular_rad_per_s = Eigen::Vector3d::Zero();
  /// Rows 0-2: J_v(origin); rows 3-5: J_ω. Columns of joints beyond the link stay zero.
  Eigen::Matrix<double, 6, Eigen::Dynamic> jacobian;
  std::size_t moving_joints = 0;  ///< the movable joints up to and including this link's
};

struct ChainSampleKinematics::State {
  State(const KinematicChain& c, const ContactMotionOptions& o)
      : chain(c),
        options(o),
        n(c.joint_count()),
        dynamics(c.impl().chain, KDL::Vector::Zero()),
        q(static_cast<unsigned>(n)),
        mass(static_cast<unsigned>(n)),
        cholesky(static_cast<Eigen::Index>(n)),
        lower(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n)),
        scratch(static_cast<Eigen::Index>(n), 3) {}

  KinematicChain chain;
  ContactMotionOptions options;
  std::size_t n = 0;
  KDL::ChainDynParam dynamics;
  KDL::JntArray q;
  KDL::JntSpaceInertiaMatrix mass;
  Eigen::LLT<Eigen::MatrixXd> cholesky;
  Eigen::MatrixXd lower;                       ///< L, M = L Lᵀ
  mutable Eigen::MatrixXd scratch;             ///< n×3: J_v(p)ᵀ, then L⁻¹ J_v(p)ᵀ (Point)
  std::vector<std::string> link_names;
  std::vector<LinkState> links;
  std::vector<Eigen::Vector3d> axes;           ///< per movable joint, base frame (Update)
  std::vector<Eigen::Vector3d> axis_points_m;  ///< a point on each axis, base frame (Update)
  std::vector<bool> prismatic;                 ///< per movable joint
  bool updated = false;
};

ChainSampleKinematics::ChainSampleKinematics(const KinematicChain& chain, const ContactMotionOptions& options) {
  internal::CheckContactMotionOptions(options);
  state_ = std::make_unique<State>(chain, options);
  State& s = *state_;
  const KDL::Chain& kdl = chain.impl().chain;
  const auto n = static_cast<Eigen::Index>(s.n);
  std::size_t moving = 0;
  for (unsigned i = 0; i < kdl.getNrOfSegments(); ++i) {
    const KDL::Segment& segment = kdl.getSegment(i);
    s.link_names.push_back(segment.getName());
    const KDL::Joint::JointType type = segment.getJoint().getType();
    if (type != KDL::Joint::Fixed) {
      ++moving;
      s.prismatic.push_back(type == KDL::Joint::TransAxis || type == KDL::Joint::TransX ||
                            type == KDL::Joint::TransY || type == KDL::Joint::TransZ);
    }
    LinkState link;
    link.jacobian = Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, n);
    link.moving_joints = moving;
    s.links.push_back(std::move(link));
  }
  s.axes.assign(s.n, Eigen::Vector3d::Zero());
  s.axis_points_m.assign(s.n, Eigen::Vector3d::Zero());
}

ChainSampleKinematics::~ChainSampleKinematics() = default;
ChainSampleKinematics::ChainSampleKinematics(ChainSampleKinematics&&) noexcept = default;
ChainSampleKinematics& ChainSampleKinematics::operator=(ChainSampleKinematics&&) noexcept = default;

const std::vector<std::string>& ChainSampleKinematics::link_names() const noexcept { return state_->link_names; }

std::optional<std::size_t> ChainSampleKinematics::LinkIndex(std::string_view link_name) const noexcept {
  for (std::size_t i = 0; i < state_->link_names.size(); ++i) {
    if (state_->link_names[i] == link_name) return i;
  }
  return std::nullopt;
}

namespace {

void CheckLinkIndex(const std::vector<std::string>& names, std::size_t link_index) {
  if (link_index >= names.size()) {
    throw std::invalid_argument("link index " + std::to_string(link_index) + " is not on the chain (it has " +
                                std::to_string(names.size()) + " links after the base, indices 0 to " +
                                std::to_string(names.size() - 1) + ")");
  }
}

}  // namespace

std::size_t ChainSampleKinematics::JointsMovingLink(std::size_t link_index) const {
  CheckLinkIndex(state_->link_names, link_index);
  return state_->links[link_index].moving_joints;
}

void ChainSampleKinematics::Update(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot, const std::string& where) {
  State& s = *state_;
  const KinematicChain& chain = s.chain;
  s.updated = false;
  const auto joint_where = [&chain, &where](const char* symbol) {
    return [&chain, &where, symbol](std::size_t i) {
      return where + ", " + symbol + std::to_string(i + 1) + " (joint '" + chain.joint_names()[i] + "')";
    };
  };
  s.q = internal::CheckSample(chain, q, qdot, s.options.reflected_mass.check_joint_limits, where + " positions",
                              where + " velocities", joint_where("q"), joint_where("qd"));

  // M(q) and its Cholesky factor.
  if (s.dynamics.JntToMass(s.q, s.mass) < 0) throw std::runtime_error("KDL ChainDynParam::JntToMass failed");
  s.cholesky.compute(s.mass.data);
  if (s.cholesky.info() != Eigen::Success) internal::RefuseSingularInertia(chain);
  s.lower = s.cholesky.matrixL();

  // One pass over the segments: each link's frame, then its Jacobian columns and twist.
  const KDL::Chain& kdl = chain.impl().chain;
  KDL::Frame frame = KDL::Frame::Identity();
  std::size_t joint = 0;
  for (unsigned i = 0; i < kdl.getNrOfSegments(); ++i) {
    const KDL::Segment& segment = kdl.getSegment(i);
    const KDL::Joint& kdl_joint = segment.getJoint();
    if (kdl_joint.getType() != KDL::Joint::Fixed) {
      s.axes[joint] = ToEigen(frame.M * kdl_joint.JointAxis());
      s.axis_points_m[joint] = ToEigen(frame * kdl_joint.JointOrigin());
      frame = frame * segment.pose(s.q(static_cast<unsigned>(joint)));
      ++joint;
    } else {
      frame = frame * segment.pose(0.0);
    }
    LinkState& link = s.links[i];
    link.rotation = ToEigen(frame.M);
    link.origin_m = ToEigen(frame.p);
    for (std::size_t k = 0; k < joint; ++k) {
      const auto column = static_cast<Eigen::Index>(k);
      if (s.prismatic[k]) {
        link.jacobian.col(column).head<3>() = s.axes[k];
        link.jacobian.col(column).tail<3>().setZero();
      } else {
        link.jacobian.col(column).head<3>() = s.axes[k].cross(link.origin_m - s.axis_points_m[k]);
        link.jacobian.col(column).tail<3>() = s.axes[k];
      }
    }
    const auto moving = static_cast<Eigen::Index>(joint);
    link.velocity_m_per_s = link.jacobian.topLeftCorner(3, moving) * qdot.head(moving);
    link.angular_rad_per_s = link.jacobian.bottomLeftCorner(3, moving) * qdot.head(moving);
  }
  s.updated = true;
}

PointMotion ChainSampleKinematics::Point(std::size_t link_index, const Eigen::Vector3d& point_in_link_m) const noexcept {
  const State& s = *state_;
  assert(s.updated && link_index < s.links.size());
  const LinkState& link = s.links[link_index];
  PointMotion motion;
  const Eigen::Vector3d r = link.rotation * point_in_link_m;  // origin -> point, base frame
  motion.position_m = link.origin_m + r;
  motion.velocity_m_per_s = link.velocity_m_per_s + link.angular_rad_per_s.cross(r);
  motion.speed_m_per_s = motion.velocity_m_per_s.norm();
  motion.moving = motion.speed_m_per_s > s.options.rest_speed_m_per_s;
  if (!motion.moving) return motion;
  motion.direction = motion.velocity_m_per_s / motion.speed_m_per_s;

  // X = J_v(p)ᵀ = J_v(o)ᵀ + J_ωᵀ [r]× (v = v_o + ω × r = v_o − [r]× ω), rows of joints that
  // move the link only; the rest are zero.
  const auto k = static_cast<Eigen::Index>(link.moving_joints);
  const auto n = static_cast<Eigen::Index>(s.n);
  Eigen::MatrixXd& x = s.scratch;
  const Eigen::Matrix3d skew = Skew(r);
  for (Eigen::Index j = 0; j < n; ++j) {
    if (j < k) {
      x.row(j) = link.jacobian.col(j).head<3>().transpose() + link.jacobian.col(j).tail<3>().transpose() * skew;
    } else {
      x.row(j).setZero();
    }
  }
  // X ← L⁻¹ X by forward substitution (in place, no allocation); then Λ⁻¹ = XᵀX.
  const Eigen::MatrixXd& lower = s.lower;
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::RowVector3d row = x.row(i);
    for (Eigen::Index j = 0; j < i; ++j) row -= lower(i, j) * x.row(j);
    x.row(i) = row / lower(i, i);
  }
  double along = 0.0;   // uᵀ Λ⁻¹ u = |X u|²
  double trace = 0.0;   // trace(Λ⁻¹) = |X|²
  for (Eigen::Index i = 0; i < n; ++i) {
    const double projection = x.row(i).dot(motion.direction);
    along += projection * projection;
    trace += x.row(i).squaredNorm();
  }
  motion.reflected_mass_kg = along > s.options.reflected_mass.singular_relative_tolerance * trace && along > 0.0
                                 ? 1.0 / along
                                 : std::numeric_limits<double>::infinity();
  return motion;
}

Eigen::Vector3d ChainSampleKinematics::LinkOrigin(std::size_t link_index) const {
  CheckLinkIndex(state_->link_names, link_index);
  return state_->links[link_index].origin_m;
}

Eigen::Matrix3d ChainSampleKinematics::LinkRotation(std::size_t link_index) const {
  CheckLinkIndex(state_->link_names, link_index);
  return state_->links[link_index].rotation;
}

}  // namespace covopt::robot
