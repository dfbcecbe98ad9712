#pragma once
/// @file simulation_plan.hpp
/// The scene every scene-taking command reads as `covopt simulate` does (simulate.hpp): its
/// options as typed (SimulateOptions), their registration (AddSceneOptions) and what they
/// resolve to (SimulationPlan, ResolveSimulation), the judging of an impact against the plan's
/// limits and the input warnings. Shared by the commands; no command's own code.
///
/// The scene is Scene{} (the paper's), then the --scene file, then the flags.

#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "covopt/core/impact_result.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/core/solve.hpp"
#include "covopt/optim/speed_limit.hpp"
#include "covopt/materials/material.hpp"
#include "covopt/scene_file/integrators.hpp"
#include "body_region_options.hpp"
#include "catalog_options.hpp"
#include "plot.hpp"
#include "report_option.hpp"
#include "robot_model_options.hpp"
#include "run_context.hpp"
#include "scene_file.hpp"
#include "uncertainty_options.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The scene's named choices as typed: --thresholds, --head-area and --covering-law.
struct SceneChoices {
  /// --thresholds cumulative|literal.
  std::optional<std::string> thresholds;
  /// --head-area frontal|temporo-parietal|nasal|... (docs/model.md §7.1).
  std::optional<std::string> head_area;
  /// --covering-law auto|foam|hertz: the law that describes the covering (auto: the foam law
  /// where the material has a measured curve, else Hertz).
  std::optional<std::string> covering_law;
};

/// The options of `covopt simulate`, as typed. Values are read (units, ranges) by
/// ResolveSimulation, so that every message can name its flag.
struct SimulateOptions {
  /// --scene FILE.toml: read before the flags, which override it.
  std::optional<std::string> scene_file;
  /// Scene flags as typed, by field name ("robot.mass" -> "10kg"); see SceneFields().
  std::map<std::string, std::string, std::less<>> scene_values;
  /// --thresholds, --head-area, --covering-law.
  SceneChoices choices;
  /// --material NAME: the covering's modulus and Poisson ratio from the material catalog
  /// (ν unknown there: 0.25, with a warning). Overrides the scene file; combined with
  /// --covering-modulus or --covering-poisson it is bad input.
  std::optional<std::string> material;
  /// --catalog FILE (repeatable), --no-builtin: the catalog --material (or the scene
  /// file's covering.material) looks in.
  CatalogOptions catalog;
  /// --laceration-limit (a stress, e.g. "1MPa") and --contusion-limit (an energy density,
  /// e.g. "2.52J/cm2"), as typed. Default: the scene file's [limits], else InjuryLimits{}.
  std::optional<std::string> laceration_limit;
  std::optional<std::string> contusion_limit;
  /// --safety-factor (simulate only), in [1, 100]: each verdict is judged against its limit
  /// divided by it. Default: the scene file's limits.safety_factor, else 1.
  std::optional<std::string> safety_factor;
  /// --keep-travel (simulate, speed-limit, robot, audit, sweep): the covering's travel rule
  /// ("full-compression" / "within-curve") as a limit. Default: reported only.
  bool keep_travel = false;
  /// --method auto|exact|cvode|<integrator> (cvode-adams, arkode-erk54, ...: see
  /// TimeIntegrationMethods()). Default auto: exact where the scene has an energy integral
  /// (conservative or damped), else the library's default integrator
  /// (TimeIntegrationOptions::method), which also runs when --history or --plot is given.
  /// exact on a braking or neck scene is bad input.
  std::optional<std::string> method;
  /// --cvode-method adams|bdf. Default: adams.
  std::optional<std::string> cvode_method;
  /// --rtol, --atol: CVODE's relative and absolute tolerances [-]. Default: the library's.
  std::optional<std::string> rtol;
  std::optional<std::string> atol;
  /// --max-steps N: CVODE's limit on internal steps in total. Default: the library's.
  std::optional<long> max_steps;
  /// --json: print one JSON object instead of the table.
  bool json = false;
  /// --report FILE.html|FILE.pdf and the sign-off flags (report_option.hpp): the report,
  /// written after a run that succeeded.
  ReportFlags report;
  /// Not typed: the command line and input files for the JSON's provenance, set by RunCli;
  /// none for the head's run inside `--body-region head` (its object is nested).
  std::optional<RunContext> run;
  /// --urdf/--base/--tip/--joints/--point/--direction: robot.mass is the robot model's
  /// reflected mass (excludes --robot-mass). Filled by subcommands that add the group.
  RobotModelOptions robot_model;
  /// --history FILE.csv: write the time history (needs the time path).
  std::optional<std::string> history_file;
  /// --plot FILE.png|FILE.svg: draw force and stress against time with gnuplot (with
  /// --sensitivities: the tornado chart of the elasticities instead).
  std::optional<std::string> plot_file;
  /// --samples, --seed, --threads, --distribution: Monte Carlo over the scene's ranges.
  UncertaintyFlags uncertainty;
  /// --sensitivities: the elasticity of each ratio to every scene input (docs/model.md §11).
  bool sensitivities = false;
  /// --body-region, --body-area, --contact, --contact-area: judge ISO/TS 15066 body regions
  /// (body_region_options.hpp). Filled by the subcommands that add the group.
  BodyRegionFlags body;
  /// Not typed: set by the subcommands that take scene ranges (simulate, speed-limit); for
  /// the others ResolveSimulation refuses a range with one line.
  bool accept_ranges = false;
};

