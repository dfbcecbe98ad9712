#include "covopt/report/summary_json.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "covopt/core/number_format.hpp"
#include "criterion_display.hpp"
#include "json_number.hpp"
#include "summary_object.hpp"

namespace covopt::report {
namespace {

using Json = nlohmann::ordered_json;
using internal::Number;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ---- writing -------------------------------------------------------------------------------

Json RowObject(const SummaryRow& r) {
  return {{"target", r.target},     {"criterion", r.criterion},
          {"part", ToString(r.part)}, {"unit", r.unit},
          {"value", Number(r.value)}, {"limit", Number(r.limit)},
          {"derated_limit", Number(r.derated_limit)}, {"ratio", Number(r.ratio)},
          {"margin", Number(r.margin)}, {"counted", r.counted},
          {"passed", r.passed},       {"binding", r.binding},
          {"law", r.law},             {"validity", r.validity},
          {"source", r.source},       {"note", r.note}};
}

Json LimitObject(const LimitRow& r) {
  return {{"target", r.target}, {"quantity", r.quantity}, {"unit", r.unit}, {"value", Number(r.value)},
          {"binding_criterion", r.binding_criterion}, {"law", r.law}, {"validity", r.validity}, {"note", r.note}};
}

Json CoveringObject(const CoveringSummary& c) {
  if (!c.present) return nullptr;
  return {{"material", c.material}, {"thickness_m", Number(c.thickness_m)}, {"law", c.law},
          {"validity", c.validity}, {"validity_ratio", Number(c.validity_ratio)}};
}

Json LimitTableObjects(const std::vector<LimitTableSummary>& tables) {
  Json list = Json::array();
  for (const LimitTableSummary& t : tables) {
    list.push_back({{"title", t.title}, {"edition", t.edition}, {"source", t.source}, {"sha256", t.sha256}});
  }
  return list;
}

Json RobotObject(const RobotSummary& r) {
  return {{"model_file", r.model_file}, {"motion", r.motion}, {"joints", r.joints},
          {"reflected_mass_kg", Number(r.reflected_mass_kg)}, {"payload_kg", Number(r.payload_kg)},
          {"speed_m_per_s", Number(r.speed_m_per_s)}};
}

// ---- reading -------------------------------------------------------------------------------

const Json& Key(const Json& object, std::string_view key, std::string_view where) {
  const auto it = object.find(key);
  if (it == object.end()) {
    throw std::invalid_argument(fmt::format("result summary: {} has no key \"{}\"", where, key));
  }
  return *it;
}

std::string Text(const Json& object, std::string_view key, std::string_view where) {
  const Json& v = Key(object, key, where);
  if (!v.is_string()) throw std::invalid_argument(fmt::format("result summary: {}.{} is not a string", where, key));
  return v.get<std::string>();
}

bool Flag(const Json& object, std::string_view key, std::string_view where) {
  const Json& v = Key(object, key, where);
  if (!v.is_boolean()) throw std::invalid_argument(fmt::format("result summary: {}.{} is not true or false", where, key));
  return v.get<bool>();
}

/// A number; null reads back as `if_null` (the documented non-finite value of that key).
double Real(const Json& object, std::string_view key, std::string_view where, double if_null = kNaN) {
  const Json& v = Key(object, key, where);
  if (v.is_null()) return if_null;
  if (!v.is_number()) throw std::invalid_argument(fmt::format("result summary: {}.{} is not a number", where, key));
  return v.get<double>();
}

std::vector<std::string> Texts(const Json& object, std::string_view key, std::string_view where) {
  const Json& v = Key(object, key, where);
  std::vector<std::string> out;
  if (!v.is_array()) throw std::invalid_argument(fmt::format("result summary: {}.{} is not a list", where, key));
  for (const Json& item : v) {
    if (!item.is_string()) throw std::invalid_argument(fmt::format("result summary: {}.{} holds a non-string", where, key));
    out.push_back(item.get<std::string>());
  }
  return out;
}

const Json& List(const Json& object, std::string_view key, std::string_view where) {
  const Json& v = Key(object, key, where);
  if (!v.is_array()) throw std::invalid_argument(fmt::format("result summary: {}.{} is not a list", where, key));
  return v;
}

VerdictState StateOf(const std::string& word) {
  for (const VerdictState s : {VerdictState::kSafe, VerdictState::kMarginal, VerdictState::kUnsafe,
                               VerdictState::kLimits, VerdictState::kNotEvaluated}) {
    if (ToString(s) == word) return s;
  }
  throw std::invalid_argument(fmt::format(
      "result summary: state \"{}\" is not one of safe, marginal, unsafe, limits, not-evaluated", word));
}

CriterionPart PartOf(const std::string& word) {
  for (const CriterionPart p : {CriterionPart::kInjury, CriterionPart::kDesignRule}) {
    if (ToString(p) == word) return p;
  }
  throw std::invalid_argument(fmt::format("result summary: part \"{}\" is not injury or design-rule", word));
}

SummaryRow RowFrom(const Json& o) {
  constexpr std::string_view w = "a row";
  SummaryRow r{.target = Text(o, "target", w),
               .criterion = Text(o, "criterion", w),
               .part = PartOf(Text(o, "part", w)),
               .unit = Text(o, "unit", w),
               .value = Real(o, "value", w),
               .limit = Real(o, "limit", w),
               .derated_limit = Real(o, "derated_limit", w),
               .ratio = 0.0,
               .margin = 0.0,
               .counted = Flag(o, "counted", w),
               .passed = Flag(o, "passed", w),
               .binding = Flag(o, "binding", w),
               .law = Text(o, "law", w),
               .validity = Text(o, "validity", w),
               .source = Text(o, "source", w),
               .note = Text(o, "note", w)};
  // A ratio without a limit is unknown (NaN); with one, a null ratio is the not-evaluated +inf.
  r.ratio = Real(o, "ratio", w, std::isnan(r.limit) ? kNaN : kInf);
  r.margin = Real(o, "margin", w, std::isnan(r.ratio) ? kNaN : -kInf);
  return r;
}

LimitRow LimitFrom(const Json& o) {
  constexpr std::string_view w = "a limit row";
  return LimitRow{.target = Text(o, "target", w),
                  .quantity = Text(o, "quantity", w),
                  .unit = Text(o, "unit", w),
                  .value = Real(o, "value", w, kInf),
                  .binding_criterion = Text(o, "binding_criterion", w),
                  .law = Text(o, "law", w),
                  .validity = Text(o, "validity", w),
                  .note = Text(o, "note", w)};
}

CoveringSummary CoveringFrom(const Json& o) {
  if (o.is_null()) return {};
  constexpr std::string_view w = "the covering";
  return CoveringSummary{.present = true,
                         .material = Text(o, "material", w),
                         .thickness_m = Real(o, "thickness_m", w),
                         .law = Text(o, "law", w),
                         .validity = Text(o, "validity", w),
                         .validity_ratio = Real(o, "validity_ratio", w)};
}

/// "limit_tables" (absent in a summary written before it existed: none).
std::vector<LimitTableSummary> LimitTablesFrom(const Json& o) {
  std::vector<LimitTableSummary> tables;
  if (!o.contains("limit_tables")) return tables;
  constexpr std::string_view w = "a limit table";
  for (const Json& t : List(o, "limit_tables", "the summary")) {
    tables.push_back({.title = Text(t, "title", w), .edition = Text(t, "edition", w), .source = Text(t, "source", w),
                      .sha256 = Text(t, "sha256", w)});
  }
  return tables;
}

RobotSummary RobotFrom(const Json& o) {
  constexpr std::string_view w = "the robot";
  return RobotSummary{.model_file = Text(o, "model_file", w),
                      .motion = Text(o, "motion", w),
                      .joints = Texts(o, "joints", w),
                      .reflected_mass_kg = Real(o, "reflected_mass_kg", w),
                      .payload_kg = Real(o, "payload_kg", w),
                      .speed_m_per_s = Real(o, "speed_m_per_s", w)};
}

/// The "summary" object of a result, or the object itself when it is a summary.
const Json& FindSummary(const Json& root) {
  if (root.is_object()) {
    const auto it = root.find("summary");
    if (it != root.end() && it->is_object()) return *it;
    if (root.contains("kind") && root.contains("rows")) return root;
  }
  throw std::invalid_argument("result summary: the result has no \"summary\" object");
}

// ---- text ----------------------------------------------------------------------------------

/// "2.52 J/cm²" in the CLI's units; a share ("1") without a unit.
std::string RowAmount(const SummaryRow& r, double si) {
  internal::Display d = internal::DisplayOf(r.criterion, r.unit);
  if (d.unit == "1") d.unit = "";
  return internal::Amount(si, d);
}

std::string Ratio(double ratio) { return std::isfinite(ratio) ? fmt::format("{:.4g}", ratio) : "unknown"; }

std::string HeadLine(const ResultSummary& s) {
  const std::string_view word = StateWord(s.state);
  if (s.state == VerdictState::kNotEvaluated) return fmt::format("{}: the result could not be computed", word);
  if (s.kind == ResultSummary::Kind::kLimits) {
    std::size_t none = 0;
    for (const LimitRow& r : s.limits) none += r.value > 0.0 ? 0 : 1;
    if (none > 0) return fmt::format("{}: {} of {} cases have no safe value", word, none, s.limits.size());
    return fmt::format("{}: safe at or below each case's value ({} cases)", word, s.limits.size());
  }
  const std::string_view compare = s.state == VerdictState::kSafe ? ">=" : s.state == VerdictState::kMarginal ? "<" : "";
  std::string line = fmt::format("{}, margin {}", word, FormatPercent(s.margin));
  if (!compare.empty()) line += fmt::format(" {} {}", compare, FormatPercent(s.margin_threshold));
  if (!s.governing_criterion.empty()) {
    line += fmt::format(": {} {} ratio {}", s.governing_target, s.governing_criterion, Ratio(s.governing_ratio));
  }
  return line;
}

std::string CoveringLine(const CoveringSummary& c) {
  if (!c.present) return "covering: none (bare robot)";
  std::string line = "covering: " + (c.material.empty() ? std::string("given by its modulus") : c.material);
  line += fmt::format(", {} mm, law {}", std::isfinite(c.thickness_m) ? FormatSignificant(c.thickness_m * 1e3, 4) : "unknown",
                      c.law);
  if (!c.validity.empty()) line += ", " + c.validity;
  if (std::isfinite(c.validity_ratio)) line += fmt::format(" (validity ratio {:.3g})", c.validity_ratio);
  return line;
}

std::string RobotLine(const RobotSummary& r) {
  std::string line = "robot:";
  if (!r.model_file.empty()) line += " " + r.model_file + ",";
  if (!r.motion.empty()) line += " " + r.motion + ",";
  if (!r.joints.empty()) line += fmt::format(" {} joints,", r.joints.size());
  line += std::isfinite(r.reflected_mass_kg) ? fmt::format(" reflected mass {:.4g} kg", r.reflected_mass_kg)
                                             : std::string(" reflected mass per case");
  if (std::isfinite(r.payload_kg) && r.payload_kg > 0.0) line += fmt::format(", payload {:.4g} kg", r.payload_kg);
  if (std::isfinite(r.speed_m_per_s)) line += fmt::format(", speed {:.4g} m/s", r.speed_m_per_s);
  return line;
}

std::string RowLine(const SummaryRow& r, double safety_factor) {
  std::string line = fmt::format("  {} {}: {}", r.target, r.criterion, RowAmount(r, r.value));
  if (std::isfinite(r.limit)) {
    line += ", limit " + RowAmount(r, r.limit);
    if (safety_factor != 1.0) line += " (derated " + RowAmount(r, r.derated_limit) + ")";
  }
  line += fmt::format(", ratio {}, margin {}, {}", Ratio(r.ratio), FormatPercent(r.margin),
                      !r.counted ? "not counted" : r.passed ? "passed" : "FAILED");
  if (!r.note.empty()) line += " (" + r.note + ")";
  if (r.binding) line += "  <- governing";
  return line;
}

std::string SummaryLines(const ResultSummary& s, bool rows);

std::string LimitLine(const LimitRow& r) {
  std::string value = std::isinf(r.value) ? std::string("not limited")
                      : r.value > 0.0     ? fmt::format("{:.4g} {}", r.value, r.unit)
                                          : std::string("no safe value");
  std::string line = fmt::format("  {}: {} {}", r.target, r.quantity, value);
  if (!r.binding_criterion.empty()) line += ", bound by " + r.binding_criterion;
  if (!r.law.empty()) line += ", law " + r.law;
  if (!r.validity.empty()) line += ", " + r.validity;
  if (!r.note.empty()) line += " (" + r.note + ")";
  return line;
}

}  // namespace

namespace internal {

Json SummaryObject(const ResultSummary& s) {
  Json rows = Json::array();
  for (const SummaryRow& r : s.rows) rows.push_back(RowObject(r));
  Json limits = Json::array();
  for (const LimitRow& r : s.limits) limits.push_back(LimitObject(r));
  return {
      {"kind", s.kind == ResultSummary::Kind::kVerdict ? "verdict" : "limits"},
      {"command", s.command},
      {"evaluated", s.evaluated},
      {"safe", s.safe},
      {"state", ToString(s.state)},
      {"safety_factor", Number(s.safety_factor)},
      {"margin", Number(s.margin)},
      {"margin_threshold", Number(s.margin_threshold)},
      {"governing", {{"target", s.governing_target}, {"criterion", s.governing_criterion},
                     {"ratio", Number(s.governing_ratio)}, {"case", s.governing_case}}},
      {"targets", s.targets},
      {"criteria", s.criteria},
      {"standards", s.standards},
      {"limit_tables", LimitTableObjects(s.limit_tables)},
      {"scope", s.scope},
      {"covering", CoveringObject(s.covering)},
      {"robot", RobotObject(s.robot)},
      {"rows", std::move(rows)},
      {"limits", std::move(limits)}};
}

}  // namespace internal

std::string SummaryJson(const ResultSummary& summary) { return internal::SummaryObject(summary).dump(); }

ResultSummary SummaryFromJson(const std::string& result_json) {
  const Json root = Json::parse(result_json, nullptr, false);
  if (root.is_discarded()) throw std::invalid_argument("result summary: the result is not JSON");
  const Json& o = FindSummary(root);
  constexpr std::string_view w = "the summary";
  ResultSummary s;
  const std::string kind = Text(o, "kind", w);
  if (kind != "verdict" && kind != "limits") {
    throw std::invalid_argument(fmt::format("result summary: kind \"{}\" is not verdict or limits", kind));
  }
  s.kind = kind == "verdict" ? ResultSummary::Kind::kVerdict : ResultSummary::Kind::kLimits;
  s.command = Text(o, "command", w);
  s.evaluated = Flag(o, "evaluated", w);
  s.safe = Flag(o, "safe", w);
  s.state = StateOf(Text(o, "state", w));
  s.safety_factor = Real(o, "safety_factor", w);
  s.margin = Real(o, "margin", w, s.kind == ResultSummary::Kind::kVerdict ? -kInf : kNaN);
  s.margin_threshold = Real(o, "margin_threshold", w);
  const Json& g = Key(o, "governing", w);
  s.governing_target = Text(g, "target", "the governing case");
  s.governing_criterion = Text(g, "criterion", "the governing case");
  s.governing_ratio = Real(g, "ratio", "the governing case", kInf);
  s.governing_case = Text(g, "case", "the governing case");
  s.targets = Texts(o, "targets", w);
  s.criteria = Texts(o, "criteria", w);
  s.standards = Texts(o, "standards", w);
  s.limit_tables = LimitTablesFrom(o);
  s.scope = Texts(o, "scope", w);
  s.covering = CoveringFrom(Key(o, "covering", w));
  s.robot = RobotFrom(Key(o, "robot", w));
  for (const Json& r : List(o, "rows", w)) s.rows.push_back(RowFrom(r));
  for (const Json& r : List(o, "limits", w)) s.limits.push_back(LimitFrom(r));
  return s;
}

std::string SummaryText(const ResultSummary& s, int indent, bool rows) {
  const std::string pad(static_cast<std::size_t>(std::max(indent, 0)), ' ');
  std::string indented;
  std::size_t start = 0;
  const std::string text = SummaryLines(s, rows);
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    indented += pad + text.substr(start, end - start + 1);
    start = end + 1;
  }
  return indented;
}

