// Forced failures of NLopt and Ipopt (issue 6): an oracle that returns NaN everywhere, NaN
// only in its gradient or constraints, or throws after some evaluations; an Ipopt that cannot
// run. Each must come back as the backend's status (raw code and name kept), the exception
// rethrown after the C solver has returned, and the design searches must take their
// documented fallback (the global point is kept and the report says why). Under
// COVOPT_SANITIZE these are also the leak checks of the failure paths.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/core/scene.hpp>
#include <covopt/optim/backends.hpp>
#include <covopt/optim/covering_design.hpp>

using namespace covopt::optim;
using Catch::Matchers::Contains;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// A bowl, min at (0.3, -0.2), whose evaluations can be made to fail in several ways.
class Sabotaged : public Problem {
 public:
  enum class Mode { kNone, kNanObjective, kNanGradient, kNanConstraint, kThrowAfter };
  explicit Sabotaged(Mode mode, long throw_after = 0, bool constrained = false)
      : mode_(mode), throw_after_(throw_after), constrained_(constrained) {}

  std::size_t dimension() const override { return 2; }
  std::size_t inequality_count() const override { return constrained_ ? 1 : 0; }
  std::vector<double> lower_bounds() const override { return {-1.0, -1.0}; }
  std::vector<double> upper_bounds() const override { return {1.0, 1.0}; }
  bool Objective(std::span<const double> x, double& value, std::span<double> g) const override {
    if (mode_ == Mode::kThrowAfter && ++calls_ > throw_after_) {
      throw std::runtime_error("oracle gave up after " + std::to_string(throw_after_) + " calls");
    }
    const double a = x[0] - 0.3, b = x[1] + 0.2;
    value = mode_ == Mode::kNanObjective ? kNaN : a * a + 2 * b * b;
    if (!g.empty()) {
      g[0] = mode_ == Mode::kNanGradient ? kNaN : 2 * a;
      g[1] = 4 * b;
    }
    return true;
  }
  bool Constraints(std::span<const double> x, std::span<double> values,
                   std::span<double> jacobian) const override {
    // x0 + x1 <= 0.5 (inactive at the minimum).
    values[0] = mode_ == Mode::kNanConstraint ? kNaN : x[0] + x[1] - 0.5;
    if (!jacobian.empty()) {
      jacobian[0] = 1.0;
      jacobian[1] = 1.0;
    }
    return true;
  }

 private:
  Mode mode_;
  long throw_after_;
  bool constrained_;
  mutable long calls_ = 0;
};

using Mode = Sabotaged::Mode;
const std::vector<double> kStart = {-0.5, 0.5};

void CheckReportNamesTheBackend(const SolveResult& r) {
  CHECK_FALSE(r.report.backend.empty());
  CHECK_FALSE(r.report.raw_name.empty());
}

}  // namespace

TEST_CASE("NLopt: an objective that is NaN everywhere is an evaluation failure",
          "[backend][faults][nlopt]") {
  for (const NloptAlgorithm algorithm :
       {NloptAlgorithm::kDirectL, NloptAlgorithm::kIsres, NloptAlgorithm::kMlsl,
        NloptAlgorithm::kCobyla, NloptAlgorithm::kSlsqp, NloptAlgorithm::kLbfgs}) {
    CAPTURE(ToString(algorithm));
    NloptOptions options;
    options.algorithm = algorithm;
    options.max_evaluations = 200;
    const SolveResult r = SolveWithNlopt(Sabotaged(Mode::kNanObjective), kStart, options);
    CheckReportNamesTheBackend(r);
    CHECK(r.report.termination == Termination::kEvaluationFailure);
    CHECK(r.report.objective_evaluations > 0);
    CHECK(r.report.failed_evaluations == r.report.objective_evaluations);
    CHECK_FALSE(r.is_usable());
  }
}

TEST_CASE("NLopt: a NaN gradient or constraint is a counted failure, not a crash",
          "[backend][faults][nlopt]") {
  NloptOptions options;
  options.algorithm = NloptAlgorithm::kSlsqp;
  options.max_evaluations = 200;
  const SolveResult gradient = SolveWithNlopt(Sabotaged(Mode::kNanGradient), kStart, options);
  CheckReportNamesTheBackend(gradient);
  CHECK(gradient.report.failed_evaluations > 0);
  CHECK(gradient.report.termination != Termination::kConverged);

  options.algorithm = NloptAlgorithm::kCobyla;
  const SolveResult constraint =
      SolveWithNlopt(Sabotaged(Mode::kNanConstraint, 0, /*constrained=*/true), kStart, options);
  CheckReportNamesTheBackend(constraint);
  CHECK(constraint.report.failed_evaluations > 0);
  CHECK((std::isfinite(constraint.objective) || !constraint.is_usable()));
}