/// What the options resolve to: a scene and how to compute and report it.
struct SimulationPlan {
  Scene scene;
  /// Where each non-default scene field came from, by field name:
  /// "robot.mass" -> "--robot-mass '10kg'" or "scene.toml".
  std::map<std::string, std::string, std::less<>> sources;
  /// The catalog entry the covering's E and ν come from (--material, or the scene file's
  /// covering.material), if any, and how messages name where it was chosen:
  /// "--material 'NAME'" or "covering.material 'NAME' (scene.toml:12:12)".
  std::optional<materials::Material> covering_material;
  std::string covering_material_source;
  /// The injury limits: InjuryLimits{} (1 MPa, 2.52 J/cm²), then the scene file's [limits],
  /// then --laceration-limit/--contusion-limit.
  InjuryLimits limits;
  /// The limits are divided by this [-], in [1, 100] (scene file's limits.safety_factor,
  /// then --safety-factor). Ratios stay value/limit; a verdict is safe when
  /// safety_factor * ratio <= 1.
  double safety_factor = 1.0;
  /// --keep-travel: the covering's travel rule counts as a limit (SpeedLimitOptions::keep_travel).
  bool keep_travel = false;
  /// How the impact is computed (--method, --rtol, ...; --history and --plot record a history).
  SolveOptions solve;
  /// The time path runs (ChoosePath(scene, solve)); false for the exact path.
  bool time_path = false;
  std::optional<std::string> history_file;
  std::optional<std::string> plot_file;
  PlotFormat plot_format = PlotFormat::kPng;
  bool json = false;
  /// Scene inputs given as ranges LO..HI (flags, or the scene file's strings), each field's
  /// value in `scene` set to the middle of its range.
  std::vector<SceneRange> ranges;
  /// With --urdf: where robot.mass came from and the robot model's warnings, shown with
  /// the input warnings.
  std::vector<std::string> robot_model_notes;
  /// What the inputs add to the report: the scene file's [report] table.
  ResultInputs inputs;
};

/// The scene group ("Scene" in --help), registered here once: --scene FILE, every scene field's
/// flag (--robot-mass ...; not the covering's unless `with_covering`: optimize designs it), each
/// stored by its dotted name in `scene_values`, and the choices (--thresholds, --head-area,
/// --covering-law). The targets must outlive the parse.
void AddSceneFieldOptions(CLI::App& command, std::optional<std::string>& scene_file,
                          std::map<std::string, std::string, std::less<>>& scene_values, SceneChoices& choices,
                          bool with_covering = true);

/// Adds the scene options every scene-taking subcommand shares to `sub`: --scene, the scene
/// fields (--robot-mass ...), --thresholds, --material, --catalog/--no-builtin,
/// --laceration-limit and --contusion-limit. They fill `options` (which must outlive the
/// parse); ResolveSimulation reads them.
void AddSceneOptions(CLI::App& sub, SimulateOptions& options);

/// "cvode-adams, cvode-bdf, arkode-erk32, ...": every time-integration method's name (the
/// library's list, as Python names them).
using scene_file::IntegratorNames;

/// Reads every value and checks how the options combine (the scene's ranges are left to the
/// library; limits and the safety factor are checked here). A scene input given as LO..HI
/// goes to SimulationPlan::ranges when options.accept_ranges, else is refused.
/// @throws InputError naming the flag or the scene-file field.
SimulationPlan ResolveSimulation(const SimulateOptions& options);

/// Judges report.result's peaks against the plan's limits (each ratio is value/limit, and a
/// verdict is safe when plan.safety_factor * ratio <= 1), against the covering material's
/// compressive strength when it is known (report.crush), and says what the verdict covers
/// (report.scope).
void Judge(report::SimulationReport& report, const SimulationPlan& plan);

/// Warnings about the input itself, beside the library's about the result: values the
/// user set that the model ignores (a covering modulus or material without a covering),
/// a catalog material without a Poisson ratio ("ν unknown, 0.25 assumed"), and a safety
/// factor above 1 (the verdicts are then judged against the derated limits, which it
/// states).
std::vector<std::string> InputWarnings(const SimulationPlan& plan);

/// The crush check a limit search can make on a plan's covering (optim::CrushCheckFor).
optim::CoveringCrushCheck CrushCheckOf(const SimulationPlan& plan);

/// Adds to a library message that names scene fields ("robot.mass must be ...") where the
/// user set them: "... (robot.mass from --robot-mass '-10kg')".
std::string AttributeError(const std::string& message, const SimulationPlan& plan);


}  // namespace covopt::cli
