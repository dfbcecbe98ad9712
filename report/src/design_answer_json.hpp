#pragma once
/// @file design_answer_json.hpp
/// The default answer's keys of DesignJson (private to covopt_report).

#include <nlohmann/json.hpp>

#include "covopt/optim/design.hpp"

namespace covopt::report::internal {

/// Adds to a DesignJson object `j`: "material_range" (the recommendation's check over its
/// stated uncertainty, or null), "nearest_changes" (or null), and to each of j["candidates"]
/// its "range_note" ("" when its range changed nothing).
void AddDesignAnswerJson(nlohmann::ordered_json& j, const optim::DesignResult& result);

}  // namespace covopt::report::internal
