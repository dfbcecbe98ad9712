#pragma once
/// @file html_assessment.hpp
/// What the HTML report says (private to covopt_report): a command's --json object read into
/// its verdict, its rows, the criteria and the models it rests on.

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "html_text.hpp"

namespace covopt::report::internal::html {

/// One verdict line: value against limit, ratio and margin.
struct VerdictRow {
  std::string subject;    ///< what is judged: "head: laceration", "chest (sternum): force"
  std::string criterion;  ///< the criterion, with its source in short
  std::string value;      ///< value, limit and derated limit as read (display units)
  std::string limit;
  std::string derated;
  Json ratio;             ///< a number, or null where the row has none (a yes/no criterion)
  double safety_factor = 1.0;
  std::optional<bool> safe;
  std::string note;
};

/// One criterion and where its limit comes from.
struct Criterion {
  std::string name;
  std::string limit;
  std::string source;
};

enum class Model { kHead, kBody, kSpeedLimit, kTrajectory, kAudit, kRobust };

struct Governing {
  std::string criterion;  ///< "contusion", "chest (sternum): force", ...
  Json ratio;             ///< the JSON's number, or null when the kind has none
};

struct Assessment {
  bool safe = false;
  std::string headline;          ///< one sentence: what was found
  std::string safe_means;        ///< what SAFE means for this kind, when it needs saying
  Governing governing;
  double safety_factor = 1.0;
  std::vector<VerdictRow> rows;  ///< every verdict
  std::string rows_note;         ///< what the rows are (e.g. "the recommended design")
  std::vector<Criterion> criteria;
  std::set<Model> models;
  std::vector<std::string> input_keys;  ///< top-level keys shown as inputs
};

/// The assessment of each command's result; std::invalid_argument when it has no verdict,
/// nlohmann::json::exception when it is not that command's result.
void AssessSimulate(Assessment& a, const Json& j);
void AssessOptimize(Assessment& a, const Json& j);
void AssessSpeedLimit(Assessment& a, const Json& j);
void AssessTrajectory(Assessment& a, const Json& j);
void AssessAudit(Assessment& a, const Json& j);

}  // namespace covopt::report::internal::html
