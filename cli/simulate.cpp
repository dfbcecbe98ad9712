#include "simulate.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fmt/ostream.h>

#include "covopt/core/exact.hpp"
#include "covopt/core/solve.hpp"
#include "covopt/core/impact_model.hpp"
#include "covopt/materials/catalog.hpp"
#include "covopt/optim/input_warnings.hpp"
#include "covopt/optim/robust_design.hpp"
#include "covopt/report/robust_json.hpp"
#include "body_region_commands.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "quantity.hpp"
#include "report_option.hpp"
#include "scene_fields.hpp"
#include "scene_file.hpp"

namespace covopt::cli {
namespace {

std::string_view TypeName(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::kMass: return "MASS";
    case QuantityKind::kLength: return "LENGTH";
    case QuantityKind::kSpeed: return "SPEED";
    case QuantityKind::kModulus: return "MODULUS";
    case QuantityKind::kDensity: return "DENSITY";
    case QuantityKind::kDimensionless: return "RATIO";
    case QuantityKind::kEnergyDensity: return "ENERGY_DENSITY";
    case QuantityKind::kTime: return "TIME";
    case QuantityKind::kAcceleration: return "ACCELERATION";
    case QuantityKind::kDampingCoefficient: return "DAMPING";
    case QuantityKind::kStiffness: return "STIFFNESS";
    case QuantityKind::kViscousDamping: return "DAMPING";
    case QuantityKind::kArea: return "AREA";
  }
  return "VALUE";
}

constexpr std::string_view kFooter = R"(Values take a unit: 10kg, 2m/s, 15mm, "15 mm", 27.6MPa, 6.5GPa, 0.3.
A bare number is SI, and must be plausible: --robot-radius 40 would be 40 m
and is refused (write 40mm, or 40m if you mean it). Units: mass kg, g, t
('fixed' for an immovable body); length m, cm, mm, um ('flat' for the robot
radius); speed m/s, mm/s, cm/s, km/h; modulus and stress Pa, kPa, MPa, GPa,
N/m2, N/mm2; energy density J/m2, J/cm2, kJ/m2; time s, ms; acceleration m/s2;
contact damping s/m; stiffness N/m, kN/m; viscous damping N*s/m, Ns/m; Poisson
ratios, tolerances and the safety factor are plain numbers. Unset values come from --scene, else the
paper's scene (limits 1 MPa and 2.52 J/cm2, safety factor 1).
--material NAME takes the covering's E and ν from the catalog (built-in, plus
--catalog files); it overrides --scene and excludes --covering-modulus/-poisson.

Exit codes: 0 done; 1 the computation failed or an output could not be
written (e.g. gnuplot missing); 2 bad input.)";

}  // namespace

std::string IntegratorNames() {
  std::string names;
  for (const ComputationMethod method : TimeIntegrationMethods()) {
    if (!names.empty()) names += ", ";
    names += ToString(method);
  }
  return names;
}