std::string SummaryHeadline(const ResultSummary& summary) { return HeadLine(summary); }

namespace {

std::string SummaryLines(const ResultSummary& s, bool rows) {
  std::string text = HeadLine(s) + "\n";
  if (s.kind == ResultSummary::Kind::kVerdict && !s.governing_case.empty()) {
    text += "governing case: " + s.governing_case + "\n";
  }
  text += CoveringLine(s.covering) + "\n";
  text += RobotLine(s.robot) + "\n";
  if (!s.standards.empty()) {
    std::string joined;
    for (const std::string& standard : s.standards) joined += (joined.empty() ? "" : "; ") + standard;
    text += "judged against: " + joined + "\n";
  }
  for (const LimitTableSummary& t : s.limit_tables) {
    text += "limit table: " + t.title + " (" + t.source + ", sha256 " + t.sha256 + ")\n";
  }
  if (s.kind == ResultSummary::Kind::kVerdict && s.safety_factor != 1.0) {
    text += fmt::format("safety factor {:g}\n", s.safety_factor);
  }
  if (!rows) return text;
  for (const SummaryRow& r : s.rows) text += RowLine(r, s.safety_factor) + "\n";
  for (const LimitRow& r : s.limits) text += LimitLine(r) + "\n";
  return text;
}

}  // namespace

}  // namespace covopt::report
