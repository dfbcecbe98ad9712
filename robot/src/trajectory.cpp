#include "covopt/robot/trajectory.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "chain_impl.hpp"
#include "covopt/internal/text.hpp"

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
  // Appended, not "q" + std::to_string(...): GCC 12 -O3 warns (-Wrestrict) on that when inlined.
  const bool position = index <= joint_count;
  std::string meaning = position ? "q" : "qd";
  meaning += std::to_string(position ? index : index - joint_count);
  meaning += position ? " [rad]" : " [rad/s]";
  return meaning;
}

}  // namespace

namespace {

/// "traj.csv:12, column 5 (q4 [rad], joint 'elbow')" or "trajectory sample 3, q4 (joint 'elbow')":
/// where joint j's position (offset 0) or velocity (offset n) of sample i is.
internal::JointWhere SampleWhere(const KinematicChain& chain, const JointTrajectory& trajectory, std::size_t i,
                                 std::size_t offset) {
  return [&chain, &trajectory, i, offset](std::size_t joint) {
    const std::size_t column = 1 + offset + joint;
    const std::string meaning = ColumnMeaning(column, chain.joint_count());
    const std::string name = "joint '" + chain.joint_names()[joint] + "'";
    if (i < trajectory.line_numbers.size()) {
      return trajectory.source_name + ":" + std::to_string(trajectory.line_numbers[i]) + ", column " +
             std::to_string(column + 1) + " (" + meaning + ", " + name + ")";
    }
    return "trajectory sample " + std::to_string(i + 1) + ", " + meaning.substr(0, meaning.find(' ')) + " (" +
           name + ")";
  };
}

/// A cell as a finite decimal number ([+-]digits[.digits][e[+-]digits]): no hex, inf or nan.
std::optional<double> ParseDecimal(std::string_view cell) {
  if (!cell.empty() && cell.front() == '+') cell.remove_prefix(1);  // from_chars takes '-' only
  if (cell.empty() || cell.front() == '+' || (cell.front() == '-' && cell.size() > 1 && cell[1] == '+')) {
    return std::nullopt;
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value, std::chars_format::general);
  if (error != std::errc() || end != cell.data() + cell.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

/// At most 40 characters of `cell`, for messages: a 100,000-digit value is not echoed; control
/// characters escaped (a NUL byte would end the exception's message).
std::string Excerpt(std::string_view cell) {
  return covopt::internal::EscapeControlCharacters(cell.size() <= 40 ? cell : cell.substr(0, 40)) +
         (cell.size() <= 40 ? "" : "...");
}

bool AllNumbers(const std::vector<std::string_view>& columns) {
  for (const std::string_view cell : columns) {
    if (!ParseDecimal(cell)) return false;
  }
  return true;
}

[[noreturn]] void RefuseColumnCount(const std::string& where, std::size_t got, std::size_t joint_count) {
  std::ostringstream message;
  message << where << ": " << got << " column" << (got == 1 ? "" : "s") << ", expected " << 1 + 2 * joint_count
          << " (time [s], " << joint_count << " joint positions [rad], " << joint_count
          << " joint velocities [rad/s])";
  throw std::invalid_argument(message.str());
}

/// One sample line's columns appended to `trajectory`.
void AppendSample(JointTrajectory& trajectory, const std::vector<std::string_view>& columns,
                  std::size_t joint_count, const std::string& where, std::size_t line_number) {
  const std::size_t expected = 1 + 2 * joint_count;
  Eigen::VectorXd values(static_cast<Eigen::Index>(expected));
  for (std::size_t c = 0; c < expected; ++c) {
    const std::optional<double> value = ParseDecimal(columns[c]);
    if (!value) {
      throw std::invalid_argument(where + ", column " + std::to_string(c + 1) + " (" + ColumnMeaning(c, joint_count) +
                                  "): expected a finite number (got '" + Excerpt(columns[c]) + "'), in decimal");
    }
    values[static_cast<Eigen::Index>(c)] = *value;
  }
  const double time = values[0];
  if (!trajectory.time_s.empty() && time < trajectory.time_s.back()) {
    std::ostringstream message;
    message << where << ", column 1 (time [s]): time goes backwards (" << time << " s after "
            << trajectory.time_s.back() << " s)";
    throw std::invalid_argument(message.str());
  }
  if (trajectory.size() == kMaxTrajectorySamples) {
    throw std::invalid_argument(where + ": more than 1000000 samples, the limit for a trajectory");
  }
  const auto n = static_cast<Eigen::Index>(joint_count);
  trajectory.time_s.push_back(time);
  trajectory.positions.push_back(values.segment(1, n));
  trajectory.velocities.push_back(values.segment(1 + n, n));
  trajectory.line_numbers.push_back(line_number);
}

JointTrajectory ParseJointTrajectory(std::string_view text, std::size_t joint_count, const std::string& source_name) {
  JointTrajectory trajectory;
  trajectory.source_name = source_name;
  std::size_t line_number = 0;
  bool first_line = true;
  bool header_seen = false;
  std::vector<std::string_view> columns;
  while (!text.empty()) {
    const std::size_t newline = text.find('\n');
    const std::string_view line = Trim(text.substr(0, newline));
    text.remove_prefix(newline == std::string_view::npos ? text.size() : newline + 1);
    ++line_number;
    if (line.empty() || line.front() == '#') continue;
    columns = SplitColumns(line);
    const std::string where = source_name + ":" + std::to_string(line_number);
    if (columns.size() != 1 + 2 * joint_count) RefuseColumnCount(where, columns.size(), joint_count);
    if (std::exchange(first_line, false) && !AllNumbers(columns)) {
      header_seen = true;
      continue;
    }
    AppendSample(trajectory, columns, joint_count, where, line_number);
  }
  if (trajectory.time_s.empty()) {
    throw std::invalid_argument(source_name + (header_seen ? ": the trajectory has a header but no samples"
                                                           : ": empty trajectory; expected an optional header "
                                                             "line and then one line per sample (time [s], "
                                                             "positions, velocities)"));
  }
  if (!header_seen) {
    trajectory.warnings.push_back(
        source_name + ": no header line (line 1 of the samples is all numbers): every line is read as a sample "
        "whose columns are time [s], the " + std::to_string(joint_count) + " joint positions [rad or m], the " +
        std::to_string(joint_count) + " joint velocities [rad/s or m/s]");
  }
  return trajectory;
}

}  // namespace

JointTrajectory ReadJointTrajectory(std::istream& in, std::size_t joint_count,
                                    const std::string& source_name) {
  return ParseJointTrajectory(internal::ReadBounded(in, kMaxTrajectoryBytes, source_name, "trajectory"),
                              joint_count, source_name);
}

JointTrajectory ReadJointTrajectory(const std::filesystem::path& path, std::size_t joint_count) {
  return ParseJointTrajectory(internal::ReadBoundedFile(path, kMaxTrajectoryBytes, "trajectory file"), joint_count,
                              path.string());
}

namespace {

/// `value` in its shortest form that reads back exactly (as covopt::FormatShortest, which robot
/// does not link); a non-finite value is refused, the reader would not take it.
void AppendShortest(std::string& text, double value, std::size_t sample, const char* what) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument("trajectory sample " + std::to_string(sample + 1) + ": " + what +
                                " is not a finite number; the trajectory CSV holds finite decimals only");
  }
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  text.append(buffer, result.ptr);
}

}  // namespace