namespace {

/// Sets the covering's E and ν from a catalog entry: --material NAME, else the scene file's
/// covering.material (after the file's values, before the flags, which may not set E or ν
/// too).
void ApplyMaterial(const SimulateOptions& options, const SceneFileExtras& extras,
                   SimulationPlan& plan) {
  const bool from_flag = options.material.has_value();
  const std::string& name = from_flag ? *options.material : *extras.covering_material;
  const std::string chosen =
      from_flag ? fmt::format("--material '{}'", name)
                : fmt::format("covering.material '{}' ({})", name, extras.covering_material_where);
  for (const auto& [field, flag] : {std::pair{"covering.modulus", "--covering-modulus"},
                                    std::pair{"covering.poisson", "--covering-poisson"}}) {
    if (options.scene_values.count(field) != 0) {
      throw InputError(fmt::format("{} sets the covering's modulus and Poisson ratio; give "
                                   "either {} or {}, not both",
                                   chosen, from_flag ? "--material" : "covering.material", flag));
    }
  }
  const materials::Catalog catalog = LoadCatalog(options.catalog);
  const materials::Material* material = catalog.Find(name);
  if (material == nullptr) {
    throw InputError(from_flag ? "--material: " + NoSuchMaterial(catalog, name)
                               : fmt::format("{}: covering.material: {}",
                                             extras.covering_material_where,
                                             NoSuchMaterial(catalog, name)));
  }
  plan.scene.covering.youngs_modulus_Pa = material->youngs_modulus_Pa;
  plan.scene.covering.poisson_ratio = materials::PoissonRatioOrDefault(*material);
  plan.covering_material_source =
      from_flag ? fmt::format("--material '{}'", material->name)
                : fmt::format("covering.material '{}' ({})", material->name,
                              extras.covering_material_where);
  plan.sources["covering.modulus"] = plan.covering_material_source;
  plan.sources["covering.poisson"] = plan.covering_material_source;
  plan.covering_material = *material;
}

/// The injury limits and the safety factor of the scene file's [limits] (the flags'
/// are ApplySceneFlags's).
void ApplyLimits(const SceneFileExtras& extras, SimulationPlan& plan) {
  if (extras.laceration_limit_Pa) {
    plan.limits.laceration_tensile_stress_Pa = *extras.laceration_limit_Pa;
  }
  if (extras.contusion_limit_J_per_m2) {
    plan.limits.contusion_energy_density_J_per_m2 = *extras.contusion_limit_J_per_m2;
  }
  if (extras.safety_factor) plan.safety_factor = *extras.safety_factor;
}

/// The flags' scene inputs (the limits, the scene fields not given as ranges, the
/// thresholds) applied by the library's one resolution (scene_file::ApplySceneInputs), its
/// messages naming the flags (scene_file::SceneInputSpellings); their sources noted.
void ApplySceneFlags(const SimulateOptions& options, SimulationPlan& plan) {
  std::vector<scene_file::SceneInput> inputs;
  const auto add = [&](std::string field, std::string_view flag, const std::string& typed) {
    plan.sources[field] = fmt::format("{} '{}'", flag, typed);
    inputs.push_back({std::move(field), typed, ""});
  };
  for (const LimitField& field : LimitFields()) {
    const std::optional<std::string>& typed = field.key == "laceration"  ? options.laceration_limit
                                              : field.key == "contusion" ? options.contusion_limit
                                                                         : options.safety_factor;
    if (typed) add(field.dotted_name(), field.flag, *typed);
  }
  for (const SceneField& field : SceneFields()) {
    const auto typed = options.scene_values.find(field.dotted_name());
    if (typed != options.scene_values.end() && !IsRangeText(typed->second)) add(typed->first, field.flag, typed->second);
  }
  if (options.thresholds) add("model.thresholds", "--thresholds", *options.thresholds);
  if (options.head_area) add("head.area", "--head-area", *options.head_area);
  scene_file::ResolvedScene resolved{plan.scene, plan.limits, plan.safety_factor, nullptr};
  ApplySceneFlagInputs(inputs, resolved);
  plan.scene = resolved.scene;
  plan.limits = resolved.limits;
  plan.safety_factor = resolved.safety_factor;
}

}  // namespace

