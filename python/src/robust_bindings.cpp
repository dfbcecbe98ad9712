/// @file robust_bindings.cpp
/// covopt.worst_case, covopt.injury_probability, covopt.sensitivities and
/// covopt.robust_optimize: robust design over an uncertainty box (optim/robust_design.hpp,
/// docs/model.md §11) with the scene keywords of covopt.simulate. The dicts are
/// report/robust_json's, the objects `covopt simulate/optimize --json` print with scene ranges.
/// See python/covopt/__init__.py for the documentation.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <limits>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "covopt/core/exact.hpp"
#include "covopt/core/impact_model.hpp"
#include "covopt/core/scene_fields.hpp"
#include "covopt/core/time_integration.hpp"
#include "covopt/materials/catalog.hpp"
#include "covopt/optim/design.hpp"
#include "covopt/optim/robust_design.hpp"
#include "covopt/report/robust_json.hpp"
#include "report_charts.hpp"
#include "scene_keywords.hpp"

namespace py = pybind11;

namespace covopt::python {
namespace {

/// A whole number in [low, high], compared as Python ints (exactly, up to 2^64 - 1: a
/// seed may be any unsigned 64-bit value, 0 .. 18446744073709551615, as --seed's).
std::uint64_t Whole(const py::object& v, const char* keyword, std::uint64_t low, std::uint64_t high) {
  const bool whole = py::isinstance<py::int_>(v) && !py::isinstance<py::bool_>(v);
  if (!whole || PyObject_RichCompareBool(v.ptr(), py::int_(low).ptr(), Py_LT) != 0 ||
      PyObject_RichCompareBool(v.ptr(), py::int_(high).ptr(), Py_GT) != 0) {
    PyErr_Clear();
    throw std::invalid_argument(std::string(keyword) + " must be a whole number in [" + std::to_string(low) +
                                ", " + std::to_string(high) + "] (got " +
                                py::repr(v).cast<std::string>() + ")");
  }
  return v.cast<std::uint64_t>();
}

/// samples=, seed= and threads= of the sampling; none without samples.
std::optional<optim::InjuryProbabilityOptions> ReadSampling(const py::kwargs& kwargs) {
  const auto samples = Option(kwargs, "samples");
  if (!samples) return std::nullopt;
  optim::InjuryProbabilityOptions sampling;
  sampling.samples = Whole(*samples, "samples", 1, 10000000000);
  const auto seed = Option(kwargs, "seed");
  sampling.seed = seed ? Whole(*seed, "seed", 0, std::numeric_limits<std::uint64_t>::max()) : 1;
  const auto threads = Option(kwargs, "threads");
  sampling.threads = threads ? static_cast<unsigned>(Whole(*threads, "threads", 0, 4096)) : 0;
  return sampling;
}

/// The scene field of a keyword ("head_mass" or "head-mass").
const SceneField& FieldOf(const std::string& key) {
  std::string name = key;
  for (char& c : name) if (c == '_') c = '-';
  const SceneField* field = FindSceneField(name);
  if (field == nullptr) {
    throw std::invalid_argument("ranges: unknown input '" + key + "'; the scene fields are " + SceneFieldNames());
  }
  return *field;
}

/// ranges={"head_mass": ("3.7kg", "5.8kg"), ...} (or "3.7kg..5.8kg") and distributions=
/// {"head_mass": ("normal", "4.5kg", "0.5kg")} into the library's inputs.
std::vector<optim::UncertainInput> ReadRanges(const py::kwargs& kwargs) {
  const auto ranges = Option(kwargs, "ranges");
  if (!ranges || !py::isinstance<py::dict>(*ranges) || py::len(*ranges) == 0) {
    throw std::invalid_argument("ranges: expected a dict of scene inputs to (low, high), e.g. "
                                "{'head_mass': ('3.7kg', '5.8kg')}");
  }
  std::vector<optim::UncertainInput> inputs;
  for (const auto& item : py::reinterpret_borrow<py::dict>(*ranges)) {
    const std::string key = py::str(item.first).cast<std::string>();
    const SceneField& field = FieldOf(key);
    const std::string keyword = "ranges['" + key + "']";
    optim::UncertainInput input;
    input.field = std::string(field.name);
    if (py::isinstance<py::str>(item.second)) {
      const std::string text = item.second.cast<std::string>();
      const std::size_t dots = text.find("..");
      if (dots == std::string::npos) throw std::invalid_argument(keyword + ": expected 'LO..HI' or (low, high) (got '" + text + "')");
      input.low = ReadSceneQuantity(py::str(text.substr(0, dots)), field.spec, keyword);
      input.high = ReadSceneQuantity(py::str(text.substr(dots + 2)), field.spec, keyword);
    } else {
      const py::tuple pair = py::tuple(py::reinterpret_borrow<py::object>(item.second));
      if (pair.size() != 2) throw std::invalid_argument(keyword + ": expected (low, high)");
      input.low = ReadSceneQuantity(pair[0], field.spec, keyword);
      input.high = ReadSceneQuantity(pair[1], field.spec, keyword);
    }
    inputs.push_back(input);
  }
  if (const auto d = Option(kwargs, "distributions")) {
    if (!py::isinstance<py::dict>(*d)) {
      throw std::invalid_argument("distributions: expected a dict, e.g. {'head_mass': ('normal', '4.5kg', '0.5kg')}");
    }
    for (const auto& item : py::reinterpret_borrow<py::dict>(*d)) {
      const std::string key = py::str(item.first).cast<std::string>();
      const SceneField& field = FieldOf(key);
      auto input = std::find_if(inputs.begin(), inputs.end(), [&](const auto& i) { return i.field == field.name; });
      if (input == inputs.end()) throw std::invalid_argument("distributions: " + key + " has no range; a distribution needs one");
      const py::tuple law = py::tuple(py::reinterpret_borrow<py::object>(item.second));
      const std::string name = law.size() > 0 ? py::str(law[0]).cast<std::string>() : "";
      if (law.size() != 3 || (name != "normal" && name != "lognormal")) {
        throw std::invalid_argument("distributions['" + key + "']: expected ('normal' or 'lognormal', mean, sd)");
      }
      input->distribution = name == "normal" ? optim::InputDistribution::kNormal : optim::InputDistribution::kLognormal;
      const QuantitySpec units_only{field.spec.kind, false, false};
      input->mean = ReadSceneQuantity(law[1], units_only, "distributions['" + key + "'] mean");
      input->standard_deviation = ReadSceneQuantity(law[2], units_only, "distributions['" + key + "'] sd");
    }
  }
  return inputs;
}

/// The nominal scene (the middle of every range) and the box.
struct Box {
  SceneInputs scene;
  std::optional<optim::UncertaintyBox> box;
};

Box ReadBox(const SceneInputs& scene, const py::kwargs& kwargs) {
  Box b{scene, std::nullopt};
  const std::vector<optim::UncertainInput> inputs = ReadRanges(kwargs);
  for (const optim::UncertainInput& input : inputs) {
    FindSceneField(input.field)->field(b.scene.scene) = 0.5 * (input.low + input.high);
  }
  try {
    b.box.emplace(optim::UncertaintyBox::FromScene(b.scene.scene, inputs));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("ranges: ") + e.what());
  }
  return b;
}

/// The dict `covopt simulate --json` prints with ranges (and --samples when asked).
py::object UncertainSimulation(const SceneInputs& scene, const py::kwargs& kwargs, bool sample) {
  Box b = ReadBox(scene, kwargs);
  optim::WorstCaseOptions worst_options;
  worst_options.limits = b.scene.limits;
  worst_options.safety_factor = b.scene.safety_factor;
  // The material's strength: a crushed covering fails the worst case (docs/model.md §12).
  worst_options.compressive_strength_Pa = b.scene.CrushCheck().compressive_strength_Pa;
  std::optional<optim::InjuryProbabilityOptions> sampling;
  if (sample) {
    sampling = ReadSampling(kwargs);
    if (!sampling) throw std::invalid_argument("injury_probability() needs samples=N");
    sampling->limits = b.scene.limits;
    sampling->safety_factor = b.scene.safety_factor;
    sampling->compressive_strength_Pa = worst_options.compressive_strength_Pa;
  }
  report::SimulationReport impact;
  optim::WorstCase worst;
  std::optional<optim::InjuryProbability> probability;
  {
    py::gil_scoped_release release;
    worst = optim::FindWorstCase(*b.box, worst_options);
    impact.scene = worst.scene;
    // A braking robot's worst case is a time-path impact (docs/model.md §11).
    const ImpactModel model = ImpactModel::FromScene(worst.scene);
    impact.result = worst.scene.robot_brakes() ? SimulateImpact(model) : SolveExact(model);
    if (sampling) probability = optim::EstimateInjuryProbability(*b.box, *sampling);
  }
  impact.covering_material = b.scene.covering_material;
  impact.covering_poisson_assumed = b.scene.covering_poisson_assumed;
  b.scene.Judge(impact);
  // The report's chart: the worst case's history (as the CLI's simulate with ranges).
  return WithReportCharts(JsonToPython(report::UncertainSimulationJson(impact, &*b.box, &worst,
                                                                       probability ? &*probability : nullptr, nullptr, -1)),
                          [impact] { return chart::SimulationCharts(impact); });
}

py::object WorstCase(const SceneInputs& scene, const py::kwargs& kwargs) {
  return UncertainSimulation(scene, kwargs, false);
}

py::object InjuryProbability(const SceneInputs& scene, const py::kwargs& kwargs) {
  return UncertainSimulation(scene, kwargs, true);
}

py::object Sensitivities(const SceneInputs& inputs) {
  optim::ElasticityOptions options;
  options.limits = inputs.limits;
  optim::ElasticityTable table;
  {
    py::gil_scoped_release release;
    table = optim::ComputeElasticities(inputs.scene, options);
  }
  return JsonToPython(report::ElasticitiesJson(table, -1));
}

py::object RobustOptimize(const SceneInputs& scene, const py::kwargs& kwargs) {
  for (const char* k : {"covering_modulus", "covering_thickness", "covering_poisson", "material"}) {
    if (scene.Gave(k)) throw std::invalid_argument(std::string(k) + ": the covering is what robust_optimize designs");
  }
  SceneInputs without_law = scene;  // the law is the design's, not the designed covering's
  without_law.scene.covering.law = CoveringLaw::kAuto;
  Box b = ReadBox(without_law, kwargs);
  optim::DesignOptions design;
  design.limits = b.scene.limits;
  design.safety_factor = b.scene.safety_factor;
  design.allow_full_compression = Flag(kwargs, "allow_full_compression");
  design.allow_crushing = Flag(kwargs, "allow_crushing");
  design.allow_unknown_strength = Flag(kwargs, "allow_unknown_strength");
  design.covering_law = scene.scene.covering.law;  // auto: the foam law where a material has a curve
  std::vector<optim::CandidateMaterial> materials = optim::SelectCandidates(materials::Catalog::BuiltIn());
  optim::KeepCandidatesForLaw(materials, design.covering_law);
  (void)optim::KeepCandidatesTheSceneModels(materials, design.covering_law, b.scene.scene);  // as the CLI
  std::optional<optim::InjuryProbabilityOptions> sampling = ReadSampling(kwargs);
  if (const auto p = Option(kwargs, "max_injury_probability")) {
    if (!sampling) throw std::invalid_argument("max_injury_probability needs samples=N (the probability is estimated)");
    optim::ProbabilityDesignOptions options;
    options.design = design;
    options.sampling = *sampling;
    options.max_probability = p->cast<double>();
    if (!(options.max_probability > 0.0 && options.max_probability < 1.0)) {
      throw std::invalid_argument("max_injury_probability must be in (0, 1) (got " + py::repr(*p).cast<std::string>() + ")");
    }
    optim::ProbabilityDesign result;
    {
      py::gil_scoped_release release;
      result = optim::FindProbabilityDesign(*b.box, materials, options);
    }
    return JsonToPython(report::ProbabilityDesignJson(*b.box, options, result, {}, -1));
  }
  optim::RobustDesignOptions options;
  options.design = design;
  optim::RobustThinnestCovering result;
  std::optional<optim::InjuryProbability> probability;
  {
    py::gil_scoped_release release;
    result = optim::FindRobustThinnestCovering(*b.box, materials, options);
    if (sampling && result.recommendation) {
      const optim::RobustCandidate& c = result.candidates[*result.recommendation];
      Scene designed = b.box->nominal();
      designed.covering = optim::CoveringOf(c.outcome.material, *c.outcome.recommended_thickness_m,
                                            design.covering_law);
      const std::vector<optim::UncertainInput> inputs(b.box->inputs().begin(), b.box->inputs().end());
      sampling->limits = design.limits;
      sampling->safety_factor = design.safety_factor;
      sampling->allow_full_compression = design.allow_full_compression;
      probability = optim::EstimateInjuryProbability(optim::UncertaintyBox::FromScene(designed, inputs), *sampling);
    }
  }
  return JsonToPython(report::RobustDesignJson(*b.box, options, result, probability ? &*probability : nullptr, {}, -1));
}

}  // namespace

void BindRobust(py::module_& m) {
  m.def("worst_case", &WorstCase);
  m.def("injury_probability", &InjuryProbability);
  m.def("sensitivities", &Sensitivities);
  m.def("robust_optimize", &RobustOptimize);
}

}  // namespace covopt::python
