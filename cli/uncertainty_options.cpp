#include "uncertainty_options.hpp"

#include <algorithm>
#include <cstdlib>
#include <charconv>
#include <cmath>
#include <iostream>
#include <limits>
#include <stdexcept>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "covopt/core/scene_fields.hpp"
#include "covopt/chart/tornado_chart.hpp"
#include "errors.hpp"
#include "plot.hpp"
#include "quantity.hpp"
#include "scene_fields.hpp"

namespace covopt::cli {
namespace {

constexpr std::uint64_t kMaxSamples = 10'000'000'000ULL;

std::uint64_t ParseWhole(const std::string& text, std::string_view flag, std::uint64_t low, std::uint64_t high) {
  std::uint64_t value = 0;
  const char* begin = text.data();
  const char* end = begin + text.size();
  const auto [stop, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || stop != end || text.empty() || value < low || value > high) {
    throw InputError(fmt::format("{} must be a whole number in {}..{} (got '{}')", flag, low, high, text));
  }
  return value;
}

std::string_view Trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace

void AddUncertaintyOptions(CLI::App& command, UncertaintyFlags& flags, bool with_seed_and_threads) {
  command.add_option("--samples", flags.samples,
                     "with scene ranges (LO..HI): draw N scenes and report the probability of laceration, "
                     "contusion and either, with 95 % intervals")
      ->type_name("N")
      ->group("Uncertainty");
  if (with_seed_and_threads) {
    command.add_option("--seed", flags.seed, "seed of the --samples draws (default 1); the answer depends on it only")
        ->type_name("S")
        ->group("Uncertainty");
    command.add_option("--threads", flags.threads,
                       "threads for --samples, 0 = all cores (default); the answer does not depend on it")
        ->type_name("T")
        ->group("Uncertainty");
  }
  command.add_option("--distribution", flags.distributions,
                     "how a ranged input is drawn (default uniform): NAME=normal:MEAN:SD or NAME=lognormal:MEAN:SD "
                     "(mean and sd of the value, with units; truncated to the range), repeatable")
      ->type_name("NAME=LAW:MEAN:SD")
      ->group("Uncertainty");
}

std::optional<optim::InjuryProbabilityOptions> ResolveSampling(const UncertaintyFlags& flags,
                                                              std::span<const SceneRange> ranges) {
  if (!flags.samples) {
    if (!flags.distributions.empty()) {
      throw InputError(fmt::format("--distribution '{}' applies with --samples N", flags.distributions.front()));
    }
    return std::nullopt;
  }
  if (ranges.empty()) {
    throw InputError(fmt::format("--samples {}: nothing to sample; give at least one scene input as a range "
                                 "LO..HI, e.g. --head-mass 3.7kg..5.8kg",
                                 *flags.samples));
  }
  optim::InjuryProbabilityOptions options;
  options.samples = ParseWhole(*flags.samples, "--samples", 1, kMaxSamples);
  options.seed = flags.seed ? ParseWhole(*flags.seed, "--seed", 0, std::numeric_limits<std::uint64_t>::max()) : 1;
  options.threads = flags.threads ? static_cast<unsigned>(ParseWhole(*flags.threads, "--threads", 0, 4096)) : 0;
  return options;
}

std::vector<optim::UncertainInput> ResolveUncertainInputs(std::span<const SceneRange> ranges,
                                                          std::span<const std::string> distributions) {
  std::vector<optim::UncertainInput> inputs;
  for (const SceneRange& range : ranges) {
    optim::UncertainInput input;
    input.field = range.name;
    input.low = range.low;
    input.high = range.high;
    inputs.push_back(input);
  }
  std::vector<std::string> seen;
  for (const std::string& text : distributions) {
    const auto fail = [&](const std::string& problem) {
      throw InputError(fmt::format("--distribution: {} (got '{}')", problem, text));
    };
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos) {
      fail("expected NAME=normal:MEAN:SD, NAME=lognormal:MEAN:SD or NAME=uniform, e.g. "
           "head-mass=normal:4.5kg:0.5kg");
    }
    const std::string_view name = Trim(std::string_view(text).substr(0, eq));
    const covopt::SceneField* field = FindSceneField(name);
    if (field == nullptr) {
      fail(fmt::format("unknown input '{}'; the scene fields are {}", name, SceneFieldNames()));
    }
    const auto input = std::find_if(inputs.begin(), inputs.end(),
                                    [&](const optim::UncertainInput& i) { return i.field == field->name; });
    if (input == inputs.end()) {
      fail(fmt::format("{} has no range; a distribution needs one, e.g. --{} LO..HI", field->name, field->name));
    }
    if (std::find(seen.begin(), seen.end(), std::string(field->name)) != seen.end()) {
      fail(fmt::format("{} is given a distribution twice", field->name));
    }
    seen.emplace_back(field->name);
    std::vector<std::string_view> parts;
    std::string_view rest = std::string_view(text).substr(eq + 1);
    for (std::size_t colon = rest.find(':'); colon != std::string_view::npos; colon = rest.find(':')) {
      parts.push_back(Trim(rest.substr(0, colon)));
      rest = rest.substr(colon + 1);
    }
    parts.push_back(Trim(rest));
    if (parts.size() == 1 && parts[0] == "uniform") continue;
    if (parts.size() != 3 || (parts[0] != "normal" && parts[0] != "lognormal")) {
      fail("expected NAME=normal:MEAN:SD, NAME=lognormal:MEAN:SD or NAME=uniform, e.g. "
           "head-mass=normal:4.5kg:0.5kg");
    }
    const QuantitySpec units_only{field->spec.kind, false, false};
    const std::string flag = fmt::format("--distribution {}", field->name);
    input->distribution = parts[0] == "normal" ? optim::InputDistribution::kNormal : optim::InputDistribution::kLognormal;
    input->mean = ParseQuantity(parts[1], units_only, flag + " (mean)");
    input->standard_deviation = ParseQuantity(parts[2], units_only, flag + " (standard deviation)");
    // The distribution's own faults are blamed on --distribution, not on the range flag
    // (the library would name only the field, which the range's origin would then claim).
    const std::string law(parts[0]);
    const auto value = [&](double v) { return FormatQuantity(v, field->spec.kind); };
    const std::string range = fmt::format("{}..{}", value(input->low), value(input->high));
    if (!(input->low < input->high)) {
      fail(fmt::format("a {} distribution needs a range LO..HI with LO < HI; {} is the single value {}", law,
                       field->name, value(input->low)));
    }
    if (!(std::isfinite(input->standard_deviation) && input->standard_deviation > 0.0)) {
      fail(fmt::format("the standard deviation must be > 0 (got {}); expected {}=normal:MEAN:SD or "
                       "{}=lognormal:MEAN:SD with SD > 0 and MEAN in the range {}",
                       value(input->standard_deviation), field->name, field->name, range));
    }
    if (!(input->mean >= input->low && input->mean <= input->high)) {
      fail(fmt::format("the mean {} lies outside {}'s range {}; expected {}=normal:MEAN:SD or "
                       "{}=lognormal:MEAN:SD with MEAN in {}",
                       value(input->mean), field->name, range, field->name, field->name, range));
    }
    if (input->distribution == optim::InputDistribution::kLognormal && !(input->low >= 0.0 && input->mean > 0.0)) {
      fail(fmt::format("a lognormal distribution needs a range within [0, inf) and a mean > 0 (range {}, mean {}); "
                       "use {}=normal:MEAN:SD", range, value(input->mean), field->name));
    }
  }
  return inputs;
}

optim::UncertaintyBox MakeUncertaintyBox(const Scene& nominal, std::span<const optim::UncertainInput> inputs,
                                         std::span<const SceneRange> ranges) {
  if ((nominal.is_damped() || nominal.head.has_neck()) && !ranges.empty()) {
    throw InputError(fmt::format(
        "{} '{}': ranges (uncertain inputs) cover the two-mass impact, conservative or with a braking robot; a "
        "scene with {} is not supported with ranges (docs/model.md §11)",
        ranges.front().source, ranges.front().text, nominal.head.has_neck() ? "a neck" : "contact damping"));
  }
  try {
    return optim::UncertaintyBox::FromScene(nominal, inputs);
  } catch (const std::invalid_argument& e) {
    std::string message = e.what();
    // A fault of a distribution (the library names the field only): blame --distribution.
    if (message.find(" distribution") != std::string::npos || message.find(" standard deviation") != std::string::npos ||
        message.find(" mean ") != std::string::npos) {
      throw InputError(fmt::format("--distribution: {} (the forms are NAME=normal:MEAN:SD, NAME=lognormal:MEAN:SD "
                                   "and NAME=uniform, MEAN in NAME's range)",
                                   message));
    }
    std::string origins;
    for (const SceneRange& range : ranges) {
      if (message.find(range.name) != std::string::npos || message.find(range.field) != std::string::npos) {
        origins += fmt::format("{}{} from {} '{}'", origins.empty() ? "" : "; ", range.name, range.source, range.text);
      }
    }
    throw InputError(origins.empty() ? message : message + " (" + origins + ")");
  }
}

void SetNominalValues(Scene& scene, std::span<const SceneRange> ranges) {
  for (const SceneRange& range : ranges) {
    if (const covopt::SceneField* field = FindSceneField(range.name)) {
      field->field(scene) = 0.5 * (range.low + range.high);
    }
  }
}

void PlotTornado(const std::string& path, const optim::ElasticityTable& table, bool svg) {
  RunGnuplot(path, [&](const std::string& output) {
    return chart::TornadoChart(table, svg ? PlotFormat::kSvg : PlotFormat::kPng, output);
  });
}

}  // namespace covopt::cli
