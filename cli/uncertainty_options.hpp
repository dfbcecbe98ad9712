#pragma once
/// @file uncertainty_options.hpp
/// The command line of issue 14 (docs/model.md §11) shared by simulate, optimize and
/// speed-limit: scene ranges into an optim::UncertaintyBox, --samples/--seed/--threads/
/// --distribution into InjuryProbabilityOptions, and a progress bar on a terminal's stderr.

#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "covopt/core/scene.hpp"
#include "covopt/optim/robust_design.hpp"
#include "covopt/report/robust_text.hpp"
#include "progress.hpp"
#include "scene_file.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The sampling flags as typed.
struct UncertaintyFlags {
  std::optional<std::string> samples;  ///< --samples N, 1..1e10
  std::optional<std::string> seed;     ///< --seed S, a whole number (default 1)
  std::optional<std::string> threads;  ///< --threads T, 0 (all cores, the default) .. 4096
  /// --distribution NAME=normal:MEAN:SD | NAME=lognormal:MEAN:SD | NAME=uniform (repeatable).
  std::vector<std::string> distributions;
};

/// Adds --samples and --distribution (and --seed and --threads when `with_seed_and_threads`;
/// optimize has its own) to `command`, in group "Uncertainty".
void AddUncertaintyOptions(CLI::App& command, UncertaintyFlags& flags, bool with_seed_and_threads);

/// The sampling the flags ask for, or empty without --samples.
/// @throws InputError for a bad value, --distribution/--seed without --samples, or --samples
///   without a range.
std::optional<optim::InjuryProbabilityOptions> ResolveSampling(const UncertaintyFlags& flags,
                                                              std::span<const SceneRange> ranges);

/// The ranges as the library's inputs, with their --distribution (uniform otherwise).
/// @throws InputError for an unknown NAME, a NAME without a range, a malformed distribution.
std::vector<optim::UncertainInput> ResolveUncertainInputs(std::span<const SceneRange> ranges,
                                                          std::span<const std::string> distributions);

/// optim::UncertaintyBox::FromScene with the library's message as InputError, naming where
/// the ranges were given; a nominal scene with damping, braking or a neck gets one line
/// saying the robust searches run on the exact path only.
optim::UncertaintyBox MakeUncertaintyBox(const Scene& nominal, std::span<const optim::UncertainInput> inputs,
                                         std::span<const SceneRange> ranges);

/// Sets each range's field of `scene` to the middle of the range (the nominal value).
void SetNominalValues(Scene& scene, std::span<const SceneRange> ranges);

/// The text of worst cases, probabilities, time-path use and elasticities (covopt/report/robust_text.hpp).
using report::DescribeValues;
using report::PrintElasticities;
using report::PrintInjuryProbability;
using report::PrintTimePathUse;
using report::PrintWorstCase;

/// The tornado chart of `table` into `path` (gnuplot; bars of the laceration and contusion
/// elasticities per input, largest at the top). @throws OutputError.
void PlotTornado(const std::string& path, const optim::ElasticityTable& table, bool svg);

/// The sampling's progress (cli/progress.hpp): a bar on a terminal, and on a log or a pipe a
/// line per 10 % step once the run has taken 5 s. Callback() is what
/// InjuryProbabilityOptions::progress takes.
class SamplingProgressBar : public ProgressBar {
 public:
  SamplingProgressBar(std::ostream& err, std::string label)
      : ProgressBar(err, std::move(label), ProgressBarOptions{.lines_when_not_terminal = true}) {}
};

}  // namespace covopt::cli