void AddSceneOptions(CLI::App& sub_app, SimulateOptions& options) {
  CLI::App* sub = &sub_app;
  sub->add_option("--scene", options.scene_file,
                  "TOML scene file; flags override it (see cli/examples/paper_scene.toml)")
      ->type_name("FILE.toml");

  const Scene defaults;
  for (const SceneField& field : SceneFields()) {
    Scene scene = defaults;
    const std::string key = field.dotted_name();
    sub->add_option_function<std::string>(
           std::string(field.flag),
           [&options, key](const std::string& value) { options.scene_values[key] = value; },
           fmt::format("{} (default {})", field.help,
                       FormatQuantity(field.field(scene), field.spec.kind)))
        ->type_name(std::string(TypeName(field.spec.kind)))
        ->group("Scene");
  }
  sub->add_option("--thresholds", options.thresholds,
                  "phase thresholds: cumulative (default) or literal (the paper's text)")
      ->check(CLI::IsMember({"cumulative", "literal"}))
      ->group("Scene");
  sub->add_option("--head-area", options.head_area,
                  "the struck area of the head, whose lowest published fracture force the peak force is judged against: " +
                      HeadAreaChoices() + " (default frontal, the forehead; docs/model.md §7.1)")
      ->type_name("AREA")
      ->group("Scene");
  sub->add_option("--material", options.material,
                  "covering modulus and Poisson ratio from the material catalog (see 'covopt "
                  "materials list'); ν unknown there: 0.25, with a warning")
      ->type_name("NAME")
      ->group("Scene");
  AddCatalogOptions(*sub, options.catalog);
  for (const LimitField& field : LimitFields()) {
    if (field.key == "safety_factor") continue;  // simulate's own; sweep shows the ratios
    const InjuryLimits defaults;
    const double value = field.key == "laceration" ? defaults.laceration_tensile_stress_Pa
                                                   : defaults.contusion_energy_density_J_per_m2;
    sub->add_option(std::string(field.flag),
                    field.key == "laceration" ? options.laceration_limit : options.contusion_limit,
                    fmt::format("{} (default {})", field.help,
                                FormatQuantity(value, field.spec.kind)))
        ->type_name(field.key == "laceration" ? "STRESS" : "ENERGY_DENSITY")
        ->group("Limits");
  }
}

void SetupSimulate(CLI::App* sub, SimulateOptions& options) {
  sub->footer(std::string(kFooter));
  AddSceneOptions(*sub, options);
  sub->add_option("--safety-factor", options.safety_factor,
                  "judge each verdict against its limit divided by this factor, 1-100 "
                  "(default 1)")
      ->type_name("RATIO")
      ->group("Limits");

  sub->add_option("--method", options.method,
                  "auto (default: the exact energy balance where the scene admits it, else "
                  "the time path), exact, cvode (CVODE, see --cvode-method), or one "
                  "integrator: " + IntegratorNames() + fmt::format(". --history/--plot, "
                  "--braking and a neck need a time path: {} unless given",
                  ToString(TimeIntegrationOptions{}.method)))
      ->type_name("METHOD")
      ->group("Computation");
  sub->add_option("--cvode-method", options.cvode_method,
                  "CVODE family: adams (default) or bdf")
      ->check(CLI::IsMember({"adams", "bdf"}))
      ->group("Computation");
  sub->add_option("--rtol", options.rtol,
                  fmt::format("time-path relative tolerance (default {:g})",
                              TimeIntegrationOptions{}.relative_tolerance))
      ->type_name("RATIO")
      ->group("Computation");
  sub->add_option("--atol", options.atol,
                  "time-path absolute tolerance, scaled per component (default: rtol)")
      ->type_name("RATIO")
      ->group("Computation");

  sub->add_option("--max-steps", options.max_steps,
                  fmt::format("time-path limit on internal steps; reaching it fails the run "
                              "(default {})",
                              TimeIntegrationOptions{}.max_steps))
      ->type_name("N")
      ->group("Computation");

  AddRobotModelOptions(*sub, options.robot_model, true, "Robot model (instead of --robot-mass)");
  AddBodyRegionOptions(*sub, options.body);
  options.accept_ranges = true;
  AddUncertaintyOptions(*sub, options.uncertainty, true);
  sub->add_flag("--sensitivities", options.sensitivities,
                "the elasticity d ln r / d ln x of each injury ratio and the compression ratio to every scene "
                "input (at the worst case with ranges); with --plot, a tornado chart")
      ->group("Uncertainty");
  sub->add_flag("--json", options.json, "print one JSON object (SI units) instead of the table")
      ->group("Output");
  sub->add_option("--history", options.history_file,
                  "write the time history as CSV (uses the time path)")
      ->type_name("FILE.csv")
      ->group("Output");
  sub->add_option("--plot", options.plot_file,
                  "draw force and stress against time with gnuplot (uses the time path)")
      ->type_name("FILE.png|FILE.svg")
      ->group("Output");
  AddReportOption(*sub, options.report_file);
}

