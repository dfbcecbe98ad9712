#pragma once
/// @file grid.hpp
/// Many independent impacts on the exact path, spread over threads: the engine of parameter
/// sweeps and design maps.
///
/// Every scene is validated (ImpactModel::FromScene) and solved (SolveExact) on its own, so
/// a scene outside the model's input range is an invalid point with the library's message,
/// not a failure of the whole grid. Each point's result depends on its scene alone, so the
/// results are bit-identical whatever the number of threads.

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "covopt/core/exact.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/scene.hpp"

namespace covopt {

/// Options of SolveExactGrid.
struct GridOptions {
  /// Worker threads; 0 = std::thread::hardware_concurrency() (1 if unknown). Never more
  /// threads than chunks of work are started.
  unsigned threads = 0;
  /// What the exact path computes at each point. Default: peaks and contact duration.
  ExactOptions exact;
  /// Called now and then with (points done, points in total), always from the calling
  /// thread, last with done == total. May be empty. Must not throw.
  std::function<void(std::size_t done, std::size_t total)> progress;
};

/// One grid point: a result, or why the scene could not be solved.
struct GridPointResult {
  /// SolveExact's result; empty when the scene is outside the model's input range.
  std::optional<ImpactResult> result;
  /// InjuryAssessment of result->peaks against the default limits (valid points only).
  InjuryAssessment assessment;
  /// ImpactModel::FromScene's message for an invalid scene, e.g.
  /// "head.radius must exceed scalp.thickness ..."; empty for a valid one.
  std::string error;

  bool valid() const noexcept { return result.has_value(); }
};

/// Solves every scene on the exact path, in parallel; results in the scenes' order.
/// @throws std::invalid_argument when options.threads is above 4096.
std::vector<GridPointResult> SolveExactGrid(std::span<const Scene> scenes,
                                            const GridOptions& options = {});

}  // namespace covopt
