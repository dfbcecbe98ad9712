#pragma once
/// @file design_csv.hpp
/// `covopt optimize --csv`: the design's candidate table as CSV.

#include <string>
#include <vector>

#include "covopt/optim/design.hpp"

namespace covopt::report {

/// Every candidate of a design (optim::DesignResult::candidates, ranked), one row each, SI units
/// in the header: rank, material, family, youngs_modulus_Pa, poisson_ratio, poisson_assumed,
/// crush_behaviour, compressive_strength_Pa, admissible, thickness_m, min_safe_thickness_m, the
/// ratios, governing_criterion, governing_ratio (under `rule`), margin,
/// max_compressive_stress_Pa, fully_compressed.
std::string DesignCandidatesCsv(const std::vector<optim::CandidateOutcome>& candidates, const optim::DesignRule& rule);

}  // namespace covopt::report
