#pragma once
/// @file verdict_object.hpp
/// VerdictJson's object, for the JSON writers that embed it (private to covopt_report).

#include <nlohmann/json.hpp>

#include <covopt/core/verdict.hpp>

namespace covopt::report::internal {

/// The object of VerdictJson (verdict_text.hpp).
nlohmann::ordered_json VerdictObject(const Verdict& verdict);

}  // namespace covopt::report::internal
