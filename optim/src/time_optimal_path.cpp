// The time-optimal path parameterisation by reachability analysis (optim/time_optimal_path.hpp,
// docs/model.md "Re-timing"). Per segment the constraints are linear in (x, u) = (ṡ², s̈); the
// controllable set K_i is the projection of that polygon onto x, computed exactly by eliminating
// u (Fourier-Motzkin: every lower bound on u against every upper bound), which is the 2-variable
// LP of TOPP-RA solved for both ends of K_i at once.
#include "covopt/optim/time_optimal_path.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <covopt/core/number_format.hpp>

namespace covopt::optim {

const char* ToString(TimeOptimalStatus status) noexcept {
  return status == TimeOptimalStatus::kSuccess ? "success" : "infeasible";
}

const char* ToString(PathSpeedBound bound) noexcept {
  switch (bound) {
    case PathSpeedBound::kPathSpeed: return "path-speed";
    case PathSpeedBound::kJointSpeed: return "joint-speed";
    case PathSpeedBound::kJointAcceleration: return "joint-acceleration";
    case PathSpeedBound::kBoundary: return "boundary";
  }
  return "path-speed";
}

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::string Num(double value) { return FormatSignificant(value); }

/// "name[index]" (appended piecewise: GCC 12's -Wrestrict misfires on "[" + to_string + "]").
std::string Indexed(std::string name, std::size_t index) {
  name += '[';
  name += std::to_string(index);
  name += ']';
  return name;
}

[[noreturn]] void Reject(const std::string& field, double value, const std::string& range) {
  throw std::invalid_argument("time-optimal path: " + field + " = " + Num(value) + " must be " + range);
}

[[noreturn]] void RejectSize(const std::string& field, std::size_t size, std::size_t expected,
                             const std::string& what) {
  throw std::invalid_argument("time-optimal path: " + field + " has " + std::to_string(size) +
                              " entries; it must have " + std::to_string(expected) + " (" + what + ")");
}

/// The largest x = ṡ² the static bounds allow at sample i (path speed, joint speeds).
double StaticBound(const PathSamples& path, const PathLimits& limits, std::size_t i) {
  double x_max = limits.max_path_speed[i] * limits.max_path_speed[i];
  for (Eigen::Index j = 0; j < limits.max_joint_speed.size(); ++j) {
    const double slope = std::abs(path.dq_ds[i][j]);
    if (slope > 0.0 && std::isfinite(limits.max_joint_speed[j])) {
      const double v = limits.max_joint_speed[j] / slope;
      x_max = std::min(x_max, v * v);
    }
  }
  return x_max;
}

void ValidateLimits(const PathLimits& limits, std::size_t samples, Eigen::Index joints) {
  if (limits.max_path_speed.size() != samples) {
    RejectSize("limits.max_path_speed", limits.max_path_speed.size(), samples, "one per sample");
  }
  for (std::size_t i = 0; i < samples; ++i) {
    if (!(limits.max_path_speed[i] > 0.0)) {
      Reject(Indexed("limits.max_path_speed", i), limits.max_path_speed[i], "> 0 (or +inf: none)");
    }
  }
  if (limits.max_joint_speed.size() != joints) {
    RejectSize("limits.max_joint_speed", static_cast<std::size_t>(limits.max_joint_speed.size()),
               static_cast<std::size_t>(joints), "one per joint of path.dq_ds");
  }
  if (limits.max_joint_acceleration.size() != joints) {
    RejectSize("limits.max_joint_acceleration", static_cast<std::size_t>(limits.max_joint_acceleration.size()),
               static_cast<std::size_t>(joints), "one per joint of path.dq_ds");
  }
  for (Eigen::Index j = 0; j < joints; ++j) {
    if (!(limits.max_joint_speed[j] > 0.0)) {
      Reject(Indexed("limits.max_joint_speed", static_cast<std::size_t>(j)), limits.max_joint_speed[j],
             "> 0 [rad/s or m/s] (or +inf: none)");
    }
    const double a = limits.max_joint_acceleration[j];
    if (!(a > 0.0 && std::isfinite(a))) {
      Reject(Indexed("limits.max_joint_acceleration", static_cast<std::size_t>(j)), a, "> 0 and finite [rad/s² or m/s²]");
    }
  }
}

void ValidateBoundary(const std::optional<double>& speed, const std::string& field, double static_bound_x) {
  if (!speed) return;
  const double bound = std::sqrt(static_bound_x);
  if (!(*speed >= 0.0 && *speed <= bound)) {
    Reject(field, *speed, "in [0, " + Num(bound) + "] (the sample's path-speed and joint-speed bounds)");
  }
}

void Validate(const PathSamples& path, const PathLimits& limits, const TimeOptimalOptions& options) {
  const std::size_t n = path.s.size();
  if (n < 2) {
    throw std::invalid_argument("time-optimal path: path.s has " + std::to_string(n) +
                                " samples; it must have at least 2");
  }
  if (path.dq_ds.size() != n) RejectSize("path.dq_ds", path.dq_ds.size(), n, "one per sample of path.s");
  const Eigen::Index joints = path.dq_ds[0].size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::string at = Indexed("", i);
    if (!std::isfinite(path.s[i])) Reject("path.s" + at, path.s[i], "finite");
    if (i > 0 && !(path.s[i] > path.s[i - 1])) {
      Reject("path.s" + at, path.s[i], "> " + Indexed("path.s", i - 1) + " = " + Num(path.s[i - 1]) +
                                           " (strictly increasing)");
    }
    if (path.dq_ds[i].size() != joints) {
      RejectSize("path.dq_ds" + at, static_cast<std::size_t>(path.dq_ds[i].size()),
                 static_cast<std::size_t>(joints), "as many joints as path.dq_ds[0]");
    }
    for (Eigen::Index j = 0; j < joints; ++j) {
      if (!std::isfinite(path.dq_ds[i][j])) {
        Reject(Indexed("path.dq_ds" + at, static_cast<std::size_t>(j)), path.dq_ds[i][j], "finite");
      }
    }
  }
  ValidateLimits(limits, n, joints);
  if (!(options.tolerance > 0.0 && options.tolerance <= 1e-3)) {
    Reject("options.tolerance", options.tolerance, "in (0, 1e-3]");
  }
  ValidateBoundary(options.start_path_speed, "options.start_path_speed", StaticBound(path, limits, 0));
  ValidateBoundary(options.end_path_speed, "options.end_path_speed", StaticBound(path, limits, n - 1));
}

