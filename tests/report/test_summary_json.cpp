// covopt::report::SummaryJson / SummaryFromJson / SummaryText (report/summary_json.hpp): every
// field reads back exactly, a number that is not finite is null and reads back as the one
// non-finite value its key can hold, a missing key is named, and the text says the state.

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "covopt/core/result_summary.hpp"
#include "covopt/report/summary_json.hpp"

namespace {

using covopt::CriterionPart;
using covopt::ResultSummary;
using covopt::Verdict;
using covopt::VerdictState;
using Json = nlohmann::json;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Equal, or both NaN.
bool Same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

void CheckSame(const covopt::SummaryRow& a, const covopt::SummaryRow& b) {
  CHECK(a.target == b.target);
  CHECK(a.criterion == b.criterion);
  CHECK(a.part == b.part);
  CHECK(a.unit == b.unit);
  CHECK(Same(a.value, b.value));
  CHECK(Same(a.limit, b.limit));
  CHECK(Same(a.derated_limit, b.derated_limit));
  CHECK(Same(a.ratio, b.ratio));
  CHECK(Same(a.margin, b.margin));
  CHECK(a.counted == b.counted);
  CHECK(a.passed == b.passed);
  CHECK(a.binding == b.binding);
  CHECK(a.law == b.law);
  CHECK(a.validity == b.validity);
  CHECK(a.source == b.source);
  CHECK(a.note == b.note);
}

void CheckSame(const covopt::LimitRow& a, const covopt::LimitRow& b) {
  CHECK(a.target == b.target);
  CHECK(a.quantity == b.quantity);
  CHECK(a.unit == b.unit);
  CHECK(Same(a.value, b.value));
  CHECK(a.binding_criterion == b.binding_criterion);
  CHECK(a.law == b.law);
  CHECK(a.validity == b.validity);
  CHECK(a.note == b.note);
}

void CheckSame(const ResultSummary& a, const ResultSummary& b) {
  CHECK(a.kind == b.kind);
  CHECK(a.command == b.command);
  CHECK(a.evaluated == b.evaluated);
  CHECK(a.safe == b.safe);
  CHECK(Same(a.safety_factor, b.safety_factor));
  CHECK(Same(a.margin, b.margin));
  CHECK(Same(a.margin_threshold, b.margin_threshold));
  CHECK(a.state == b.state);
  CHECK(a.governing_target == b.governing_target);
  CHECK(a.governing_criterion == b.governing_criterion);
  CHECK(Same(a.governing_ratio, b.governing_ratio));
  CHECK(a.governing_case == b.governing_case);
  CHECK(a.targets == b.targets);
  CHECK(a.criteria == b.criteria);
  CHECK(a.standards == b.standards);
  REQUIRE(a.limit_tables.size() == b.limit_tables.size());
  for (std::size_t i = 0; i < a.limit_tables.size(); ++i) {
    CHECK(a.limit_tables[i].title == b.limit_tables[i].title);
    CHECK(a.limit_tables[i].edition == b.limit_tables[i].edition);
    CHECK(a.limit_tables[i].source == b.limit_tables[i].source);
    CHECK(a.limit_tables[i].sha256 == b.limit_tables[i].sha256);
  }
  CHECK(a.scope == b.scope);
  CHECK(a.covering.present == b.covering.present);
  CHECK(a.covering.material == b.covering.material);
  CHECK(Same(a.covering.thickness_m, b.covering.thickness_m));
  CHECK(a.covering.law == b.covering.law);
  CHECK(a.covering.validity == b.covering.validity);
  CHECK(Same(a.covering.validity_ratio, b.covering.validity_ratio));
  CHECK(a.robot.model_file == b.robot.model_file);
  CHECK(a.robot.motion == b.robot.motion);
  CHECK(a.robot.joints == b.robot.joints);
  CHECK(Same(a.robot.reflected_mass_kg, b.robot.reflected_mass_kg));
  CHECK(Same(a.robot.payload_kg, b.robot.payload_kg));
  CHECK(Same(a.robot.speed_m_per_s, b.robot.speed_m_per_s));
  REQUIRE(a.rows.size() == b.rows.size());
  for (std::size_t i = 0; i < a.rows.size(); ++i) CheckSame(a.rows[i], b.rows[i]);
  REQUIRE(a.limits.size() == b.limits.size());
  for (std::size_t i = 0; i < a.limits.size(); ++i) CheckSame(a.limits[i], b.limits[i]);
}

/// A head and a chest verdict with awkward numbers: 0.1 + 0.2, an unknown limit, a note.
ResultSummary Verdicts() {
  Verdict head;
  head.safety_factor = 1.2;
  head.Add("laceration", CriterionPart::kInjury, "Pa", 0.1 + 0.2, 1e6, "Park et al. 2011");
  head.Add("contusion", CriterionPart::kInjury, "J/m2", 2.0e4 / 3.0, 2.52e4, "Park et al. 2011");
  head.Add("crush", CriterionPart::kDesignRule, "Pa", 1.5e5, kNaN, "the material's compressive strength", false)
      .note = "strength unknown";
  covopt::AddLawValidity(head, true, 0.4321);
  head.scope = {"the head's criteria of Park et al. 2011", "a second sentence"};
  Verdict chest;
  chest.safety_factor = 1.2;
  chest.Add("force", CriterionPart::kInjury, "N", 123.456789, 140.0, "ISO/TS 15066:2016 Table A.2");
  ResultSummary s;
  s.command = "simulate";
  s.margin_threshold = 0.15;
  s.AddVerdict("head (frontal)", head, "foam", "within");
  s.AddVerdict("chest (sternum)", chest, "hertz", "beyond the curve's last point");
  s.AddLimitTable({.title = "Company limits", .edition = "Company 2026", .source = "limits.toml", .sha256 = "ab12"});
  s.AddLimitTable({.title = "Company limits", .edition = "Company 2026", .source = "limits.toml", .sha256 = "ab12"});
  s.Finish();
  s.governing_case = "sample 41 at t = 1.23 s, link fr3_link7 against the chest";
  s.covering = {.present = true, .material = "XPS Dow blue", .thickness_m = 0.02591, .law = "foam",
                .validity = "within", .validity_ratio = 0.4321};
  s.robot = {.model_file = "fr3.urdf", .motion = "program pick.csv (412 samples)",
             .joints = {"fr3_joint1", "fr3_joint2"}, .reflected_mass_kg = kNaN, .payload_kg = 0.5,
             .speed_m_per_s = 1.0 / 3.0};
  return s;
}

}  // namespace