namespace {

/// --method, --cvode-method, --rtol, --atol and --max-steps: the path (the library's
/// ChoosePath: exact where the scene has an energy integral, the time path for a braking robot,
/// a neck or a history, docs/model.md §10) and the time path's options.
void ResolveComputation(const SimulateOptions& options, SimulationPlan& plan) {
  SolveOptions& solve = plan.solve;
  solve.record_history = plan.history_file || plan.plot_file;
  std::optional<ComputationMethod> integrator;
  if (options.method && *options.method != "auto") {
    if (*options.method == "cvode") {
      solve.path = PathChoice::kTimePath;
    } else if (const auto named = ParseComputationMethod(*options.method);
               named && *named != ComputationMethod::kExact) {
      solve.path = PathChoice::kTimePath;
      integrator = named;
    } else if (*options.method == "exact") {
      solve.path = PathChoice::kExact;
      if (!plan.scene.has_energy_integral()) {
        throw InputError(
            "--method exact: the exact path needs an energy integral; a scene with braking or a "
            "neck has only the time path; use --method auto or a time integrator");
      }
      if (solve.record_history) {
        throw InputError(fmt::format(
            "--method exact computes no time history, which {} needs; drop --method exact "
            "(the default integrator runs then) or give a time-path method",
            plan.history_file ? "--history" : "--plot"));
      }
    } else {
      throw InputError(fmt::format("--method: expected exact, cvode or one of {}, or auto "
                                   "(the default) (got '{}')",
                                   IntegratorNames(), *options.method));
    }
  }
  plan.time_path = ChoosePath(plan.scene, solve) == PathChoice::kTimePath;
  if (!plan.time_path) {
    for (const auto& [flag, given] : {std::pair{"--cvode-method", options.cvode_method.has_value()},
                                      std::pair{"--rtol", options.rtol.has_value()},
                                      std::pair{"--atol", options.atol.has_value()},
                                      std::pair{"--max-steps", options.max_steps.has_value()}}) {
      if (given) {
        throw InputError(fmt::format(
            "{} applies to the time path only, and this scene takes the exact path; add "
            "--method cvode (or another integrator)",
            flag));
      }
    }
    return;
  }

  TimeIntegrationOptions& time = solve.time_path;
  if (integrator) {
    if (options.cvode_method) {
      throw InputError(fmt::format("--cvode-method applies with --method cvode, not with "
                                   "--method {}",
                                   *options.method));
    }
    time.method = *integrator;
  } else if (options.method && *options.method == "cvode") {
    time.method = ComputationMethod::kCvodeAdams;  // CVODE's default family here
  }
  if (options.cvode_method) {
    if (*options.cvode_method == "adams") {
      time.method = ComputationMethod::kCvodeAdams;
    } else if (*options.cvode_method == "bdf") {
      time.method = ComputationMethod::kCvodeBdf;
    } else {
      throw InputError(fmt::format("--cvode-method: expected 'adams' or 'bdf' (got '{}')",
                                   *options.cvode_method));
    }
  }
  // Each flag against the library's range (ValidateTimeIntegrationOptions), named in front.
  const auto check = [&time](std::string_view flag) {
    try {
      ValidateTimeIntegrationOptions(time);
    } catch (const std::invalid_argument& e) {
      throw InputError(fmt::format("{}: {}", flag, e.what()));
    }
  };
  const QuantitySpec& tolerance = quantity_specs::kTolerance;
  if (options.rtol) {
    time.relative_tolerance = ParseQuantity(*options.rtol, tolerance, "--rtol");
    check("--rtol");
  }
  if (options.atol) {
    time.absolute_tolerance = ParseQuantity(*options.atol, tolerance, "--atol");
    // The library reads 0 as "default: rtol", so an explicit 0 must not get through.
    if (!(time.absolute_tolerance > 0.0)) {
      throw InputError(fmt::format("--atol must be > 0 (got '{}')", *options.atol));
    }
    check("--atol");
  }
  if (options.max_steps) {
    time.max_steps = *options.max_steps;
    check("--max-steps");
  }
}

}  // namespace

