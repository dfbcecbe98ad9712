// covopt::Verdict (core/verdict.hpp): the one verdict type. Its governing criterion, margin,
// derated limits, and the separation of the injury verdict from the covering's design rules.

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "covopt/core/verdict.hpp"

using covopt::Criterion;
using covopt::CriterionPart;
using covopt::Verdict;

namespace {

Verdict TwoInjuries(double sf) {
  Verdict v;
  v.safety_factor = sf;
  v.Add("laceration", CriterionPart::kInjury, "Pa", 0.4e6, 1e6, "Park et al. 2011");
  v.Add("contusion", CriterionPart::kInjury, "J/m2", 1.26e4, 2.52e4, "Park et al. 2011");
  return v;
}

}  // namespace

TEST_CASE("Verdict: ratio, derated limit and pass of each criterion", "[verdict]") {
  const Verdict v = TwoInjuries(2.0);
  const Criterion& con = *v.Find("contusion");
  CHECK(con.ratio == Approx(0.5));
  CHECK(con.derated_limit == Approx(1.26e4));  // limit / SF
  CHECK(con.limit == 2.52e4);                  // the standard's limit stays
  CHECK(con.passed);                           // SF × 0.5 = 1: on the derated limit, still within it
  CHECK(v.Find("laceration")->derated_limit == Approx(0.5e6));
  CHECK(v.Find("fracture") == nullptr);
}

TEST_CASE("Verdict: the governing criterion is the counted one with the largest ratio", "[verdict]") {
  Verdict v = TwoInjuries(1.0);
  CHECK(v.governing_name() == "contusion");
  CHECK(v.governing_ratio() == Approx(0.5));
  CHECK(v.margin() == Approx(0.5));
  // A larger ratio that does not count (the paper's criterion) never governs, nor fails the verdict.
  v.Add("full-compression", CriterionPart::kDesignRule, "1", 1.4, 1.0, "the covering's travel", false, true);
  CHECK(v.governing_name() == "contusion");
  CHECK(v.safe());
  CHECK_FALSE(v.Find("full-compression")->passed);
}

TEST_CASE("Verdict: the margin is 1 - SF x governing ratio, negative when exceeded", "[verdict]") {
  const Verdict v = TwoInjuries(2.5);
  CHECK(v.margin() == Approx(1.0 - 2.5 * 0.5));
  CHECK(v.margin() < 0.0);
  CHECK_FALSE(v.safe());
  CHECK_FALSE(v.injury_safe());
  CHECK(v.design_rules_met());  // no design rule: nothing of the covering failed
  CHECK(covopt::FormatPercent(v.margin()) == "-25.0 %");
  CHECK(covopt::FormatPercent(0.588) == "58.8 %");
}

TEST_CASE("Verdict: the covering's design rules are separate from the injury verdict, and safe needs both",
          "[verdict]") {
  Verdict v = TwoInjuries(1.0);
  // A bottomed-out covering: its travel ratio may be small after rounding, the flag fails it.
  v.Add("full-compression", CriterionPart::kDesignRule, "1", 1.02, 1.0, "the covering's travel", true, true);
  CHECK(v.injury_safe());
  CHECK_FALSE(v.design_rules_met());
  CHECK_FALSE(v.safe());
  CHECK(v.governing_name() == "full-compression");
  // A crushed covering alone also fails the design rules, not the injury verdict.
  Verdict crushed = TwoInjuries(1.0);
  crushed.Add("crush", CriterionPart::kDesignRule, "Pa", 3e6, 0.16e6, "the material's compressive strength");
  CHECK(crushed.injury_safe());
  CHECK_FALSE(crushed.design_rules_met());
  CHECK_FALSE(crushed.safe());
  CHECK(crushed.governing_ratio() == Approx(18.75));
}

TEST_CASE("Verdict: an unknown limit counted fails without governing, and a failed evaluation is never safe",
          "[verdict]") {
  Verdict v = TwoInjuries(1.0);
  v.Add("crush", CriterionPart::kDesignRule, "Pa", 1e5, std::numeric_limits<double>::quiet_NaN(),
        "the material's compressive strength", true, true);
  CHECK(v.governing_name() == "contusion");  // the margin stays the ratios'
  CHECK(v.margin() == Approx(0.5));
  CHECK_FALSE(v.Find("crush")->passed);
  CHECK_FALSE(v.design_rules_met());
  CHECK_FALSE(v.safe());

  Verdict failed = TwoInjuries(1.0);
  failed.evaluated = false;
  CHECK_FALSE(failed.safe());
  CHECK(std::isinf(failed.governing_ratio()));
  CHECK(failed.margin() == -std::numeric_limits<double>::infinity());
  CHECK(failed.CountedNames() == std::vector<std::string>{"laceration", "contusion"});
}
