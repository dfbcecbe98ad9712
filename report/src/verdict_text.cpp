#include "covopt/report/verdict_text.hpp"

#include <cmath>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "criterion_display.hpp"
#include "json_number.hpp"
#include "verdict_object.hpp"

namespace covopt::report {
namespace {

using internal::Amount;
using internal::Display;

Display DisplayOf(const Criterion& c) { return internal::DisplayOf(c.name, c.unit); }

bool Exceeded(const Criterion& c, double safety_factor) { return !c.passed || !(safety_factor * c.ratio <= 1.0); }

std::string_view StatusWord(const Criterion& c) {
  if (!c.counted) return "--";
  return SafeWord(c.passed);
}

std::string PartLine(const Verdict& v, CriterionPart part, std::string_view title, const std::string& pad) {
  const bool ok = part == CriterionPart::kInjury ? v.injury_safe() : v.design_rules_met();
  return fmt::format("{}{:<12} {}", pad, title, SafeWord(ok && v.evaluated));
}

}  // namespace

std::string RatioText(const Criterion& c, double safety_factor) {
  const Display d = DisplayOf(c);
  std::string text = std::isfinite(c.ratio) ? fmt::format("ratio {:.4g}", c.ratio) : std::string("ratio unknown");
  if (!Exceeded(c, safety_factor)) return text;
  text += fmt::format(" EXCEEDED (limit {}, derated {} at SF {:g}", Amount(c.limit, d), Amount(c.derated_limit, d),
                      safety_factor);
  if (c.name == "full-compression" && c.ratio > 1.0) text += ": fully compressed";
  if (c.name == "within-curve" && c.ratio > 1.0) text += ": the layer is used up";
  return text + ")";
}

std::string CriterionText(const Criterion& c, double safety_factor) {
  if (c.name == kLawValidityRule) {  // a yes/no of the model's range: no value to derate
    return fmt::format("{:<17} {:<7} {}", c.name, StatusWord(c),
                       c.passed ? "within the covering law's validity"
                                : "OUT of the covering law's validity (see the validity note)");
  }
  const Display d = DisplayOf(c);
  std::string text = fmt::format("{:<17} {:<7} {} {}", c.name, StatusWord(c), d.label, Amount(c.value, d));
  if (std::isfinite(c.limit)) {
    text += fmt::format(", limit {}", Amount(c.limit, d));
    if (safety_factor != 1.0) text += fmt::format(" (derated {})", Amount(c.derated_limit, d));
  }
  text += ", " + RatioText(c, safety_factor);
  if (!c.counted) text += "; not counted";
  if (!c.note.empty()) text += fmt::format(" ({})", c.note);
  return text;
}

std::string VerdictSummary(const Verdict& v) {
  if (!v.evaluated) return "UNSAFE (no verdict: the contact was not computed)";
  return fmt::format("{} (governing {}, ratio {:.4g}, margin {}, safety factor {:g})", SafeWord(v.safe()),
                     v.governing_name(), v.governing_ratio(), FormatPercent(v.margin()), v.safety_factor);
}

std::vector<std::string> VerdictLines(const Verdict& v, int indent) {
  const std::string pad(static_cast<std::size_t>(indent), ' ');
  std::vector<std::string> lines;
  for (const CriterionPart part : {CriterionPart::kInjury, CriterionPart::kDesignRule}) {
    bool heading = false;
    for (const Criterion& c : v.criteria) {
      if (c.part != part) continue;
      if (!heading) {
        lines.push_back(PartLine(v, part, part == CriterionPart::kInjury ? "injury" : "design rules", pad));
        heading = true;
      }
      lines.push_back(pad + "  " + CriterionText(c, v.safety_factor));
      // The fracture force is one study's: its citation stays beside it (docs/model.md §7.1).
      if (c.name == "fracture") lines.push_back(fmt::format("{}    {:<17} source: {}", pad, "", c.source));
    }
  }
  lines.push_back(fmt::format("{}{:<12} {}", pad, "overall", VerdictSummary(v)));
  return lines;
}

namespace internal {

nlohmann::ordered_json VerdictObject(const Verdict& v) {
  using Json = nlohmann::ordered_json;
  Json criteria = Json::array();
  for (const Criterion& c : v.criteria) {
    criteria.push_back({{"name", c.name},
                        {"part", ToString(c.part)},
                        {"unit", c.unit},
                        {"value", Number(c.value)},
                        {"limit", Number(c.limit)},
                        {"derated_limit", Number(c.derated_limit)},
                        {"ratio", Number(c.ratio)},
                        {"counted", c.counted},
                        {"passed", c.passed},
                        {"source", c.source},
                        {"note", c.note.empty() ? Json(nullptr) : Json(c.note)}});
  }
  return {{"safe", v.safe()},
          {"injury_safe", v.injury_safe()},
          {"design_rules_met", v.design_rules_met()},
          {"evaluated", v.evaluated},
          {"governing", v.governing_name()},
          {"governing_ratio", Number(v.governing_ratio())},
          {"margin", Number(v.margin())},
          {"margin_percent", Number(v.margin() * 100.0)},
          {"safety_factor", v.safety_factor},
          {"criteria", std::move(criteria)},
          {"scope", v.scope}};
}

}  // namespace internal

std::string VerdictJson(const Verdict& v, int indent) { return internal::VerdictObject(v).dump(indent); }

}  // namespace covopt::report
