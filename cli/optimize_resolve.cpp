#include "optimize_resolve.hpp"

#include <algorithm>
#include <charconv>
#include <limits>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "covopt/core/physical_floors.hpp"
#include "covopt/materials/catalog.hpp"
#include "catalog_options.hpp"
#include "design_flag_ranges.hpp"
#include "errors.hpp"
#include "oracle_options.hpp"
#include "quantity.hpp"
#include "scene_fields.hpp"
#include "scene_file.hpp"

namespace covopt::cli {
namespace {

using optim::DesignOptions;

double Parse(const std::optional<std::string>& text, const QuantitySpec& spec, std::string_view flag,
             double fallback) {
  return text ? ParseQuantity(*text, spec, flag) : fallback;
}

/// A whole number in [min, max] as typed after `flag` (no sign for min >= 0, no unit).
unsigned long long ParseCount(const std::string& text, std::string_view flag, unsigned long long min,
                              unsigned long long max) {
  unsigned long long value = 0;
  const char* const end = text.data() + text.size();
  const auto [stop, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || stop != end || value < min || value > max) {
    throw InputError(fmt::format("{}: expected a whole number in [{}, {}] (got '{}')", flag, min, max, text));
  }
  return value;
}

/// --oracle, --method and --rtol into the request's OracleOptions (the scene must be read).
void ResolveOracle(const OptimizeOptions& o, Resolved& r) {
  r.request.options.oracle = ResolveOracleFlags(o.oracle_flags, r.request.scene, "optimise", r.warnings);
}

/// The scene (file, flags, ranges, --urdf) into `r`, with the scene file's limits.
void ResolveScene(const OptimizeOptions& o, Resolved& r) {
  DesignOptions& d = r.request.options;
  if (o.scene_file) {
    SceneFileExtras extras;
    for (const std::string& name : ApplySceneFile(*o.scene_file, r.request.scene, &extras)) {
      if (name.rfind("covering.", 0) == 0) {
        r.warnings.push_back(fmt::format("{} in {} is ignored: the covering is what optimize designs",
                                         name, *o.scene_file));
      }
    }
    for (const SceneRange& range : extras.ranges) {
      if (range.field.rfind("covering.", 0) != 0) r.ranges.push_back(range);  // covering: warned above
    }
    if (extras.laceration_limit_Pa) d.limits.laceration_tensile_stress_Pa = *extras.laceration_limit_Pa;
    if (extras.contusion_limit_J_per_m2) d.limits.contusion_energy_density_J_per_m2 = *extras.contusion_limit_J_per_m2;
    if (extras.safety_factor) d.safety_factor = *extras.safety_factor;
    r.inputs.file_report = extras.report;
    (void)ReportInfoOf({}, r.inputs);  // a bad [report] value is refused before anything runs
  }
  std::vector<scene_file::SceneInput> inputs;  // the values, for the library's one resolution
  for (const SceneField& field : SceneFields()) {
    const auto typed = o.scene_values.find(field.dotted_name());
    if (typed != o.scene_values.end()) {
      std::erase_if(r.ranges, [&](const SceneRange& range) { return range.field == field.dotted_name(); });
      if (IsRangeText(typed->second)) {
        r.ranges.push_back(AsInputError([&] { return scene_file::ParseSceneRange(typed->second, field, field.flag); }));
      } else {
        inputs.push_back({typed->first, typed->second, ""});
      }
    }
  }
  scene_file::ResolvedScene resolved{r.request.scene, d.limits, d.safety_factor, nullptr};
  ApplySceneFlagInputs(inputs, resolved);
  r.request.scene = resolved.scene;
  SetNominalValues(r.request.scene, r.ranges);
  if (o.choices.thresholds) r.request.scene.model.thresholds = ParseThresholds(*o.choices.thresholds, "--thresholds");
  if (o.choices.head_area) r.request.scene.head.area = ParseHeadArea(*o.choices.head_area, "--head-area");
  if (o.choices.covering_law) {
    r.request.scene.covering.law =
        AsInputError([&] { return scene_file::ParseCoveringLawOrThrow(*o.choices.covering_law, "--covering-law"); });
  }
  // The law the catalog materials are designed with (auto: the foam law where a material has a
  // curve). It is the design's, not the scene's covering's (which is what is designed).
  r.request.options.covering_law = r.request.scene.covering.law;
  r.request.scene.covering.law = CoveringLaw::kAuto;
  if (o.robot_model.given()) {  // --urdf ...: robot.mass from the robot model
    RobotModelMass mass = ResolveRobotModelMass(o.robot_model, o.scene_values.count(kRobotMassField) != 0);
    r.request.scene.robot.mass_kg = mass.mass_kg;
    std::erase_if(r.ranges, [](const SceneRange& range) { return range.field == kRobotMassField; });
    r.warnings.insert(r.warnings.begin(), mass.notes.begin(), mass.notes.end());
  }
}

/// The design flags (criterion, space, limits, safety factor, ν, step, --thickness) into `r`,
/// each checked against its range with the flag's name.
void ResolveDesignFlags(const OptimizeOptions& o, Resolved& r) {
  DesignOptions& d = r.request.options;
  namespace specs = covopt::quantity_specs;
  d.allow_full_compression = o.allow_full_compression;
  d.allow_crushing = o.allow_crushing;
  d.allow_unknown_strength = o.allow_unknown_strength;
  d.space.max_thickness_m = Parse(o.max_thickness, specs::kCoveringThickness, "--max-thickness", d.space.max_thickness_m);
  d.space.min_modulus_Pa = Parse(o.min_modulus, specs::kCoveringModulus, "--min-modulus", d.space.min_modulus_Pa);
  d.space.max_modulus_Pa = Parse(o.max_modulus, specs::kCoveringModulus, "--max-modulus", d.space.max_modulus_Pa);
  d.safety_factor = Parse(o.safety_factor, specs::kSafetyFactor, "--safety-factor", d.safety_factor);
  d.covering_poisson_ratio = Parse(o.covering_poisson, specs::kPoissonRatio, "--covering-poisson", d.covering_poisson_ratio);
  d.thickness_step_m = Parse(o.thickness_step, specs::kThicknessStep, "--thickness-step", d.thickness_step_m);
  d.limits.laceration_tensile_stress_Pa =
      Parse(o.laceration_limit, specs::kLacerationLimit, "--laceration-limit", d.limits.laceration_tensile_stress_Pa);
  d.limits.contusion_energy_density_J_per_m2 =
      Parse(o.contusion_limit, specs::kContusionLimit, "--contusion-limit", d.limits.contusion_energy_density_J_per_m2);
  // Range checks with the flag's name (the library would name its own fields).
  auto require = [](bool ok, const std::string& message) {
    if (!ok) throw InputError(message);
  };
  RequireMaxThickness(d.space.max_thickness_m, d.space.min_thickness_m, o.max_thickness);
  require(d.space.min_modulus_Pa > 0 && d.space.max_modulus_Pa > d.space.min_modulus_Pa &&
              d.space.max_modulus_Pa <= 1e13,
          fmt::format("--min-modulus/--max-modulus must satisfy 0 < min < max <= 1e13 Pa (got {} Pa, {} Pa)",
                      d.space.min_modulus_Pa, d.space.max_modulus_Pa));
  require(d.safety_factor >= 1.0 && d.safety_factor <= 100.0,
          fmt::format("--safety-factor must be in [1, 100] (got '{}')", o.safety_factor.value_or(fmt::format("{}", d.safety_factor))));
  require(d.covering_poisson_ratio > -1.0 && d.covering_poisson_ratio <= 0.5,
          fmt::format("--covering-poisson must be in (-1, 0.5] (got '{}')", o.covering_poisson.value_or("")));
  RequireThicknessStep(d.thickness_step_m, o.thickness_step);
  // The limits' one range (scene_file::CheckLimitValue), as simulate, scene files and Python.
  const std::span<const LimitField> limit_fields = LimitFields();
  CheckLimitValue(limit_fields[0], d.limits.laceration_tensile_stress_Pa, "--laceration-limit",
                  fmt::format("'{}'", o.laceration_limit.value_or("")));
  CheckLimitValue(limit_fields[1], d.limits.contusion_energy_density_J_per_m2, "--contusion-limit",
                  fmt::format("'{}'", o.contusion_limit.value_or("")));
  if (o.thickness) {
    r.request.thickness_m = ParseQuantity(*o.thickness, specs::kCoveringThickness, "--thickness");
    require(*r.request.thickness_m >= kMinLayerThickness_m && *r.request.thickness_m <= 1.0,
            fmt::format("--thickness must be in [0.1 mm, 1 m] (got '{}'); for no covering use "
                        "'covopt simulate --covering-thickness 0'",
                        *o.thickness));
    if (o.max_thickness) {
      throw InputError(fmt::format("--thickness {} and --max-thickness {} conflict: --thickness fixes the thickness "
                                   "(the least injury there), --max-thickness bounds the search for the thinnest; "
                                   "give one",
                                   *o.thickness, *o.max_thickness));
    }
  }
}

}  // namespace

Resolved ResolveOptimize(const OptimizeOptions& o) {
  Resolved r;
  DesignOptions& d = r.request.options;
  ResolveScene(o, r);
  ResolveDesignFlags(o, r);
  if (o.global_algorithm) {
    const std::string& g = *o.global_algorithm;
    if (g == "direct-l") d.global_algorithm = optim::NloptAlgorithm::kDirectL;
    else if (g == "isres") d.global_algorithm = optim::NloptAlgorithm::kIsres;
    else if (g == "mlsl") d.global_algorithm = optim::NloptAlgorithm::kMlsl;
    else throw InputError(fmt::format("--global: expected direct-l, isres or mlsl (got '{}')", g));
  }
  if (o.seed) d.seed = ParseCount(*o.seed, "--seed", 0, std::numeric_limits<unsigned long>::max());
  if (o.runners_up) r.runners_up = static_cast<int>(ParseCount(*o.runners_up, "--top", 0, 1000000));
  if (o.threads) {  // 0 = every core, as simulate's sampling and sweep take it
    const auto threads = ParseCount(*o.threads, "--threads", 0, 256);
    d.threads = threads == 0 ? static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 256u))
                             : static_cast<int>(threads);
  }
  ResolveOracle(o, r);

  // The candidates: the built-in catalog and --catalog files (or only those, --no-builtin), filtered.
  const materials::Catalog catalog = [&] {
    try {
      return LoadCatalog(o.catalog);
    } catch (const InputError& e) {
      const std::string what = e.what();
      throw InputError(what.rfind("--", 0) == 0 ? what : "--catalog: " + what);
    }
  }();
  try {
    r.request.materials = optim::SelectCandidates(catalog, o.materials, o.families);
    // Under --covering-law foam the catalog's materials without a curve are no candidates; one
    // named with --material is refused by the design, naming it.
    if (o.materials.empty()) optim::KeepCandidatesForLaw(r.request.materials, r.request.options.covering_law);
    for (std::string& w : optim::KeepCandidatesTheSceneModels(r.request.materials, r.request.options.covering_law,
                                                               r.request.scene)) {
      r.warnings.push_back(std::move(w));
    }
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    throw InputError((what.rfind("no family", 0) == 0 ? "--family: " : "--material: ") + what);
  }
  return r;
}

}  // namespace covopt::cli
