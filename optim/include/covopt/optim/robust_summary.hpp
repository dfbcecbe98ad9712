#pragma once
/// @file robust_summary.hpp
/// The result summary (covopt/core/result_summary.hpp) of the robust designs: one row each,
/// the design's own verdict restated (never judged again).

#include <covopt/core/result_summary.hpp>

#include "covopt/optim/robust_design.hpp"
#include "covopt/optim/robust_probability.hpp"

namespace covopt::optim {

/// `optimize` with ranges: one row, the recommendation's worst case over the box (its binding
/// criterion, governing ratio and admissibility: unit "1", limit 1); without a recommendation
/// the bare robot's worst case, safe only when it needs no covering. `area`: the struck area.
ResultSummary SummarizeRobustDesign(const RobustDesignOptions& options, const RobustThinnestCovering& result,
                                    HeadArea area);

/// `optimize --max-injury-probability P`: one row, the recommendation's (else the bare
/// robot's) upper 95 % bound of P(inadmissible) against P (margin 1 − bound / P).
ResultSummary SummarizeProbabilityDesign(const ProbabilityDesignOptions& options, const ProbabilityDesign& result,
                                         HeadArea area);

}  // namespace covopt::optim
