#include "robot.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/report/robot_json.hpp"
#include "covopt/robot/reflected_mass.hpp"
#include "errors.hpp"
#include "run_context.hpp"

namespace covopt::cli {
namespace {

constexpr std::string_view kFooter = R"(The reflected mass m_u = 1 / (u' J_v M^-1 J_v' u) of the contact point along the
unit direction u (J_v: the point's linear Jacobian, M: the joint-space inertia
matrix, from the URDF's links through Orocos KDL), and its extremes over all
directions (the reciprocal eigenvalues of J_v M^-1 J_v'). A direction the robot
cannot move the point in (a singular configuration) has an infinite mass:
"fixed", with a warning. Links beyond the tip ride along as rigid payload.
--payload-mass (with --payload-com, --payload-inertia) mounts a tool and the
part it holds on the tip link: it counts in the reflected mass, and the table
and the JSON give the masses without it too.
Without --direction only the extremes are given. Joint positions (and a
trajectory's velocities) must lie within the URDF's <limit>s and a full turn;
--ignore-joint-limits skips the URDF's limits, with a warning. Robot models
shipped with covopt: share/covopt/robots.

--trajectory FILE.csv checks a motion instead (no --joints, no --direction):
per sample the contact point's speed |J_v q'|, the reflected mass along its
motion, the injury ratios of an impact there on the covering and head of the
scene flags (as in 'covopt speed-limit'), the max safe speed at that mass, and
safe_speed_scale = min over samples of max safe speed / speed: the factor by
which the whole trajectory may be sped up (> 1) or must be slowed (< 1); the
URDF's velocity limits are not part of it. The CSV's first line is a header
unless it is all numbers (then it is a sample, with a warning); at most 64 MiB
and 10^6 samples. The
table lists every sample of a trajectory of up to 20 samples; of a longer one
the 10 with the smallest speed scale and every unsafe one (at most 30).

Exit codes: 0 done (with --trajectory also when the motion is unsafe); 1 a --csv
or --plot output could not be written; 2 bad input.)";

std::string Mass(double mass_kg) {
  return std::isfinite(mass_kg) ? fmt::format("{:.4g} kg", mass_kg) : std::string("fixed (infinite)");
}

std::string Direction(const Eigen::Vector3d& v) {
  auto clean = [](double x) { return std::abs(x) < 5e-13 ? 0.0 : x; };
  return fmt::format("({:.4g}, {:.4g}, {:.4g})", clean(v[0]), clean(v[1]), clean(v[2]));
}

}  // namespace

void SetupRobot(CLI::App* sub, RobotOptions& options) {
  sub->footer(std::string(kFooter));
  AddRobotModelOptions(*sub, options.model, false, "Robot model");
  sub->add_flag("--json", options.json, "print one JSON object (SI units) instead of the table")->group("Output");
  AddRobotTrajectoryOptions(*sub, options.trajectory);
}

int RunRobot(const RobotOptions& options, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "robot");
  if (options.trajectory.file) return RunRobotTrajectory(options.model, options.trajectory, options.json, options.run, out, err);
  if (const auto flag = options.trajectory.FirstCheckFlag()) {
    return errors.BadInput(fmt::format("{} applies with --trajectory FILE.csv only (the trajectory check)", *flag));
  }
  robot::ReflectedMassResult result;
  std::optional<report::RobotPayload> payload;  // with one: the same contact without it
  std::string robot_line;
  try {
    const RobotModelInput input = ResolveRobotModelInput(options.model, false);
    result = robot::ReflectedMass(input.chain, input.joint_positions, input.point_in_tip_m, input.direction,
                                  options.model.reflected_mass_options());
    if (!input.chain.payload().empty()) {
      payload = report::RobotPayload{
          input.chain.payload(),
          robot::ReflectedMass(input.chain.WithPayload({}), input.joint_positions, input.point_in_tip_m,
                               input.direction, options.model.reflected_mass_options())};
    }
    std::string joints;
    for (std::size_t i = 0; i < input.chain.joint_names().size(); ++i) {
      joints += fmt::format("{}{} {:.6g}", i ? ", " : "", input.chain.joint_names()[i],
                            input.joint_positions[static_cast<Eigen::Index>(i)]);
    }
    robot_line = fmt::format("Robot    {}: {} -> {}, {} movable joint{}\nJoints   {}\n", input.chain.robot_name(),
                             input.chain.base_link(), input.chain.tip_link(), input.chain.joint_count(),
                             input.chain.joint_count() == 1 ? "" : "s", joints.empty() ? "(none)" : joints);
    if (payload) {
      const Eigen::Matrix3d& inertia = payload->payload.inertia_kg_m2;
      robot_line += fmt::format(
          "Payload  {:.6g} kg at {} m (tip frame), {}\n", payload->payload.mass_kg,
          Direction(payload->payload.center_of_mass_m),
          inertia.isZero(0.0) ? std::string("a point mass")
                              : fmt::format("inertia about its centre of mass (ixx, iyy, izz, ixy, ixz, iyz) "
                                            "{:.4g}, {:.4g}, {:.4g}, {:.4g}, {:.4g}, {:.4g} kg m²",
                                            inertia(0, 0), inertia(1, 1), inertia(2, 2), inertia(0, 1),
                                            inertia(0, 2), inertia(1, 2)));
    }
  } catch (const std::invalid_argument& e) {  // InputError and the library's checks
    return errors.BadInput(e.what());
  }
  if (options.json) {
    out << WithRunProvenance(report::RobotJson(result, {}, 2, payload), options.run) << '\n';
    return 0;
  }
  fmt::print(out, "{}", robot_line);
  fmt::print(out, "Contact  {} m in the base frame\n\nReflected mass{}\n", Direction(result.contact_point_m),
             payload ? fmt::format("{:<37} without the payload", "") : "");
  // The mass with the payload, and without it (its own extreme direction) when there is one.
  const auto row = [&](const char* name, const Eigen::Vector3d& direction, double mass_kg, double bare_kg) {
    fmt::print(out, "  {:<8} {:<30} {}\n", name, Direction(direction),
               payload ? fmt::format("{:<18} {}", Mass(mass_kg), Mass(bare_kg)) : Mass(mass_kg));
  };
  const robot::ReflectedMassResult& bare = payload ? payload->without_payload : result;
  if (result.reflected_mass_kg) row("along", *result.direction, *result.reflected_mass_kg, *bare.reflected_mass_kg);
  row("largest", result.max_direction, result.max_reflected_mass_kg, bare.max_reflected_mass_kg);
  row("smallest", result.min_direction, result.min_reflected_mass_kg, bare.min_reflected_mass_kg);
  if (result.warnings.empty()) {
    fmt::print(out, "\nWarnings: none\n");
  } else {
    fmt::print(out, "\nWarnings\n");
    for (const std::string& warning : result.warnings) fmt::print(out, "  - {}\n", warning);
  }
  return 0;
}

}  // namespace covopt::cli
