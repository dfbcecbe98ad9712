#pragma once
/// @file optimize.hpp
/// `covopt optimize`: which real covering material, how thick, and with what margin.
///
/// The scene (without covering) comes from Scene{}, --scene and the scene flags as in
/// `covopt simulate`. Problem (a), the default: the thinnest admissible covering — the
/// laceration and contusion ratios <= 1/safety factor and (default criterion) the covering not
/// fully compressed at the peak — continuous (E_c, b_c) and snapped to every catalog material. Problem (b), with --thickness: the covering with the least injury
/// at that thickness. Exit codes: 0 an answer (including "nothing is safe"), 1 the search
/// failed, 2 bad input.

#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "body_region_options.hpp"
#include "simulation_plan.hpp"
#include "covopt/optim/design.hpp"
#include "catalog_options.hpp"
#include "oracle_options.hpp"
#include "robot_model_options.hpp"
#include "run_context.hpp"
#include "uncertainty_options.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The options of `covopt optimize`, as typed (read and checked by RunOptimize).
struct OptimizeOptions {
  std::optional<std::string> scene_file;
  /// Scene flags by field name ("robot.mass" -> "10kg"); the covering's are not offered.
  std::map<std::string, std::string, std::less<>> scene_values;
  /// --thresholds, --head-area, --covering-law.
  SceneChoices choices;
  std::optional<std::string> max_thickness;     ///< --max-thickness (default 50 mm)
  std::optional<std::string> min_modulus;       ///< --min-modulus (default 0.1 MPa)
  std::optional<std::string> max_modulus;       ///< --max-modulus (default 1 GPa)
  std::optional<std::string> safety_factor;     ///< --safety-factor (default 1, or the scene file's)
  /// --urdf/--base/--tip/--joints/--point/--direction: robot.mass from the robot model.
  RobotModelOptions robot_model;
  std::optional<std::string> laceration_limit;  ///< --laceration-limit (default 1 MPa)
  std::optional<std::string> contusion_limit;   ///< --contusion-limit (default 2.52 J/cm²)
  /// --allow-full-compression: the paper's criterion (safety only) instead of the default
  /// "no-full-compression" (safe and the covering not fully compressed at the peak).
  bool allow_full_compression = false;
  /// --allow-crushing: a sacrificial liner; the crush criterion is reported, not applied.
  bool allow_crushing = false;
  /// --allow-unknown-strength: materials of unknown compressive strength may be recommended,
  /// each with a warning.
  bool allow_unknown_strength = false;
  std::optional<std::string> thickness;         ///< --thickness: problem (b)
  std::optional<std::string> covering_poisson;  ///< ν of the continuous design (0.25)
  std::optional<std::string> thickness_step;    ///< --thickness-step (default 0.5 mm)
  CatalogOptions catalog;                       ///< --catalog FILE (repeatable), --no-builtin
  std::vector<std::string> families;            ///< --family (repeatable)
  std::vector<std::string> materials;           ///< --material (repeatable): only these
  std::optional<std::string> global_algorithm;  ///< --global direct-l|isres|mlsl
  std::optional<std::string> seed;              ///< --seed: a whole number
  std::optional<std::string> runners_up;        ///< --top N rows in the table (default 8)
  std::optional<std::string> threads;           ///< --threads N of the catalog snap (default 1)
  OracleFlags oracle_flags;                     ///< --oracle, --method, --rtol
  /// --samples, --distribution (seed and threads: --seed, --threads): with scene ranges, the
  /// recommendation's probability of injury, or the sampling of --max-injury-probability.
  UncertaintyFlags uncertainty;
  /// --max-injury-probability P: with ranges and --samples, the thinnest covering whose
  /// probability of failing the criterion is <= P (FindProbabilityDesign).
  std::optional<std::string> max_injury_probability;
  bool json = false;
  /// --report FILE.html|FILE.pdf and the sign-off flags (report_option.hpp): the report,
  /// written after a run that succeeded.
  ReportFlags report;
  /// Not typed: the command line and input files for the JSON's provenance, set by RunCli.
  std::optional<RunContext> run;
  /// --body-region, --body-area, --contact, --contact-area: design for ISO/TS 15066 body
  /// regions (optim::DesignForBodyRegions) instead of the head alone.
  BodyRegionFlags body;
  /// --csv FILE: the candidate table as CSV (every candidate, SI units in the header).
  std::optional<std::string> csv;
  /// --plot FILE.png|FILE.svg: the design map (optim::DesignMap, report::DesignMapChart); the
  /// head's design only (not with --body-region or scene ranges).
  std::optional<std::string> plot_file;
};

/// Registers the options of the `optimize` subcommand `sub` (made by RunCli with its name and
/// summary), storing what is typed into `options`, which must outlive the parse.
void SetupOptimize(CLI::App* sub, OptimizeOptions& options);

/// `optimize --body-region ... --speed V` (optimize_body_region.cpp): the covering that lets
/// the robot reach V for every target. `head` is optimize's resolved request (the robot, the
/// head, the candidates, the rule's flags), `inputs` what the scene file adds to the report,
/// `warnings` its input warnings. Returns the exit code.
int RunBodyRegionOptimize(const OptimizeOptions& options, const optim::DesignRequest& head, const ResultInputs& inputs,
                          const std::vector<std::string>& warnings, const BodyRegionPlan& regions, std::ostream& out,
                          std::ostream& err);

/// Runs the subcommand; returns the exit code (0, 1 or 2).
int RunOptimize(const OptimizeOptions& options, std::ostream& out, std::ostream& err);

}  // namespace covopt::cli