void WriteJointTrajectory(std::ostream& out, const JointTrajectory& trajectory,
                          const std::vector<std::string>& joint_names) {
  const std::size_t n = joint_names.size();
  if (trajectory.positions.size() != trajectory.size() || trajectory.velocities.size() != trajectory.size()) {
    throw std::invalid_argument("trajectory: time_s (" + std::to_string(trajectory.size()) + "), positions (" +
                                std::to_string(trajectory.positions.size()) + ") and velocities (" +
                                std::to_string(trajectory.velocities.size()) + ") differ in length");
  }
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    if (static_cast<std::size_t>(trajectory.positions[i].size()) != n ||
        static_cast<std::size_t>(trajectory.velocities[i].size()) != n) {
      throw std::invalid_argument("trajectory sample " + std::to_string(i + 1) + ": " +
                                  std::to_string(trajectory.positions[i].size()) + " positions and " +
                                  std::to_string(trajectory.velocities[i].size()) + " velocities; the joint names give " +
                                  std::to_string(n) + " joints");
    }
  }
  std::string text = "time_s";
  for (const std::string& name : joint_names) text += "," + name;
  for (const std::string& name : joint_names) text += "," + name + "_velocity";
  text += "\n";
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    AppendShortest(text, trajectory.time_s[i], i, "time");
    for (Eigen::Index j = 0; j < static_cast<Eigen::Index>(n); ++j) {
      text += ',';
      AppendShortest(text, trajectory.positions[i][j], i, "a position");
    }
    for (Eigen::Index j = 0; j < static_cast<Eigen::Index>(n); ++j) {
      text += ',';
      AppendShortest(text, trajectory.velocities[i][j], i, "a velocity");
    }
    text += "\n";
  }
  out << text;
}

ContactMotionResult ContactMotion(const KinematicChain& chain, const JointTrajectory& trajectory,
                                  const Eigen::Vector3d& point_in_tip_m,
                                  const ContactMotionOptions& options) {
  internal::CheckContactMotionOptions(options);
  if (trajectory.positions.size() != trajectory.size() ||
      trajectory.velocities.size() != trajectory.size()) {
    throw std::invalid_argument("trajectory: time_s, positions and velocities differ in length");
  }
  internal::CheckPoint(point_in_tip_m);
  ContactMotionResult result;
  result.joint_names = chain.joint_names();
  result.warnings = chain.warnings();
  result.warnings.insert(result.warnings.end(), trajectory.warnings.begin(), trajectory.warnings.end());
  if (!options.reflected_mass.check_joint_limits) result.warnings.push_back(internal::JointLimitsIgnoredWarning(chain));
  std::size_t fixed_samples = 0;
  std::size_t first_fixed = 0;
  std::size_t fastest = 0;
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const std::string sample_name = "trajectory sample " + std::to_string(i + 1);
    const std::string positions_name = sample_name + " positions";
    const std::string velocities_name = sample_name + " velocities";
    const KDL::JntArray joints = internal::CheckSample(
        chain, trajectory.positions[i], trajectory.velocities[i], options.reflected_mass.check_joint_limits,
        positions_name, velocities_name, SampleWhere(chain, trajectory, i, 0),
        SampleWhere(chain, trajectory, i, chain.joint_count()));
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
    // The number only: ReflectedMassAt's sentences, formatted per sample, were most of the time.
    sample.contact_point_m = point.contact_point_m;
    sample.reflected_mass_kg = internal::ReflectedMassAlongOrMax(point, direction, options.reflected_mass);
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