/// One constraint a x + b u <= c of a segment, and what it stands for.
struct Constraint {
  double a = 0.0, b = 0.0, c = 0.0;
  enum class Kind { kAccelerationStart, kAccelerationEnd, kReachNext } kind = Kind::kReachNext;
  Eigen::Index joint = 0;
};

/// What set an end of a controllable set: a static bound, or one constraint, or a pair of
/// constraints (u eliminated between them).
struct Cause {
  enum class Kind { kNonNegative, kStatic, kSingle, kPair } kind = Kind::kNonNegative;
  int first = -1, second = -1;
};

struct Interval {
  double lo = 0.0, hi = kInfinity;
  Cause lo_by, hi_by;
};

/// The problem, its segments' constraints and their description.
class Solver {
 public:
  Solver(const PathSamples& path, const PathLimits& limits, const TimeOptimalOptions& options)
      : path_(path), limits_(limits), options_(options), n_(path.s.size()), static_x_(n_) {
    std::vector<double> finite;
    for (std::size_t i = 0; i < n_; ++i) {
      static_x_[i] = StaticBound(path, limits, i);
      if (std::isfinite(static_x_[i])) finite.push_back(static_x_[i]);
    }
    // The scale of the tolerance: the median finite speed bound (x = ṡ²), not the largest, which a
    // sample where the joints barely move (q' ~ 0) can make arbitrarily large; 1 when none is finite.
    if (!finite.empty()) {
      const auto middle = finite.begin() + static_cast<std::ptrdiff_t>(finite.size() / 2);
      std::nth_element(finite.begin(), middle, finite.end());
      x_scale_ = *middle;
    }
  }

  TimeOptimalProfile Run();

