#pragma once
/// @file design_answer.hpp
/// The default answer of `covopt optimize` (docs/guide/optimize.md, "The default answer"),
/// applied to a DesignResult by Design(): a recommended material with a compressive curve must
/// also be admissible over its stated uncertainty (material_range.hpp: its curve scaled over its
/// σ(25 %) band and rate factor), at the thinnest thickness that is; a material that is not
/// within the maximum thickness is not admissible (its row says why) and the next one is
/// recommended. A curve candidate's row (its score and margin) is then that of its range's worst
/// end at its thickness. When no material is admissible, the result carries the nearest changes.

#include "covopt/optim/design.hpp"

namespace covopt::optim {

/// Checks the admissible candidates of `result` (problem a or b of `request`) over their
/// ranges, raises or refuses them, re-ranks them, sets the recommendation, the verdict
/// (kNoSafeMaterial when none is left), material_range, range_notes and nearest_changes.
/// A scene the exact path cannot answer (braking, a neck) is left as it is, with a warning when
/// a candidate has a curve. Not applied to a failed result or a bare robot that is safe.
void AnswerOverRange(const DesignRequest& request, DesignResult& result);

}  // namespace covopt::optim
