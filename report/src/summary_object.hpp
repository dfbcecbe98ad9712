#pragma once
/// @file summary_object.hpp
/// SummaryJson's object, for the JSON writers that embed it as "summary" (private to covopt_report).

#include <nlohmann/json.hpp>

#include <covopt/core/result_summary.hpp>

namespace covopt::report::internal {

/// The object of SummaryJson (summary_json.hpp).
nlohmann::ordered_json SummaryObject(const ResultSummary& summary);

}  // namespace covopt::report::internal