SimulationPlan ResolveSimulation(const SimulateOptions& options) {
  SimulationPlan plan;

  // The scene: defaults, then the file, then the flags.
  SceneFileExtras extras;
  if (options.scene_file) {
    for (std::string& name : ApplySceneFile(*options.scene_file, plan.scene, &extras)) {
      plan.sources[std::move(name)] = *options.scene_file;
    }
    plan.ranges = extras.ranges;
  }
  if (options.material || extras.covering_material) {
    ApplyMaterial(options, extras, plan);
  } else if (options.catalog.given()) {
    throw InputError(fmt::format("{} applies only with --material NAME (or a scene file's "
                                 "covering.material)",
                                 options.catalog.files.empty() ? "--no-builtin" : "--catalog"));
  }
  ApplyLimits(extras, plan);
  for (const SceneField& field : SceneFields()) {
    const auto typed = options.scene_values.find(field.dotted_name());
    if (typed != options.scene_values.end()) {
      // A flag replaces the scene file's value or range.
      std::erase_if(plan.ranges, [&](const SceneRange& r) { return r.field == field.dotted_name(); });
      if (IsRangeText(typed->second)) {
        plan.ranges.push_back(AsInputError([&] { return scene_file::ParseSceneRange(typed->second, field, field.flag); }));
        plan.sources[field.dotted_name()] = fmt::format("{} '{}'", field.flag, typed->second);
      }
    }
  }
  ApplySceneFlags(options, plan);
  if (!plan.ranges.empty() && !options.accept_ranges) {
    throw InputError(fmt::format("{} '{}': a range (an uncertain input) is taken by simulate, optimize and speed-limit "
                                 "only; this command needs one value",
                                 plan.ranges.front().source, plan.ranges.front().text));
  }
  if (options.robot_model.given()) {  // --urdf ...: robot.mass from the robot model
    RobotModelMass mass =
        ResolveRobotModelMass(options.robot_model, options.scene_values.count(kRobotMassField) != 0);
    plan.scene.robot.mass_kg = mass.mass_kg;
    std::erase_if(plan.ranges, [](const SceneRange& r) { return r.field == kRobotMassField; });
    plan.sources[kRobotMassField] = mass.source;
    plan.robot_model_notes = std::move(mass.notes);
  }
  // Only SetupSimulate fills scene_values, with known names; a caller building the options
  // by hand gets told.
  const auto fields = SceneFields();
  for (const auto& typed : options.scene_values) {
    if (std::none_of(fields.begin(), fields.end(),
                     [&](const SceneField& f) { return f.dotted_name() == typed.first; })) {
      throw InputError(
          fmt::format("unknown scene field '{}' (got '{}')", typed.first, typed.second));
    }
  }
  SetNominalValues(plan.scene, plan.ranges);

  // Outputs.
  plan.json = options.json;
  if (options.history_file) {
    if (options.history_file->empty()) throw InputError("--history: empty file name");
    plan.history_file = options.history_file;
  }
  if (options.plot_file) {
    const auto format = PlotFormatFor(*options.plot_file);
    if (!format) {
      throw InputError(fmt::format("--plot: cannot tell the format of '{}'; name the file "
                                   "*.png or *.svg",
                                   *options.plot_file));
    }
    plan.plot_file = options.plot_file;
    plan.plot_format = *format;
  }

  ResolveComputation(options, plan);
  return plan;
}

void Judge(report::SimulationReport& report, const SimulationPlan& plan) {
  report.assessment =
      report::JudgeInjuries(report.result.peaks, plan.limits, plan.safety_factor, report.scene.head.area);
  report.safety_factor = plan.safety_factor;
  const optim::CoveringCrushCheck crush = CrushCheckOf(plan);
  if (crush.compressive_strength_Pa > 0.0) {
    report.crush = optim::CrushVerdict(report.result.peaks, crush.compressive_strength_Pa, plan.safety_factor);
  }
  // The verdict judges the skin and (with a strength) crushing; full compression is reported.
  report.scope = optim::HeadVerdictScope(
      optim::DesignRule{plan.safety_factor, optim::DesignCriterion::kPaper, false, !crush.notes.empty()});
}