 private:
  void BuildSegment(std::size_t i, double next_lo, double next_hi);
  Interval Project(std::size_t i) const;
  std::string Describe(const Constraint& constraint, std::size_t i) const;
  std::string Describe(const Cause& cause, std::size_t i) const;
  TimeOptimalProfile Infeasible(TimeOptimalProfile profile, std::size_t i, const std::string& why) const;
  bool Backward(TimeOptimalProfile& profile, std::string& why, std::size_t& where);
  bool Forward(TimeOptimalProfile& profile, std::string& why, std::size_t& where);
  PathSpeedBound Classify(std::size_t i, double x) const;

  const PathSamples& path_;
  const PathLimits& limits_;
  const TimeOptimalOptions& options_;
  std::size_t n_;
  std::vector<double> static_x_;
  double x_scale_ = 1.0;  // see the constructor
  std::vector<Constraint> constraints_;  // of the segment being solved
  std::vector<int> upper_, lower_;       // indices of the constraints with b > 0, b < 0
};

void Solver::BuildSegment(std::size_t i, double next_lo, double next_hi) {
  constraints_.clear();
  const double ds = path_.s[i + 1] - path_.s[i];
  for (Eigen::Index j = 0; j < path_.dq_ds[i].size(); ++j) {
    const double start = path_.dq_ds[i][j];
    const double end = path_.dq_ds[i + 1][j];
    const double curvature = (end - start) / ds;  // q''_j on the segment
    const double a = limits_.max_joint_acceleration[j];
    // q̈ = q' u + q'' x at the start; at the end q'(s_{i+1}) u + q'' (x + 2 ds u).
    const double end_slope = end + 2.0 * ds * curvature;
    for (const double sign : {1.0, -1.0}) {
      constraints_.push_back({sign * curvature, sign * start, a, Constraint::Kind::kAccelerationStart, j});
      constraints_.push_back({sign * curvature, sign * end_slope, a, Constraint::Kind::kAccelerationEnd, j});
    }
  }
  // x + 2 ds u in [next_lo, next_hi]
  if (std::isfinite(next_hi)) constraints_.push_back({1.0, 2.0 * ds, next_hi, Constraint::Kind::kReachNext, 0});
  constraints_.push_back({-1.0, -2.0 * ds, -next_lo, Constraint::Kind::kReachNext, 0});
  upper_.clear();
  lower_.clear();
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    Constraint& c = constraints_[k];
    if (c.b == 0.0) continue;
    // Normalised: u <= C - A x (b > 0) or u >= C - A x (b < 0), with C = c / b, A = a / b.
    (c.b > 0.0 ? upper_ : lower_).push_back(static_cast<int>(k));
    const double b = c.b;
    c.a /= b;
    c.c /= b;
    c.b = b > 0.0 ? 1.0 : -1.0;
  }
}

Interval Solver::Project(std::size_t i) const {
  Interval k;
  k.hi = static_x_[i];
  k.hi_by = {Cause::Kind::kStatic, -1, -1};
  auto lower = [&](double x, Cause by) {
    if (x > k.lo) k = {x, k.hi, by, k.hi_by};
  };
  auto upper = [&](double x, Cause by) {
    if (x < k.hi) k = {k.lo, x, k.lo_by, by};
  };
  for (std::size_t c = 0; c < constraints_.size(); ++c) {
    const Constraint& con = constraints_[c];
    if (con.b != 0.0) continue;  // a x <= c
    const Cause by{Cause::Kind::kSingle, static_cast<int>(c), -1};
    if (con.a > 0.0) upper(con.c / con.a, by);
    if (con.a < 0.0) lower(con.c / con.a, by);
    if (con.a == 0.0 && con.c < 0.0) upper(-kInfinity, by);
  }
  // C_l - A_l x <= u <= C_k - A_k x  <=>  (A_k - A_l) x <= C_k - C_l
  for (const int up : upper_) {
    for (const int low : lower_) {
      const Constraint& cu = constraints_[static_cast<std::size_t>(up)];
      const Constraint& cl = constraints_[static_cast<std::size_t>(low)];
      const double alpha = cu.a - cl.a;
      const double beta = cu.c - cl.c;
      const Cause by{Cause::Kind::kPair, up, low};
      if (std::abs(alpha) <= 1e-14 * (std::abs(cu.a) + std::abs(cl.a))) {
        if (beta < -options_.tolerance * (std::abs(cu.c) + std::abs(cl.c))) upper(-kInfinity, by);
      } else if (alpha > 0.0) {
        upper(beta / alpha, by);
      } else {
        lower(beta / alpha, by);
      }
    }
  }
  // Round-off: an interval empty by less than the tolerance is the point hi.
  const double slack = options_.tolerance * std::max({std::abs(k.lo), std::isfinite(k.hi) ? std::abs(k.hi) : 0.0,
                                                      x_scale_});
  if (k.lo > k.hi && k.lo <= k.hi + slack) k.lo = k.hi = std::max(k.hi, 0.0);
  if (k.hi < 0.0 && k.hi >= -slack) k.hi = 0.0;
  return k;
}