TEST_CASE("Ipopt: NaN in the objective, gradient or constraints is Ipopt's own failure status",
          "[backend][faults][ipopt]") {
  struct Case {
    Mode mode;
    bool constrained;
  };
  for (const Case c : {Case{Mode::kNanObjective, false}, Case{Mode::kNanGradient, false},
                       Case{Mode::kNanConstraint, true}}) {
    CAPTURE(static_cast<int>(c.mode));
    const SolveResult r = SolveWithIpopt(Sabotaged(c.mode, 0, c.constrained), kStart);
    CheckReportNamesTheBackend(r);
    CAPTURE(r.report.raw_name, r.report.raw_code);
    CHECK(r.report.backend == "ipopt");
    CHECK(r.report.failed_evaluations > 0);
    CHECK(r.report.termination != Termination::kConverged);
    CHECK_FALSE(r.is_usable());
    CHECK(r.report.raw_code < 0);  // an Ipopt ApplicationReturnStatus error code
  }
}

TEST_CASE("an oracle that throws mid-run: NLopt and Ipopt stop, the exception comes back",
          "[backend][faults]") {
  for (const NloptAlgorithm algorithm :
       {NloptAlgorithm::kDirectL, NloptAlgorithm::kCobyla, NloptAlgorithm::kLbfgs}) {
    CAPTURE(ToString(algorithm));
    NloptOptions options;
    options.algorithm = algorithm;
    options.max_evaluations = 500;
    const Sabotaged oracle(Mode::kThrowAfter, 7);
    CHECK_THROWS_WITH(SolveWithNlopt(oracle, kStart, options), "oracle gave up after 7 calls");
  }
  const Sabotaged oracle(Mode::kThrowAfter, 3);
  CHECK_THROWS_WITH(SolveWithIpopt(oracle, kStart), "oracle gave up after 3 calls");
  // The backends are usable again afterwards (Ipopt's mutex was released, NLopt freed).
  const SolveResult again = SolveWithIpopt(Sabotaged(Mode::kNone), kStart);
  REQUIRE(again.is_usable());
  CHECK(again.x[0] == Approx(0.3).margin(1e-6));
  NloptOptions options;
  options.algorithm = NloptAlgorithm::kLbfgs;
  const SolveResult nlopt_again = SolveWithNlopt(Sabotaged(Mode::kNone), kStart, options);
  REQUIRE(nlopt_again.is_usable());
  CHECK(nlopt_again.x[1] == Approx(-0.2).margin(1e-5));
}

TEST_CASE("Ipopt with options it rejects is an invalid-problem status with Ipopt's name",
          "[backend][faults][ipopt]") {
  IpoptOptions options;
  options.tolerance = -1.0;  // an impossible tolerance
  const SolveResult r = SolveWithIpopt(Sabotaged(Mode::kNone), kStart, options);
  CheckReportNamesTheBackend(r);
  CAPTURE(r.report.raw_name);
  CHECK(r.report.termination == Termination::kInvalidProblem);
  CHECK_FALSE(r.is_usable());
}

TEST_CASE("design searches keep the bracketed point when Ipopt fails, and say so",
          "[design][faults]") {
  const std::vector<CandidateMaterial> materials = {{"foam A", 27.6e6, 0.22, false}};
  DesignOptions broken;
  broken.ipopt.tolerance = -1.0;  // Ipopt refuses to run
  const ThinnestSafeCovering thinnest = FindThinnestSafeCovering(covopt::Scene{}, materials, broken);
  CHECK(thinnest.continuous.local.backend == "ipopt");
  CHECK(thinnest.continuous.local.termination == Termination::kInvalidProblem);
  CHECK_THAT(thinnest.continuous.source, Contains("bracket (ipopt ended invalid-problem"));
  CHECK_THAT(thinnest.continuous.source, Contains(thinnest.continuous.local.raw_name));
  // The answer comes from the stage that worked: the bracketed search, admissible on the
  // exact path and as thin as the polished optimum to the bracket's resolution.
  const ThinnestSafeCovering polished = FindThinnestSafeCovering(covopt::Scene{}, materials);
  REQUIRE(polished.continuous.source == "ipopt");
  CHECK(thinnest.continuous.feasible);
  CHECK(thinnest.continuous.bracket.termination == Termination::kConverged);
  const double fallback_b = thinnest.continuous.score.design.thickness_m;
  const double polished_b = polished.continuous.score.design.thickness_m;
  CHECK(fallback_b == Approx(polished_b).margin(1e-10));
  CHECK(thinnest.continuous.score.admissible(1.0, DesignCriterion::kNoFullCompression));
  // The catalog snap does not depend on the continuous stage.
  REQUIRE(thinnest.candidates.size() == 1);
  CHECK(thinnest.candidates[0].recommended_thickness_m == polished.candidates[0].recommended_thickness_m);

  const LeastInjuryAtThickness at = MinimizeInjuryAtThickness(covopt::Scene{}, 0.01, materials, broken);
  CHECK(at.continuous.local.termination == Termination::kInvalidProblem);
  CHECK_THAT(at.continuous.source, Contains("(ipopt ended invalid-problem"));
  CHECK(std::isfinite(at.continuous.score.worst_ratio()));
}
