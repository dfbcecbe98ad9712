#include "oracle_options.hpp"

#include <stdexcept>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "covopt/core/impact_result.hpp"
#include "covopt/core/quantity.hpp"
#include "covopt/core/time_integration.hpp"
#include "errors.hpp"
#include "quantity.hpp"
#include "simulation_plan.hpp"

namespace covopt::cli {

void AddOracleOptions(CLI::App& sub, OracleFlags& flags, std::string_view judged, std::string_view group) {
  sub.add_option("--oracle", flags.oracle,
                 fmt::format("which path judges {}: auto (default: exact where the scene has an energy integral, "
                             "else the time path), exact, or time-path",
                             judged))
      ->type_name("auto|exact|time-path")
      ->group(std::string(group));
  sub.add_option("--method", flags.method,
                 fmt::format("the time path's integrator: cvode (Adams) or one of {} (default {}); exact "
                             "means --oracle exact",
                             IntegratorNames(), ToString(TimeIntegrationOptions{}.method)))
      ->type_name("INTEGRATOR")
      ->group(std::string(group));
  sub.add_option("--rtol", flags.rtol,
                 fmt::format("the time path's relative tolerance, in [1e-14, 1e-2] (default {:g})",
                             TimeIntegrationOptions{}.relative_tolerance))
      ->type_name("RATIO")
      ->group(std::string(group));
  sub.add_option("--max-steps", flags.max_steps,
                 fmt::format("the time path's limit on internal steps per impact, >= 10; reaching it fails "
                             "that evaluation (default {})",
                             TimeIntegrationOptions{}.max_steps))
      ->type_name("N")
      ->group(std::string(group));
}

optim::OracleOptions ResolveOracleFlags(const OracleFlags& flags, const Scene& scene, std::string_view purpose,
                                        std::vector<std::string>& warnings) {
  optim::OracleOptions oracle;
  if (flags.oracle) {
    const auto choice = optim::ParseOracleChoice(*flags.oracle);
    if (!choice) {
      throw InputError(fmt::format("--oracle: expected auto, exact or time-path (got '{}')", *flags.oracle));
    }
    oracle.choice = *choice;
  }
  bool method_exact = false;
  if (flags.method) {
    if (*flags.method == "exact") {
      method_exact = true;
    } else if (*flags.method == "cvode") {
      oracle.time_path.method = ComputationMethod::kCvodeAdams;
    } else if (const auto named = ParseComputationMethod(*flags.method);
               named && *named != ComputationMethod::kExact) {
      oracle.time_path.method = *named;
    } else {
      throw InputError(fmt::format("--method: expected exact, cvode or one of {} (got '{}')", IntegratorNames(),
                                   *flags.method));
    }
  }
  if (method_exact) {
    if (oracle.choice == optim::OracleChoice::kTimePath) {
      throw InputError("--method exact contradicts --oracle time-path: the time path runs an integrator; give one "
                       "of " + IntegratorNames() + ", or --oracle exact");
    }
    if (flags.rtol) throw InputError("--rtol applies to the time path; --method exact runs none");
    if (flags.max_steps) throw InputError("--max-steps applies to the time path; --method exact runs none");
    oracle.choice = optim::OracleChoice::kExact;
  }
  if (flags.max_steps) {
    if (*flags.max_steps < 10) throw InputError(fmt::format("--max-steps must be >= 10 (got {})", *flags.max_steps));
    oracle.time_path.max_steps = *flags.max_steps;
  }
  if (flags.rtol) {
    oracle.time_path.relative_tolerance = ParseQuantity(*flags.rtol, quantity_specs::kTolerance, "--rtol");
    if (!(oracle.time_path.relative_tolerance >= 1e-14 && oracle.time_path.relative_tolerance <= 1e-2)) {
      throw InputError(fmt::format("--rtol must be in [1e-14, 1e-2] (got '{}')", *flags.rtol));
    }
  }
  if (oracle.choice == optim::OracleChoice::kExact) {
    if (flags.method && !method_exact) {
      throw InputError(fmt::format("--method {} applies to the time path; --oracle exact runs none", *flags.method));
    }
    if (flags.rtol) throw InputError("--rtol applies to the time path; --oracle exact runs none");
    if (flags.max_steps) throw InputError("--max-steps applies to the time path; --oracle exact runs none");
    try {
      (void)optim::ChooseOracle(scene, oracle.choice);
    } catch (const std::invalid_argument&) {
      throw InputError(fmt::format(
          "--oracle exact: the exact path needs an energy integral; a scene with {} has only the time path; use "
          "--oracle auto or time-path",
          scene.robot_brakes() && scene.head.has_neck() ? "braking and a neck"
          : scene.robot_brakes()                         ? "braking (--braking)"
                                                         : "a neck (--torso-mass)"));
    }
  } else if (oracle.choice == optim::OracleChoice::kAuto && (flags.method || flags.rtol || flags.max_steps) &&
             optim::ChooseOracle(scene, oracle.choice).kind == optim::OracleKind::kExact) {
    std::vector<std::string_view> unused;
    if (flags.method) unused.push_back("--method");
    if (flags.rtol) unused.push_back("--rtol");
    if (flags.max_steps) unused.push_back("--max-steps");
    warnings.push_back(fmt::format("{} {} not used: auto chose the exact path for this scene (add --oracle "
                                   "time-path to {} on the time path)",
                                   unused.size() == 1 ? std::string(unused.front())
                                                      : fmt::format("{} and {}",
                                                                    fmt::join(unused.begin(), unused.end() - 1, ", "),
                                                                    unused.back()),
                                   unused.size() == 1 ? "is" : "are", purpose));
  }
  return oracle;
}

}  // namespace covopt::cli
