// covopt::ResultSummary (core/result_summary.hpp): rows made from verdicts, the binding row, the
// margin and the three verdict states; a table of limits.

#include <cmath>
#include <limits>
#include <string>

#include <catch2/catch.hpp>

#include "covopt/core/result_summary.hpp"

using covopt::CriterionPart;
using covopt::ResultSummary;
using covopt::Verdict;
using covopt::VerdictState;

namespace {

Verdict Head(double contusion_ratio, double sf = 1.0) {
  Verdict v;
  v.safety_factor = sf;
  v.Add("laceration", CriterionPart::kInjury, "Pa", 0.3e6, 1e6, "Park et al. 2011");
  v.Add("contusion", CriterionPart::kInjury, "J/m2", contusion_ratio * 2.52e4, 2.52e4, "Park et al. 2011");
  covopt::AddLawValidity(v, true, 0.5);
  v.scope = {"head criteria of Park et al. 2011"};
  return v;
}

Verdict Chest(double force_ratio) {
  Verdict v;
  v.Add("force", CriterionPart::kInjury, "N", force_ratio * 140.0, 140.0, "ISO/TS 15066:2016 Table A.2");
  v.Add("pressure", CriterionPart::kInjury, "Pa", 0.1e6, 1.1e6, "ISO/TS 15066:2016 Table A.2", false);
  return v;
}

}  // namespace

TEST_CASE("VerdictStateOf: not evaluated, unsafe, then SAFE at or above the threshold, else MARGINAL",
          "[summary]") {
  CHECK(covopt::VerdictStateOf(false, true, 0.5, 0.1) == VerdictState::kNotEvaluated);
  CHECK(covopt::VerdictStateOf(true, false, 0.5, 0.1) == VerdictState::kUnsafe);
  CHECK(covopt::VerdictStateOf(true, true, 0.1, 0.1) == VerdictState::kSafe);
  CHECK(covopt::VerdictStateOf(true, true, 0.002, 0.1) == VerdictState::kMarginal);
  CHECK(covopt::VerdictStateOf(true, true, 0.002, 0.0) == VerdictState::kSafe);
  CHECK(covopt::ToString(VerdictState::kNotEvaluated) == "not-evaluated");
  CHECK(covopt::StateWord(VerdictState::kMarginal) == "MARGINAL");
  CHECK(covopt::StateWord(VerdictState::kLimits) == "LIMITS");
}

TEST_CASE("ResultSummary: one row per criterion, the counted row with the largest ratio binds", "[summary]") {
  ResultSummary s;
  s.AddVerdict("head (frontal)", Head(0.6), "foam", "within");
  s.AddVerdict("chest (sternum)", Chest(0.8), "foam", "within");
  s.Finish();
  REQUIRE(s.rows.size() == 5);
  CHECK(s.rows[0].target == "head (frontal)");
  CHECK(s.rows[0].criterion == "laceration");
  CHECK(s.rows[2].criterion == "law-validity");
  CHECK(s.rows[2].part == CriterionPart::kDesignRule);
  CHECK(s.rows[3].law == "foam");
  CHECK(s.governing_target == "chest (sternum)");
  CHECK(s.governing_criterion == "force");
  CHECK(s.governing_ratio == Approx(0.8));
  CHECK(s.margin == Approx(0.2));
  CHECK(s.rows[3].binding);
  CHECK_FALSE(s.rows[1].binding);
  CHECK(s.safe);
  CHECK(s.state == VerdictState::kSafe);
  CHECK(s.targets == std::vector<std::string>{"head (frontal)", "chest (sternum)"});
  // The uncounted pressure is reported, not applied.
  CHECK(s.criteria == std::vector<std::string>{"laceration", "contusion", "law-validity", "force"});
  CHECK(s.standards == std::vector<std::string>{"Park et al. 2011", "ISO/TS 15066:2016 Table A.2"});
  CHECK(s.scope == std::vector<std::string>{"head criteria of Park et al. 2011"});
}

TEST_CASE("ResultSummary: margin is 1 - SF x ratio, a thin margin is MARGINAL, an exceeded one UNSAFE",
          "[summary]") {
  ResultSummary marginal;
  marginal.AddVerdict("head (frontal)", Head(0.998), "foam", "within");
  marginal.Finish();
  CHECK(marginal.safe);
  CHECK(marginal.margin == Approx(0.002));
  CHECK(marginal.state == VerdictState::kMarginal);

  ResultSummary derated;
  derated.AddVerdict("head (frontal)", Head(0.6, 2.0), "foam", "within");
  derated.Finish();
  CHECK(derated.safety_factor == 2.0);
  CHECK(derated.margin == Approx(1.0 - 2.0 * 0.6));
  CHECK_FALSE(derated.safe);
  CHECK(derated.state == VerdictState::kUnsafe);
  CHECK(derated.rows[1].margin == Approx(-0.2));
}

TEST_CASE("ResultSummary: a verdict not evaluated is NOT EVALUATED with a margin of -inf", "[summary]") {
  Verdict failed;
  failed.evaluated = false;
  ResultSummary s;
  s.AddVerdict("chest (sternum)", failed, "bare", "");
  s.Finish();
  CHECK_FALSE(s.evaluated);
  CHECK_FALSE(s.safe);
  CHECK(s.state == VerdictState::kNotEvaluated);
  CHECK(s.margin == -std::numeric_limits<double>::infinity());
  CHECK(s.governing_ratio == std::numeric_limits<double>::infinity());
}

TEST_CASE("ResultSummary: a table of limits is LIMITS, UNSAFE when a case has no safe value", "[summary]") {
  ResultSummary s;
  s.kind = ResultSummary::Kind::kLimits;
  s.limits.push_back({.target = "head (frontal)", .quantity = "max safe speed", .unit = "m/s", .value = 0.8,
                      .binding_criterion = "contusion", .law = "foam", .validity = "within", .note = ""});
  s.Finish();
  CHECK(s.safe);
  CHECK(s.state == VerdictState::kLimits);
  s.limits.push_back({.target = "hand", .quantity = "max safe speed", .unit = "m/s", .value = 0.0,
                      .binding_criterion = "force", .law = "foam", .validity = "within", .note = "no safe value"});
  s.Finish();
  CHECK_FALSE(s.safe);
  CHECK(s.state == VerdictState::kUnsafe);
}

TEST_CASE("ResultSummary: the case with the lowest limit governs a table", "[summary]") {
  ResultSummary s;
  s.kind = ResultSummary::Kind::kLimits;
  s.limits.push_back({.target = "5 kg", .quantity = "max safe speed", .unit = "m/s", .value = 0.8,
                      .binding_criterion = "contusion", .law = "foam", .validity = "within", .note = ""});
  s.limits.push_back({.target = "20 kg", .quantity = "max safe speed", .unit = "m/s", .value = 0.4,
                      .binding_criterion = "laceration", .law = "foam", .validity = "within", .note = ""});
  s.Finish();
  CHECK(s.governing_target == "20 kg");
  CHECK(s.governing_criterion == "laceration");
  CHECK(s.governing_case == "the lowest max safe speed: 0.4 m/s");
  CHECK(std::isnan(s.margin));
}