TEST_CASE("SummaryJson: a verdict summary reads back field by field", "[summary]") {
  const ResultSummary s = Verdicts();
  REQUIRE(s.rows.size() == 5);
  // A table added twice is named once, its edition once among the standards.
  REQUIRE(s.limit_tables.size() == 1);
  CHECK(std::count(s.standards.begin(), s.standards.end(), "Company 2026") == 1);
  const std::string text = covopt::report::SummaryJson(s);
  CheckSame(covopt::report::SummaryFromJson(text), s);
  // ... also from the whole result object holding it under "summary".
  const std::string result = R"({"safe": true, "summary": )" + text + "}";
  CheckSame(covopt::report::SummaryFromJson(result), s);
}

TEST_CASE("SummaryJson: the keys in their documented order, non-finite numbers null", "[summary]") {
  const Json j = Json::parse(covopt::report::SummaryJson(Verdicts()));
  CHECK(j["kind"] == "verdict");
  CHECK(j["state"] == "unsafe");  // SF 1.2 × the chest force ratio 0.88 exceeds 1
  CHECK(j["governing"]["criterion"] == "force");
  CHECK(j["rows"][2]["limit"].is_null());  // the unknown strength
  CHECK(j["rows"][2]["ratio"].is_null());
  CHECK(j["rows"][2]["note"] == "strength unknown");
  CHECK(j["robot"]["reflected_mass_kg"].is_null());
  CHECK(j["rows"][0]["part"] == "injury");
  CHECK(j["rows"][3]["part"] == "design-rule");
  const nlohmann::ordered_json ordered = nlohmann::ordered_json::parse(covopt::report::SummaryJson(Verdicts()));
  std::vector<std::string> keys;
  for (const auto& item : ordered.items()) keys.push_back(item.key());
  CHECK(keys == std::vector<std::string>{"kind", "command", "evaluated", "safe", "state", "safety_factor", "margin",
                                         "margin_threshold", "governing", "targets", "criteria", "standards", "limit_tables", "scope",
                                         "covering", "robot", "rows", "limits"});
}

TEST_CASE("SummaryJson: a summary not evaluated reads back with its infinities", "[summary]") {
  Verdict failed;
  failed.evaluated = false;
  failed.Add("force", CriterionPart::kInjury, "N", kInf, 140.0, "ISO/TS 15066:2016 Table A.2");
  ResultSummary s;
  s.command = "robot --trajectory";
  s.AddVerdict("hand", failed, "bare", "");
  s.Finish();
  REQUIRE(s.state == VerdictState::kNotEvaluated);
  REQUIRE(s.rows[0].ratio == kInf);
  const Json j = Json::parse(covopt::report::SummaryJson(s));
  CHECK(j["margin"].is_null());
  CHECK(j["covering"].is_null());
  const ResultSummary back = covopt::report::SummaryFromJson(j.dump());
  CHECK(back.margin == -kInf);
  CHECK(back.governing_ratio == kInf);
  CHECK(back.rows[0].margin == -kInf);
  // The value was +inf: a number without a documented infinity reads back as NaN.
  CHECK(std::isnan(back.rows[0].value));
  s.rows[0].value = kNaN;
  CheckSame(back, s);
}

