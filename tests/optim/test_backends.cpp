// The NLopt and Ipopt backends on textbook problems, no physics: Rosenbrock (unconstrained,
// minimum at (1, 1)) and Hock-Schittkowski 71 (one inequality, one equality; minimum
// f* = 17.0140173 at (1, 4.7429994, 3.8211503, 1.3794082)). Also: a failing evaluation is
// counted and survived, an exception thrown by an evaluation comes back out after the solver
// stopped, and bad input is a status, not a crash.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include <covopt/optim/backends.hpp>

using namespace covopt::optim;

namespace {

class Rosenbrock : public Problem {
 public:
  std::size_t dimension() const override { return 2; }
  std::vector<double> lower_bounds() const override { return {-2.0, -2.0}; }
  std::vector<double> upper_bounds() const override { return {2.0, 2.0}; }
  bool Objective(std::span<const double> x, double& value, std::span<double> g) const override {
    const double a = 1 - x[0], b = x[1] - x[0] * x[0];
    value = a * a + 100 * b * b;
    if (!g.empty()) {
      g[0] = -2 * a - 400 * x[0] * b;
      g[1] = 200 * b;
    }
    return true;
  }
};

/// HS071: min x1 x4 (x1 + x2 + x3) + x3, x1 x2 x3 x4 >= 25, Σ x_i² = 40, 1 <= x_i <= 5.
class Hs071 : public Problem {
 public:
  std::size_t dimension() const override { return 4; }
  std::size_t inequality_count() const override { return 1; }
  std::size_t equality_count() const override { return 1; }
  std::vector<double> lower_bounds() const override { return {1, 1, 1, 1}; }
  std::vector<double> upper_bounds() const override { return {5, 5, 5, 5}; }
  bool Objective(std::span<const double> x, double& value, std::span<double> g) const override {
    value = x[0] * x[3] * (x[0] + x[1] + x[2]) + x[2];
    if (!g.empty()) {
      g[0] = x[3] * (2 * x[0] + x[1] + x[2]);
      g[1] = x[0] * x[3];
      g[2] = x[0] * x[3] + 1;
      g[3] = x[0] * (x[0] + x[1] + x[2]);
    }
    return true;
  }
  bool Constraints(std::span<const double> x, std::span<double> c, std::span<double> j) const override {
    c[0] = 25 - x[0] * x[1] * x[2] * x[3];
    c[1] = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3] - 40;
    if (!j.empty()) {
      j[0] = -x[1] * x[2] * x[3];
      j[1] = -x[0] * x[2] * x[3];
      j[2] = -x[0] * x[1] * x[3];
      j[3] = -x[0] * x[1] * x[2];
      for (int i = 0; i < 4; ++i) j[4 + i] = 2 * x[i];
    }
    return true;
  }
};

/// HS071's Lagrangian Hessian, written out: σ ∇²f + λ_0 ∇²c_0 + λ_1 ∇²c_1, lower triangle.
std::vector<double> Hs071Hessian(const std::vector<double>& x, double sigma, const std::vector<double>& lambda) {
  const double full[4][4] = {
      {sigma * 2 * x[3] + 2 * lambda[1], sigma * x[3] - lambda[0] * x[2] * x[3],
       sigma * x[3] - lambda[0] * x[1] * x[3], sigma * (2 * x[0] + x[1] + x[2]) - lambda[0] * x[1] * x[2]},
      {0, 2 * lambda[1], -lambda[0] * x[0] * x[3], sigma * x[0] - lambda[0] * x[0] * x[2]},
      {0, 0, 2 * lambda[1], sigma * x[0] - lambda[0] * x[0] * x[1]},
      {0, 0, 0, 2 * lambda[1]}};
  std::vector<double> lower;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c <= r; ++c) lower.push_back(full[c][r]);  // upper triangle stored: (c, r), c <= r
  }
  return lower;
}

/// HS071 with its Hessian by central differences of its gradients.
class Hs071WithHessian : public Hs071 {
 public:
  bool provides_lagrangian_hessian() const override { return true; }
  bool LagrangianHessian(std::span<const double> x, double sigma, std::span<const double> lambda,
                         std::span<double> lower) const override {
    ++hessian_evaluations;
    return CentralDifferenceLagrangianHessian(*this, x, sigma, lambda, lower);
  }
  mutable long hessian_evaluations = 0;
};