std::string Solver::Describe(const Constraint& constraint, std::size_t i) const {
  const std::string joint = "joint " + std::to_string(constraint.joint);
  const std::string limit = Num(limits_.max_joint_acceleration[constraint.joint]);
  switch (constraint.kind) {
    case Constraint::Kind::kAccelerationStart:
      return joint + "'s acceleration limit " + limit + " at sample " + std::to_string(i);
    case Constraint::Kind::kAccelerationEnd:
      return joint + "'s acceleration limit " + limit + " at sample " + std::to_string(i + 1);
    case Constraint::Kind::kReachNext:
      return "reaching sample " + std::to_string(i + 1) + "'s controllable set";
  }
  return "";
}

std::string Solver::Describe(const Cause& cause, std::size_t i) const {
  switch (cause.kind) {
    case Cause::Kind::kNonNegative: return "ṡ >= 0";
    case Cause::Kind::kStatic:
      return "the path-speed and joint-speed bounds (ṡ <= " + Num(std::sqrt(static_x_[i])) + ")";
    case Cause::Kind::kSingle: return Describe(constraints_[static_cast<std::size_t>(cause.first)], i);
    case Cause::Kind::kPair:
      return Describe(constraints_[static_cast<std::size_t>(cause.first)], i) + " with " +
             Describe(constraints_[static_cast<std::size_t>(cause.second)], i);
  }
  return "";
}

TimeOptimalProfile Solver::Infeasible(TimeOptimalProfile profile, std::size_t i, const std::string& why) const {
  profile.status = TimeOptimalStatus::kInfeasible;
  profile.path_speed.clear();
  profile.path_acceleration.clear();
  profile.time_s.clear();
  profile.bound.clear();
  profile.message = "infeasible at sample " + std::to_string(i) + " (s = " + Num(path_.s[i]) + "): " + why;
  return profile;
}

bool Solver::Backward(TimeOptimalProfile& profile, std::string& why, std::size_t& where) {
  profile.controllable_min.assign(n_, 0.0);
  profile.controllable_max.assign(n_, 0.0);
  double lo = 0.0, hi = static_x_[n_ - 1];
  if (options_.end_path_speed) lo = hi = *options_.end_path_speed * *options_.end_path_speed;
  profile.controllable_min[n_ - 1] = lo;
  profile.controllable_max[n_ - 1] = hi;
  for (std::size_t i = n_ - 1; i-- > 0;) {
    BuildSegment(i, lo, hi);
    const Interval k = Project(i);
    if (!(k.lo <= k.hi)) {
      where = i;
      if (k.hi == -kInfinity) {
        why = Describe(k.hi_by, i) + " cannot be kept at any path speed";
      } else if (k.hi < 0.0) {
        why = Describe(k.hi_by, i) + " cannot be kept at any path speed >= 0";
      } else {
        why = "the controllable set is empty: ṡ <= " + Num(std::sqrt(k.hi)) + " (" + Describe(k.hi_by, i) +
              ") but ṡ >= " + Num(std::sqrt(k.lo)) + " (" + Describe(k.lo_by, i) + ")";
      }
      return false;
    }
    lo = k.lo;
    hi = k.hi;
    profile.controllable_min[i] = lo;
    profile.controllable_max[i] = hi;
  }
  return true;
}