optim::CoveringCrushCheck CrushCheckOf(const SimulationPlan& plan) {
  const bool given = std::any_of(plan.sources.begin(), plan.sources.end(),
                                 [](const auto& source) { return source.first.rfind("covering.", 0) == 0; });
  return optim::CrushCheckFor(plan.scene, plan.covering_material ? &*plan.covering_material : nullptr, given);
}

std::vector<std::string> InputWarnings(const SimulationPlan& plan) {
  std::vector<std::string> warnings = plan.robot_model_notes;
  const auto source_of = [&plan](std::string_view field) -> std::optional<std::string> {
    if (field == "covering.material") return plan.covering_material_source;
    const auto source = plan.sources.find(field);
    if (source == plan.sources.end()) return std::nullopt;
    return source->second;
  };
  for (std::string& warning :
       optim::SceneInputWarnings(plan.scene, plan.limits, plan.safety_factor,
                                 plan.covering_material ? &*plan.covering_material : nullptr, source_of)) {
    warnings.push_back(std::move(warning));
  }
  return warnings;
}

std::string AttributeError(const std::string& message, const SimulationPlan& plan) {
  const auto is_name_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.';
  };
  std::vector<std::pair<std::size_t, std::string>> origins;  // by position in the message
  for (const auto& [name, source] : plan.sources) {
    // The field name as a whole word of the message.
    for (std::size_t at = message.find(name); at != std::string::npos;
         at = message.find(name, at + 1)) {
      const std::size_t end = at + name.size();
      if ((at == 0 || !is_name_char(message[at - 1])) &&
          (end == message.size() || !is_name_char(message[end]) ||
           (message[end] == '.' && (end + 1 == message.size() || message[end + 1] == ' ')))) {
        origins.emplace_back(at, fmt::format("{} from {}", name, source));
        break;
      }
    }
  }
  if (origins.empty()) return message;
  std::sort(origins.begin(), origins.end());
  std::string attributed = message + " (";
  for (std::size_t i = 0; i < origins.size(); ++i) {
    if (i > 0) attributed += "; ";
    attributed += origins[i].second;
  }
  return attributed + ")";
}

namespace {

/// The tables of an uncertain simulation: the ranges and the worst case (with ranges), the
/// impact there, the probability of injury and the elasticities (when computed).
void PrintUncertainSimulation(std::ostream& out, const SimulationPlan& plan, const SimulationReport& report,
                              const optim::UncertaintyBox* box, const optim::WorstCase& worst,
                              const optim::InjuryProbability* probability,
                              const optim::ElasticityTable* elasticities) {
  if (box) {
    fmt::print(out, "Scene ranges: {} inputs; the impact below is the worst case over the box\n", box->size());
    for (const SceneRange& range : plan.ranges) {
      fmt::print(out, "  {:<20} {} .. {}  (from {})\n", range.name,
                 FormatQuantity(range.low, FindSceneField(range.name)->spec.kind),
                 FormatQuantity(range.high, FindSceneField(range.name)->spec.kind), range.source);
    }
    PrintWorstCase(out, *box, worst);
    PrintTimePathUse(out, *box, worst.time_path);
    out << '\n';
  }
  PrintTable(out, report);
  if (probability) {
    out << '\n';
    PrintInjuryProbability(out, *probability);
    if (box) PrintTimePathUse(out, *box, probability->time_path);
  }
  if (elasticities) {
    out << '\n';
    PrintElasticities(out, *elasticities);
  }
}

/// simulate with scene ranges, --samples or --sensitivities (docs/model.md §11): the worst
/// case over the box reported as an impact at that scene, the probability of injury and the
/// elasticities. Everything runs on the exact path.
int RunUncertainSimulate(const SimulateOptions& options, const SimulationPlan& plan,
                         const std::optional<std::string>& tornado_file, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "simulate");
  std::optional<optim::UncertaintyBox> box;
  std::optional<optim::InjuryProbabilityOptions> sampling;
  try {
    sampling = ResolveSampling(options.uncertainty, plan.ranges);
    if (!plan.ranges.empty()) {
      box.emplace(MakeUncertaintyBox(plan.scene, ResolveUncertainInputs(plan.ranges, options.uncertainty.distributions),
                                     plan.ranges));
      // A braking robot takes the time path by itself (screened by the exact path's bound,
      // docs/model.md §11); a time path asked for by a flag is refused.
      if (plan.time_path && (options.method || plan.history_file || plan.plot_file)) {
        throw InputError(fmt::format("{} with scene ranges: the worst case and the probability are computed on the "
                                     "exact path (the time path for a braking robot); drop it",
                                     plan.history_file ? "--history" : plan.plot_file ? "--plot" : "--method"));
      }
    } else if (plan.time_path && options.sensitivities && (options.method || plan.history_file)) {
      throw InputError(fmt::format("--sensitivities are computed on the exact path; {} does not apply",
                                   plan.history_file ? "--history" : "--method"));
    }
  } catch (const InputError& e) {
    return errors.BadInput(e.what());
  }

