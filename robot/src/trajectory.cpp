#include "covopt/robot/trajectory.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "chain_impl.hpp"

namespace covopt::robot {

const char* ToString(ContactMotionStatus status) noexcept {
  switch (status) {
    case ContactMotionStatus::kSuccess: return "success";
    case ContactMotionStatus::kFixedDirections: return "fixed-directions";
  }
  return "unknown";
}

namespace {

std::string_view Trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string_view> SplitColumns(std::string_view line) {
  std::vector<std::string_view> columns;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    columns.push_back(Trim(line.substr(start, comma == std::string_view::npos ? line.npos
                                                                              : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return columns;
}

/// "time [s]", "q2 [rad]", "qd1 [rad/s]": what column `index` (0-based) holds.
std::string ColumnMeaning(std::size_t index, std::size_t joint_count) {
  if (index == 0) return "time [s]";
  if (index <= joint_count) return "q" + std::to_string(index) + " [rad]";
  return "qd" + std::to_string(index - joint_count) + " [rad/s]";
}

}  // namespace

JointTrajectory ReadJointTrajectory(std::istream& in, std::size_t joint_count,
                                    const std::string& source_name) {
  const std::size_t expected = 1 + 2 * joint_count;
  JointTrajectory trajectory;
  std::string line;
  std::size_t line_number = 0;
  bool header_seen = false;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string_view text = Trim(line);
    if (text.empty() || text.front() == '#') continue;
    const std::vector<std::string_view> columns = SplitColumns(text);
    const std::string where = source_name + ":" + std::to_string(line_number);
    if (columns.size() != expected) {
      std::ostringstream message;
      message << where << ": " << columns.size() << " column" << (columns.size() == 1 ? "" : "s")
              << ", expected " << expected << " (time [s], " << joint_count
              << " joint positions [rad], " << joint_count << " joint velocities [rad/s])";
      throw std::invalid_argument(message.str());
    }
    if (!header_seen) {
      header_seen = true;
      continue;
    }
    Eigen::VectorXd values(static_cast<Eigen::Index>(expected));
    for (std::size_t c = 0; c < expected; ++c) {
      const std::string cell(columns[c]);
      char* end = nullptr;
      errno = 0;
      const double value = std::strtod(cell.c_str(), &end);
      const bool parsed = !cell.empty() && end == cell.c_str() + cell.size() && errno != ERANGE;
      if (!parsed || !std::isfinite(value)) {
        throw std::invalid_argument(where + ", column " + std::to_string(c + 1) + " (" +
                                    ColumnMeaning(c, joint_count) + "): expected a finite number (got '" +
                                    cell + "')");
      }
      values[static_cast<Eigen::Index>(c)] = value;
    }
    const double time = values[0];
    if (!trajectory.time_s.empty() && time < trajectory.time_s.back()) {
      std::ostringstream message;
      message << where << ", column 1 (time [s]): time goes backwards (" << time << " s after "
              << trajectory.time_s.back() << " s)";
      throw std::invalid_argument(message.str());
    }
    const auto n = static_cast<Eigen::Index>(joint_count);
    trajectory.time_s.push_back(time);
    trajectory.positions.push_back(values.segment(1, n));
    trajectory.velocities.push_back(values.segment(1 + n, n));
  }
  if (in.bad()) throw std::invalid_argument(source_name + ": cannot read the trajectory");
  if (!header_seen) {
    throw std::invalid_argument(source_name + ": empty trajectory; expected a header line and "
                                "then one line per sample (time [s], positions, velocities)");
  }
  if (trajectory.time_s.empty()) {
    throw std::invalid_argument(source_name + ": the trajectory has a header but no samples");
  }
  return trajectory;
}

JointTrajectory ReadJointTrajectory(const std::filesystem::path& path, std::size_t joint_count) {
  const std::string source = path.string();
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    throw std::invalid_argument(source + ": no such trajectory file");
  }
  if (std::filesystem::is_directory(path, error)) {
    throw std::invalid_argument(source + ": is a directory, not a trajectory file");
  }
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(source + ": cannot read the trajectory file");
  return ReadJointTrajectory(in, joint_count, source);
}

ContactMotionResult ContactMotion(const KinematicChain& chain, const JointTrajectory& trajectory,
                                  const Eigen::Vector3d& point_in_tip_m,
                                  const ContactMotionOptions& options) {
  if (!(options.rest_speed_m_per_s >= 0.0) || !std::isfinite(options.rest_speed_m_per_s)) {
    std::ostringstream message;
    message << "rest_speed_m_per_s must be a finite number >= 0 m/s (got "
            << options.rest_speed_m_per_s << ")";
    throw std::invalid_argument(message.str());
  }
  if (trajectory.positions.size() != trajectory.size() ||
      trajectory.velocities.size() != trajectory.size()) {
    throw std::invalid_argument("trajectory: time_s, positions and velocities differ in length");
  }
  internal::CheckFinite(point_in_tip_m, "point");
  internal::CheckSingularTolerance(options.reflected_mass);
  ContactMotionResult result;
  result.joint_names = chain.joint_names();
  result.warnings = chain.warnings();
  std::size_t fixed_samples = 0;
  std::size_t first_fixed = 0;
  std::size_t fastest = 0;
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const std::string sample_name = "trajectory sample " + std::to_string(i + 1);
    const std::string positions_name = sample_name + " positions";
    const std::string velocities_name = sample_name + " velocities";
    const KDL::JntArray joints = internal::ToJntArray(chain, trajectory.positions[i], positions_name.c_str());
    internal::ToJntArray(chain, trajectory.velocities[i], velocities_name.c_str());
    if (!std::isfinite(trajectory.time_s[i])) {
      throw std::invalid_argument(sample_name + ": time must be a finite number");
    }
    // J_v, the contact point and Λ⁻¹ once per sample: the velocity and the mass share them.
    const internal::PointInertia point = internal::ComputePointInertia(chain, joints, point_in_tip_m);
    ContactMotionSample sample;
    sample.time_s = trajectory.time_s[i];
    sample.velocity_m_per_s = point.jacobian * trajectory.velocities[i];
    sample.speed_m_per_s = sample.velocity_m_per_s.norm();
    sample.moving = sample.speed_m_per_s > options.rest_speed_m_per_s;
    std::optional<Eigen::Vector3d> direction;
    if (sample.moving) {
      sample.direction = sample.velocity_m_per_s / sample.speed_m_per_s;
      direction = sample.direction;
    }
    const ReflectedMassResult mass = internal::ReflectedMassAt(chain, point, direction, options.reflected_mass);
    sample.contact_point_m = mass.contact_point_m;
    sample.reflected_mass_kg = direction ? *mass.reflected_mass_kg : mass.max_reflected_mass_kg;
    if (sample.moving && !std::isfinite(sample.reflected_mass_kg)) {
      if (fixed_samples++ == 0) first_fixed = i;
    }
    result.samples.push_back(sample);
    if (result.samples[i].speed_m_per_s > result.samples[fastest].speed_m_per_s) fastest = i;
  }
  std::ostringstream message;
  message << result.samples.size() << " samples, peak contact-point speed "
          << result.samples[fastest].speed_m_per_s << " m/s at t = "
          << result.samples[fastest].time_s << " s";
  result.message = message.str();
  if (fixed_samples > 0) {
    std::ostringstream warning;
    warning << fixed_samples << " moving sample" << (fixed_samples == 1 ? "" : "s")
            << " (first at t = " << result.samples[first_fixed].time_s
            << " s) move along a direction of infinite (fixed) reflected mass: a singular "
               "configuration on the trajectory";
    result.warnings.push_back(warning.str());
    result.status = ContactMotionStatus::kFixedDirections;
  }
  return result;
}

std::string ContactMotionResult::BriefReport() const {
  std::ostringstream out;
  out << "Contact motion: " << message << "\n";
  for (const std::string& warning : warnings) out << "  warning: " << warning << "\n";
  return out.str();
}

}  // namespace covopt::robot