bool Solver::Forward(TimeOptimalProfile& profile, std::string& why, std::size_t& where) {
  std::vector<double> x(n_, 0.0);
  x[0] = profile.controllable_max[0];
  if (options_.start_path_speed) {
    const double start = *options_.start_path_speed * *options_.start_path_speed;
    const double slack = options_.tolerance * std::max(start, x_scale_);
    if (start > profile.controllable_max[0] + slack || start < profile.controllable_min[0] - slack) {
      where = 0;
      why = "options.start_path_speed " + Num(*options_.start_path_speed) + " is outside the controllable set ṡ in [" +
            Num(std::sqrt(profile.controllable_min[0])) + ", " + Num(std::sqrt(profile.controllable_max[0])) +
            "]: the joints' acceleration limits cannot keep the path's bounds from there";
      return false;
    }
    x[0] = std::clamp(start, profile.controllable_min[0], profile.controllable_max[0]);
  }
  profile.path_acceleration.assign(n_ - 1, 0.0);
  for (std::size_t i = 0; i + 1 < n_; ++i) {
    if (!std::isfinite(x[i])) break;
    BuildSegment(i, profile.controllable_min[i + 1], profile.controllable_max[i + 1]);
    double u = kInfinity;
    for (const int up : upper_) {
      const Constraint& c = constraints_[static_cast<std::size_t>(up)];
      u = std::min(u, c.c - c.a * x[i]);
    }
    const double ds = path_.s[i + 1] - path_.s[i];
    // Round-off: keep x_{i+1} inside K_{i+1}; u follows from the x's.
    x[i + 1] = std::clamp(x[i] + 2.0 * ds * u, profile.controllable_min[i + 1], profile.controllable_max[i + 1]);
    profile.path_acceleration[i] = (x[i + 1] - x[i]) / (2.0 * ds);
  }
  for (std::size_t i = 0; i < n_; ++i) {
    if (!std::isfinite(x[i])) {
      where = i;
      why = "the path speed is unbounded: no joint moves there and max_path_speed is +inf";
      return false;
    }
  }
  profile.path_speed.resize(n_);
  profile.bound.resize(n_);
  profile.time_s.assign(n_, 0.0);
  for (std::size_t i = 0; i < n_; ++i) {
    profile.path_speed[i] = std::sqrt(x[i]);
    profile.bound[i] = Classify(i, x[i]);
  }
  for (std::size_t i = 0; i + 1 < n_; ++i) {
    const double sum = profile.path_speed[i] + profile.path_speed[i + 1];
    if (!(sum > 0.0)) {
      where = i;
      why = "the path speed is 0 here and at sample " + std::to_string(i + 1) + ": the path would take forever";
      return false;
    }
    profile.time_s[i + 1] = profile.time_s[i] + 2.0 * (path_.s[i + 1] - path_.s[i]) / sum;
  }
  return true;
}

PathSpeedBound Solver::Classify(std::size_t i, double x) const {
  if ((i == 0 && options_.start_path_speed) || (i + 1 == n_ && options_.end_path_speed)) {
    return PathSpeedBound::kBoundary;
  }
  const double tight = 1.0 - 10.0 * options_.tolerance;
  const double path_x = limits_.max_path_speed[i] * limits_.max_path_speed[i];
  if (std::isfinite(path_x) && x >= tight * path_x) return PathSpeedBound::kPathSpeed;
  if (std::isfinite(static_x_[i]) && x >= tight * static_x_[i]) return PathSpeedBound::kJointSpeed;
  return PathSpeedBound::kJointAcceleration;
}

TimeOptimalProfile Solver::Run() {
  TimeOptimalProfile profile;
  std::string why;
  std::size_t where = 0;
  if (!Backward(profile, why, where) || !Forward(profile, why, where)) return Infeasible(std::move(profile), where, why);
  profile.status = TimeOptimalStatus::kSuccess;
  profile.message = "success: " + std::to_string(n_) + " samples, " + Num(profile.duration_s()) + " s";
  return profile;
}

}  // namespace

TimeOptimalProfile TimeOptimalParameterization(const PathSamples& path, const PathLimits& limits,
                                               const TimeOptimalOptions& options) {
  Validate(path, limits, options);
  Solver solver(path, limits, options);
  return solver.Run();
}

}  // namespace covopt::optim