  SimulationReport report;
  optim::WorstCase worst;
  std::optional<optim::InjuryProbability> probability;
  std::optional<optim::ElasticityTable> elasticities;
  try {
    report.scene = plan.scene;
    if (box) {
      optim::WorstCaseOptions worst_options;
      worst_options.safety_factor = plan.safety_factor;
      worst_options.limits = plan.limits;
      // The material's strength: a crushed covering fails the worst case (docs/model.md §12).
      worst_options.compressive_strength_Pa = CrushCheckOf(plan).compressive_strength_Pa;
      worst = optim::FindWorstCase(*box, worst_options);
      report.scene = worst.scene;
    }
    if (plan.covering_material) {
      report.covering_material = plan.covering_material->name;
      report.covering_poisson_assumed = !plan.covering_material->poisson_ratio.has_value();
    }
    const ImpactModel model = ImpactModel::FromScene(report.scene);
    report.result = report.scene.robot_brakes() ? Solve(model, plan.solve) : SolveExact(model);
    if (sampling && box) {
      SamplingProgressBar bar(err, "sampling");
      sampling->safety_factor = plan.safety_factor;
      sampling->limits = plan.limits;
      sampling->compressive_strength_Pa = CrushCheckOf(plan).compressive_strength_Pa;
      sampling->progress = bar.Callback();
      probability = optim::EstimateInjuryProbability(*box, *sampling);
    }
    if (options.sensitivities) {
      optim::ElasticityOptions elasticity_options;
      elasticity_options.limits = plan.limits;
      elasticities = optim::ComputeElasticities(report.scene, elasticity_options);
    }
  } catch (const InputError& e) {
    return errors.BadInput(e.what());
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(AttributeError(e.what(), plan));
  } catch (const std::runtime_error& e) {  // a braking robot's time path failed at the scene
    return errors.Failed(e.what());
  }
  if (!report.result.ok()) {
    return errors.Failed(fmt::format("the computation failed: {} ({})", ToString(report.result.status),
                                     report.result.message));
  }
  Judge(report, plan);
  report.input_warnings = InputWarnings(plan);
  try {
    if (tornado_file) {
      if (!FindOnPath("gnuplot")) return errors.Failed(kGnuplotMissing);
      PlotTornado(*tornado_file, *elasticities, PlotFormatFor(*tornado_file) == PlotFormat::kSvg);
    }
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }

