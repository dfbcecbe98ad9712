#pragma once
/// @file design_json.hpp
/// A design answer as JSON text: the object `covopt optimize --json` prints and
/// `covopt.optimize()` returns as a dict; both call DesignJson, so keys and values agree by
/// construction. SI values, units in the keys (thickness_m, youngs_modulus_Pa, ...).

#include <span>
#include <string>

#include "covopt/optim/design.hpp"

namespace covopt::report {

/// The request's answer as one JSON object: problem, criterion, verdict, message (one sentence),
/// summary (the result summary, summary_json.hpp),
/// recommendation (null when none), continuous_optimum, bare_robot, candidates, solver
/// (termination, evaluations, seconds, global / bracket / local stage reports),
/// safety_factor, limits (and the derated ones), design_space, thickness_m (problem b),
/// scene (without the covering) and warnings: `input_warnings` (what the caller noticed
/// about its input) followed by the result's own.
/// `indent` as in nlohmann's dump: 2 (the CLI's), or -1 for one line.
std::string DesignJson(const optim::DesignRequest& request, const optim::DesignResult& result,
                       std::span<const std::string> input_warnings = {}, int indent = 2);

}  // namespace covopt::report