const double kHs071Optimum = 17.0140173;
const std::vector<double> kHs071Start = {1, 5, 5, 1};

/// Rosenbrock that fails (returns false) in a strip and throws when asked to.
class Faulty : public Rosenbrock {
 public:
  bool throw_now = false;
  bool Objective(std::span<const double> x, double& value, std::span<double> g) const override {
    if (throw_now) throw std::runtime_error("oracle exploded");
    if (x[0] > 1.5) return false;
    return Rosenbrock::Objective(x, value, g);
  }
};

}  // namespace

TEST_CASE("Ipopt solves Rosenbrock", "[backend][ipopt]") {
  const SolveResult r = SolveWithIpopt(Rosenbrock{}, std::vector<double>{-1.2, 1.0});
  INFO(r.report.raw_name);
  REQUIRE(r.is_usable());
  CHECK(r.report.termination == Termination::kConverged);
  CHECK(r.x[0] == Approx(1.0).margin(1e-6));
  CHECK(r.x[1] == Approx(1.0).margin(1e-6));
  CHECK(r.report.objective_evaluations > 0);
}

TEST_CASE("Ipopt solves HS071", "[backend][ipopt]") {
  const SolveResult r = SolveWithIpopt(Hs071{}, kHs071Start);
  INFO(r.report.raw_name);
  REQUIRE(r.is_usable());
  CHECK(r.report.termination == Termination::kConverged);
  CHECK(r.objective == Approx(kHs071Optimum).epsilon(1e-7));
  CHECK(r.max_violation < 1e-7);  // Σx² = 40: 1e-7 is 2.5e-9 relative
}

TEST_CASE("the central-difference Lagrangian Hessian matches HS071's analytic one",
          "[backend][hessian]") {
  const Hs071 problem;
  for (const std::vector<double>& x : {std::vector<double>{1, 5, 5, 1}, std::vector<double>{1.3, 4.1, 3.2, 2.7}}) {
    for (const std::vector<double>& lambda : {std::vector<double>{0.0, 0.0}, std::vector<double>{0.55, -0.16}}) {
      const double sigma = 0.8;
      std::vector<double> numeric(10);
      REQUIRE(CentralDifferenceLagrangianHessian(problem, x, sigma, lambda, numeric));
      const std::vector<double> exact = Hs071Hessian(x, sigma, lambda);
      for (std::size_t e = 0; e < exact.size(); ++e) {
        INFO("entry " << e);
        CHECK(numeric[e] == Approx(exact[e]).margin(1e-7));  // f is cubic: only rounding remains
      }
    }
  }
  // Wrong sizes are refused, not read past.
  std::vector<double> too_short(9);
  CHECK_FALSE(CentralDifferenceLagrangianHessian(problem, std::vector<double>{1, 5, 5, 1},
                                                 1.0, std::vector<double>{0, 0}, too_short));
}

TEST_CASE("Ipopt uses a problem's Lagrangian Hessian: same HS071 optimum, fewer iterations than L-BFGS",
          "[backend][ipopt][hessian]") {
  const Hs071WithHessian exact_problem;
  const SolveResult exact = SolveWithIpopt(exact_problem, kHs071Start);
  INFO(exact.report.raw_name);
  REQUIRE(exact.is_usable());
  CHECK(exact.report.termination == Termination::kConverged);
  CHECK(exact.objective == Approx(kHs071Optimum).epsilon(1e-7));
  CHECK(exact_problem.hessian_evaluations > 0);

  IpoptOptions lbfgs_options;
  lbfgs_options.limited_memory_hessian = true;
  const Hs071WithHessian approximated_problem;
  const SolveResult approximated = SolveWithIpopt(approximated_problem, kHs071Start, lbfgs_options);
  REQUIRE(approximated.is_usable());
  CHECK(approximated_problem.hessian_evaluations == 0);
  CHECK(approximated.objective == Approx(kHs071Optimum).epsilon(1e-7));
  CHECK(exact.report.gradient_evaluations < approximated.report.gradient_evaluations);
  for (std::size_t i = 0; i < 4; ++i) CHECK(exact.x[i] == Approx(approximated.x[i]).margin(1e-6));
}