  if (plan.json || options.report_file) {
    try {
      PrintAndReport(out, plan.json,
                     report::UncertainSimulationJson(report, box ? &*box : nullptr, box ? &worst : nullptr,
                                                     probability ? &*probability : nullptr,
                                                     elasticities ? &*elasticities : nullptr),
                     options.run, options.report_file, report::ReportKind::kSimulate, nullptr);
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (!plan.json) {
    PrintUncertainSimulation(out, plan, report, box ? &*box : nullptr, worst, probability ? &*probability : nullptr,
                             elasticities ? &*elasticities : nullptr);
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace

int RunSimulate(const SimulateOptions& options, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "simulate");
  if (options.body.any()) {  // ISO/TS 15066 body regions (body_region_commands.hpp)
    return RunWithBodyRegions(options.body, errors, [&](const BodyRegionPlan& regions) {
      return RunBodyRegionSimulate(options, regions, out, err);
    });
  }

  SimulationPlan plan;
  std::optional<ImpactModel> model;
  SimulationReport report;
  // With --sensitivities, --plot draws the tornado chart (no time path for it).
  std::optional<std::string> tornado_file;
  try {
    if (options.sensitivities && options.plot_file) {
      if (!PlotFormatFor(*options.plot_file)) {
        throw InputError(fmt::format("--plot: cannot tell the format of '{}'; name the file *.png or *.svg",
                                     *options.plot_file));
      }
      SimulateOptions without_plot = options;
      without_plot.plot_file.reset();
      tornado_file = options.plot_file;
      plan = ResolveSimulation(without_plot);
    } else {
      plan = ResolveSimulation(options);
    }
  } catch (const InputError& e) {
    return errors.BadInput(e.what());
  }
  if (!plan.ranges.empty() || options.sensitivities || options.uncertainty.samples ||
      !options.uncertainty.distributions.empty() || options.uncertainty.seed || options.uncertainty.threads) {
    if ((options.uncertainty.seed || options.uncertainty.threads) && !options.uncertainty.samples) {
      return errors.BadInput(fmt::format("{} applies with --samples N", options.uncertainty.seed ? "--seed" : "--threads"));
    }
    return RunUncertainSimulate(options, plan, tornado_file, out, err);
  }
  try {
    model.emplace(ImpactModel::FromScene(plan.scene));
  } catch (const std::invalid_argument& e) {  // the library's range checks
    return errors.BadInput(AttributeError(e.what(), plan));
  }
  try {
    report.scene = plan.scene;
    if (plan.covering_material) {
      report.covering_material = plan.covering_material->name;
      report.covering_poisson_assumed = !plan.covering_material->poisson_ratio.has_value();
    }
    if (plan.time_path) report.time_options = plan.solve.time_path;
    report.result = Solve(*model, plan.solve);  // smooth histories: ~400 samples over the contact
  } catch (const std::invalid_argument& e) {  // the integrator's option checks
    return errors.BadInput(e.what());
  }

  const ImpactResult& result = report.result;
  if (!result.ok()) {
    return errors.Failed(fmt::format("the computation failed: {} ({}, code {}){}{}", ToString(result.status),
                              ToString(result.method), result.raw_code,
                              result.message.empty() ? "" : ": ", result.message));
  }
  Judge(report, plan);  // the chart draws the derated limits
  report.input_warnings = InputWarnings(plan);

  try {
    // Check for gnuplot before writing anything, so that a missing tool leaves no files.
    if ((plan.plot_file || options.report_file) && !FindOnPath("gnuplot")) return errors.Failed(kGnuplotMissing);
    if (plan.history_file) WriteFileAtomically(*plan.history_file, HistoryCsv(*model, result.history));
    if (plan.plot_file) PlotHistory(*plan.plot_file, report);
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }

  if (plan.json || options.report_file) {
    try {  // the object covopt.simulate() returns
      PrintAndReport(out, plan.json, report::SimulationJson(report), options.run, options.report_file,
                     report::ReportKind::kSimulate, [&] { return std::vector{report::HistoryChart(report)}; });
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (!plan.json) {
    PrintTable(out, report);
    if (plan.history_file || plan.plot_file) {
      fmt::print(out, "Wrote      {}{}{}\n", plan.history_file.value_or(""),
                 plan.history_file && plan.plot_file ? ", " : "", plan.plot_file.value_or(""));
    }
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace covopt::cli
