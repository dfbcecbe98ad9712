#include "simulation_plan.hpp"

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
#include "covopt/optim/verdicts.hpp"
#include "covopt/report/robust_json.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "quantity.hpp"
#include "scene_fields.hpp"
#include "rule_options.hpp"
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
  const CoveringSpec covering = materials::CoveringOf(*material, plan.scene.covering.thickness_m);
  plan.scene.covering.youngs_modulus_Pa = covering.youngs_modulus_Pa;
  plan.scene.covering.poisson_ratio = covering.poisson_ratio;
  plan.scene.covering.compressive_curve = covering.compressive_curve;
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
  if (options.choices.thresholds) add("model.thresholds", "--thresholds", *options.choices.thresholds);
  if (options.choices.head_area) add("head.area", "--head-area", *options.choices.head_area);
  if (options.choices.covering_law) add("covering.law", "--covering-law", *options.choices.covering_law);
  scene_file::ResolvedScene resolved{plan.scene, plan.limits, plan.safety_factor, nullptr};
  ApplySceneFlagInputs(inputs, resolved);
  plan.scene = resolved.scene;
  plan.limits = resolved.limits;
  plan.safety_factor = resolved.safety_factor;
}

}  // namespace

void AddSceneFieldOptions(CLI::App& command, std::optional<std::string>& scene_file,
                          std::map<std::string, std::string, std::less<>>& scene_values, SceneChoices& choices,
                          bool with_covering) {
  command
      .add_option("--scene", scene_file, "TOML scene file; flags override it (see cli/examples/paper_scene.toml)")
      ->type_name("FILE.toml");
  const Scene defaults;
  for (const SceneField& field : SceneFields()) {
    if (!with_covering && field.table == "covering") continue;
    Scene scene = defaults;
    const std::string key = field.dotted_name();
    command
        .add_option_function<std::string>(
            std::string(field.flag), [&scene_values, key](const std::string& value) { scene_values[key] = value; },
            fmt::format("{} (default {})", field.help, FormatQuantity(field.field(scene), field.spec.kind)))
        ->type_name(std::string(TypeName(field.spec.kind)))
        ->group("Scene");
  }
  command
      .add_option("--thresholds", choices.thresholds, "phase thresholds: cumulative (default) or literal (the paper's text)")
      ->check(CLI::IsMember({"cumulative", "literal"}))
      ->group("Scene");
  command
      .add_option("--head-area", choices.head_area,
                  "the struck area of the head, whose lowest published fracture force the peak force is judged "
                  "against: " + HeadAreaChoices() + " (default frontal, the forehead; docs/model.md §7.1)")
      ->type_name("AREA")
      ->group("Scene");
  command
      .add_option("--covering-law", choices.covering_law,
                  "the covering's law: auto (default: the foam law where the --material has a measured compressive "
                  "curve, else Hertz), foam (the --material's measured curve; needs one), or hertz (the Hertz law, "
                  "the curve ignored) (docs/model.md §15, §16)")
      ->check(CLI::IsMember({"auto", "foam", "hertz"}))
      ->type_name("LAW")
      ->group("Scene");
}

void AddSceneOptions(CLI::App& sub_app, SimulateOptions& options) {
  CLI::App* sub = &sub_app;
  AddSceneFieldOptions(sub_app, options.scene_file, options.scene_values, options.choices, true);
  sub->add_option("--material", options.material,
                  "covering modulus and Poisson ratio from the material catalog (see 'covopt "
                  "materials list'); ν unknown there: 0.25, with a warning")
      ->type_name("NAME")
      ->group("Scene");
  AddCatalogOptions(*sub, options.catalog);
  // The injury limits (simulate adds the safety factor; sweep shows the ratios).
  AddRuleOptions(*sub, {.laceration_limit = &options.laceration_limit, .contusion_limit = &options.contusion_limit});
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
    plan.inputs.file_report = extras.report;
    (void)ReportInfoOf({}, plan.inputs);  // a bad [report] value is refused before anything runs
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
  plan.keep_travel = options.keep_travel;
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
  report.verdict = optim::SimulationVerdict(report.scene, report.result.peaks, plan.limits, plan.safety_factor,
                                            CrushCheckOf(plan), false, plan.keep_travel);
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

}  // namespace covopt::cli