TEST_CASE("SummaryJson: a table of limits reads back, a case not limited as +inf", "[summary]") {
  ResultSummary s;
  s.kind = ResultSummary::Kind::kLimits;
  s.command = "speed-limit";
  s.limits = {{.target = "head (frontal), robot mass 5 kg", .quantity = "max safe speed", .unit = "m/s",
               .value = 0.123456789, .binding_criterion = "contusion", .law = "foam", .validity = "within",
               .note = ""},
              {.target = "hand", .quantity = "max safe speed", .unit = "m/s", .value = kInf,
               .binding_criterion = "", .law = "foam", .validity = "within",
               .note = "not limited below the search limit 10 m/s"}};
  s.Finish();
  REQUIRE(s.state == VerdictState::kLimits);
  const std::string text = covopt::report::SummaryJson(s);
  CHECK(Json::parse(text)["state"] == "limits");
  CheckSame(covopt::report::SummaryFromJson(text), s);
  const std::string words = covopt::report::SummaryText(s);
  CHECK(words.rfind("LIMITS: ", 0) == 0);
  CHECK(words.find("0.1235 m/s, bound by contusion") != std::string::npos);
  CHECK(words.find("not limited") != std::string::npos);
}

TEST_CASE("SummaryFromJson: a missing summary or key is named", "[summary]") {
  CHECK_THROWS_WITH(covopt::report::SummaryFromJson(R"({"safe": true})"),
                    Catch::Contains("no \"summary\" object"));
  Json j = Json::parse(covopt::report::SummaryJson(Verdicts()));
  j["rows"][1].erase("derated_limit");
  CHECK_THROWS_WITH(covopt::report::SummaryFromJson(j.dump()), Catch::Contains("\"derated_limit\""));
  j = Json::parse(covopt::report::SummaryJson(Verdicts()));
  j["state"] = "fine";
  CHECK_THROWS_AS(covopt::report::SummaryFromJson(j.dump()), std::invalid_argument);
  CHECK_THROWS_AS(covopt::report::SummaryFromJson("not json"), std::invalid_argument);
}

TEST_CASE("SummaryText: the state word with margin and threshold, then the governing row in the CLI's units",
          "[summary]") {
  ResultSummary s;
  Verdict head;
  head.Add("laceration", CriterionPart::kInjury, "Pa", 0.3e6, 1e6, "Park et al. 2011");
  head.Add("contusion", CriterionPart::kInjury, "J/m2", 0.998 * 2.52e4, 2.52e4, "Park et al. 2011");
  s.AddVerdict("head (frontal)", head, "foam", "within");
  s.Finish();
  s.covering = {.present = true, .material = "XPS Dow blue", .thickness_m = 0.02591, .law = "foam",
                .validity = "within", .validity_ratio = 0.5};
  const std::string text = covopt::report::SummaryText(s);
  CHECK(text.rfind("MARGINAL, margin 0.2 % < 10.0 %: head (frontal) contusion ratio 0.998\n", 0) == 0);
  CHECK(text.find("covering: XPS Dow blue, 25.91 mm, law foam, within") != std::string::npos);
  CHECK(text.find("head (frontal) contusion: 2.515 J/cm², limit 2.52 J/cm², ratio 0.998, margin 0.2 %, passed"
                  "  <- governing") != std::string::npos);
  CHECK(text.find("laceration: 0.3 MPa") != std::string::npos);
  CHECK(text.back() == '\n');
  s.covering = {};
  CHECK(covopt::report::SummaryText(s).find("covering: none (bare robot)") != std::string::npos);
  // The first line alone; every line indented; the rows left out on request.
  CHECK(covopt::report::SummaryHeadline(s) == "MARGINAL, margin 0.2 % < 10.0 %: head (frontal) contusion ratio 0.998");
  const std::string indented = covopt::report::SummaryText(s, 2);
  CHECK(indented.rfind("  MARGINAL, margin", 0) == 0);
  CHECK(indented.find("\n  judged against: Park et al. 2011\n") != std::string::npos);
  CHECK(indented.find("\n    head (frontal) contusion: ") != std::string::npos);
  const std::string without_rows = covopt::report::SummaryText(s, 0, false);
  CHECK(without_rows.find("contusion: ") == std::string::npos);
  CHECK(without_rows.rfind("MARGINAL, margin", 0) == 0);
}