TEST_CASE("NLopt global and local algorithms solve Rosenbrock", "[backend][nlopt]") {
  for (NloptAlgorithm algorithm : {NloptAlgorithm::kDirectL, NloptAlgorithm::kMlsl,
                                   NloptAlgorithm::kLbfgs, NloptAlgorithm::kSlsqp}) {
    NloptOptions options;
    options.algorithm = algorithm;
    options.max_evaluations = algorithm == NloptAlgorithm::kDirectL ? 20000 : 5000;
    const SolveResult r = SolveWithNlopt(Rosenbrock{}, std::vector<double>{-1.2, 1.0}, options);
    INFO(ToString(algorithm) << ": " << r.report.raw_name << " f " << r.objective);
    REQUIRE(r.is_usable());
    CHECK(r.objective < 1e-4);
    CHECK(r.x[0] == Approx(1.0).margin(1e-2));
  }
}

TEST_CASE("NLopt solves HS071 with native and with penalised constraints", "[backend][nlopt]") {
  NloptOptions slsqp;
  slsqp.algorithm = NloptAlgorithm::kSlsqp;
  slsqp.relative_x_tolerance = 1e-10;
  const SolveResult local = SolveWithNlopt(Hs071{}, kHs071Start, slsqp);
  INFO(local.report.raw_name);
  REQUIRE(local.is_usable());
  CHECK(local.objective == Approx(kHs071Optimum).epsilon(1e-6));
  CHECK(local.max_violation < 1e-7);

  NloptOptions isres;
  isres.algorithm = NloptAlgorithm::kIsres;
  isres.max_evaluations = 60000;
  isres.constraint_tolerance = 1e-4;
  const SolveResult global = SolveWithNlopt(Hs071{}, kHs071Start, isres);
  REQUIRE(global.is_usable());
  CHECK(global.objective == Approx(kHs071Optimum).epsilon(2e-2));

  // Global result polished by Ipopt: the intended pipeline.
  const SolveResult polished = SolveWithIpopt(Hs071{}, global.x);
  CHECK(polished.objective == Approx(kHs071Optimum).epsilon(1e-7));
}

TEST_CASE("Seeded stochastic searches are reproducible", "[backend][nlopt]") {
  NloptOptions options;
  options.algorithm = NloptAlgorithm::kIsres;
  options.max_evaluations = 3000;
  const SolveResult a = SolveWithNlopt(Hs071{}, kHs071Start, options);
  const SolveResult b = SolveWithNlopt(Hs071{}, kHs071Start, options);
  CHECK(a.x == b.x);
}

TEST_CASE("Failed evaluations are counted and survived", "[backend][failure]") {
  const Faulty faulty;
  NloptOptions options;
  options.max_evaluations = 3000;
  const SolveResult n = SolveWithNlopt(faulty, std::vector<double>{-1.2, 1.0}, options);
  CHECK(n.report.failed_evaluations > 0);
  REQUIRE(n.is_usable());
  CHECK(n.x[0] == Approx(1.0).margin(2e-2));
  const SolveResult i = SolveWithIpopt(faulty, std::vector<double>{-1.2, 1.0});
  CHECK(i.is_usable());
  CHECK(i.x[0] == Approx(1.0).margin(1e-5));
}

TEST_CASE("An exception in an evaluation is rethrown after the solver stopped", "[backend][failure]") {
  Faulty faulty;
  faulty.throw_now = true;
  CHECK_THROWS_WITH(SolveWithNlopt(faulty, std::vector<double>{0, 0}), "oracle exploded");
  CHECK_THROWS_WITH(SolveWithIpopt(faulty, std::vector<double>{0, 0}), "oracle exploded");
}

TEST_CASE("Bad input is an invalid-problem status", "[backend][failure]") {
  const SolveResult n = SolveWithNlopt(Rosenbrock{}, std::vector<double>{0.0});
  CHECK(n.report.termination == Termination::kInvalidProblem);
  CHECK_FALSE(n.is_usable());
  const SolveResult i = SolveWithIpopt(Rosenbrock{}, std::vector<double>{0.0, 0.0, 0.0});
  CHECK(i.report.termination == Termination::kInvalidProblem);
}
