// Robust design over an uncertainty box (optim/robust_design.hpp), checked against brute force
// written out here (ImpactModel::FromScene + ExactPeaks on dense scans and grids):
// - the worst case of a monotone input (head mass: the heavier head) is an end, found among
//   the corners; the worst case of a non-monotone one (the scalp thickness against contusion
//   at the paper's covering, whose maximum lies near 4.7 mm inside 3..6 mm) is interior, the
//   global search finds the brute-force maximum and the corners alone fall short;
// - Monte Carlo against closed forms where the safe set is an interval of head masses (uniform,
//   truncated normal and truncated lognormal draws); the Wilson interval; the inverse normal
//   distribution function (AS 241) against the distribution function;
// - seeds (same seed, same counts; another seed, other counts) and thread counts 1, 2, 7 and
//   block sizes giving bit-identical results; the progress callback;
// - the robust thinnest covering is admissible on a grid over the whole box, is the thinnest
//   (a little thinner fails somewhere in the box), is at least the nominal design, and does
//   not depend on the thread count; the speed and mass limits over the box are the minima of a
//   grid; the probability design meets its target and a thinner covering does not;
// - elasticities against an independent finite difference, the analytic ones (E_c, b_c)
//   against differences too, the tornado order, a kink flagged as unreliable;
// - bad boxes and options are refused with the field, the value and the range.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/optim/covering_design.hpp>
#include <covopt/optim/robust_design.hpp>
#include <covopt/optim/speed_limit.hpp>

using namespace covopt;
using namespace covopt::optim;
using Catch::Matchers::Contains;

namespace {

struct Ratios {
  double laceration = 0.0, contusion = 0.0, compression = 0.0;
  bool fully_compressed = false;
  bool covered = false;
};

/// The exact path written out: FromScene + ExactPeaks, ratios against the default limits.
Ratios RatiosOf(const Scene& scene) {
  const ImpactModel model = ImpactModel::FromScene(scene);
  const ImpactPeaks peaks = ExactPeaks(model);
  Ratios r;
  r.laceration = peaks.max_tensile_stress_Pa / 1e6;
  r.contusion = peaks.max_energy_density_J_per_m2 / 25200.0;
  r.covered = model.has_covering();
  if (r.covered) {
    // The covering's own travel used, beyond the scalp's 0.8 b_s (docs/model.md §6).
    const double t1 = 0.8 * scene.scalp.thickness_m;
    r.compression = std::max(0.0, peaks.max_penetration_m - t1) / (peaks.full_compression_penetration_m - t1);
    r.fully_compressed = peaks.fully_compressed;
  }
  return r;
}

/// g = max(r_L, r_C, r_δ) at safety factor 1 under the default criterion.
double Governing(const Scene& scene) {
  const Ratios r = RatiosOf(scene);
  return std::max({r.laceration, r.contusion, r.covered ? r.compression : 0.0});
}

bool Admissible(const Scene& scene) {
  const Ratios r = RatiosOf(scene);
  return r.laceration <= 1.0 && r.contusion <= 1.0 && !(r.covered && r.fully_compressed);
}

Scene WithCovering(Scene scene, double modulus_Pa, double poisson, double thickness_m) {
  scene.covering = {modulus_Pa, poisson, thickness_m};
  return scene;
}

/// The largest head mass [kg] in [low, high] at which `scene` is admissible, by bisection
/// (admissibility is monotone in the head mass: heavier heads store more energy).
double LargestSafeHeadMass(Scene scene, double low, double high) {
  scene.head.mass_kg = low;
  REQUIRE(Admissible(scene));
  scene.head.mass_kg = high;
  REQUIRE_FALSE(Admissible(scene));
  for (int i = 0; i < 200 && high - low > 1e-13; ++i) {
    scene.head.mass_kg = 0.5 * (low + high);
    (Admissible(scene) ? low : high) = scene.head.mass_kg;
  }
  return low;
}

/// Three moduli for the robust searches' mechanics, declared not to crush (the crush criterion
/// has its own tests, tests/optim/test_crush_criterion.cpp).
std::vector<CandidateMaterial> SomeMaterials() {
  std::vector<CandidateMaterial> materials = {
      {"polystyrene foam 27.6", 27.6e6, 0.22}, {"XPS Foamular 250", 16.71e6, 0.25}, {"EPS geofoam EPS39", 10.3e6, 0.25}};
  for (CandidateMaterial& m : materials) m.crush_behaviour = covopt::materials::CrushBehaviour::kDoesNotCrush;
  return materials;
}

void RequireSameEstimate(const ProbabilityEstimate& a, const ProbabilityEstimate& b) {
  CHECK(a.count == b.count);
  CHECK(a.samples == b.samples);
  CHECK(a.probability == b.probability);
  CHECK(a.ci95_low == b.ci95_low);
  CHECK(a.ci95_high == b.ci95_high);
}

void RequireSameProbability(const InjuryProbability& a, const InjuryProbability& b) {
  RequireSameEstimate(a.laceration, b.laceration);
  RequireSameEstimate(a.contusion, b.contusion);
  RequireSameEstimate(a.any, b.any);
  RequireSameEstimate(a.fully_compressed, b.fully_compressed);
  RequireSameEstimate(a.inadmissible, b.inadmissible);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Distributions and intervals
// ---------------------------------------------------------------------------------------------

TEST_CASE("The inverse normal distribution function inverts the distribution function", "[robust][sampling]") {
  CHECK(InverseStandardNormalCdf(0.5) == 0.0);
  CHECK(InverseStandardNormalCdf(0.975) == Approx(1.959963984540054).epsilon(1e-15));
  CHECK(InverseStandardNormalCdf(0.8413447460685429) == Approx(1.0).epsilon(1e-14));
  CHECK(InverseStandardNormalCdf(1e-10) == Approx(-6.361340902404056).epsilon(1e-14));
  CHECK(InverseStandardNormalCdf(0.0) == -std::numeric_limits<double>::infinity());
  CHECK(InverseStandardNormalCdf(1.0) == std::numeric_limits<double>::infinity());
  CHECK(std::isnan(InverseStandardNormalCdf(-0.1)));
  CHECK(std::isnan(InverseStandardNormalCdf(std::nan(""))));
  // Round trip over the central region and both tails, through all three of AS 241's regions:
  // the error of p is the error of z times the density, so it is judged relative to p's own
  // sensitivity, (1 + |z|) |z| ulp for the tails.
  double worst = 0.0;
  for (double p = 1e-300; p < 0.5; p *= 1.37) {
    const double z = InverseStandardNormalCdf(p);
    const double back = StandardNormalCdf(z);
    worst = std::max(worst, std::abs(back - p) / p / (1.0 + z * z));
  }
  for (int i = 1; i < 1000; ++i) {
    const double p = i / 1000.0;
    const double z = InverseStandardNormalCdf(p);
    worst = std::max(worst, std::abs(StandardNormalCdf(z) - p) / p / (1.0 + z * z));
    CHECK(InverseStandardNormalCdf(1.0 - p) == Approx(-z).margin(1e-13));  // symmetric
  }
  CHECK(worst < 1e-14);
}

TEST_CASE("The Wilson interval matches its textbook values", "[robust][sampling]") {
  const ProbabilityEstimate half = WilsonEstimate(5, 10);
  CHECK(half.probability == 0.5);
  CHECK(half.ci95_low == Approx(0.2365931).epsilon(1e-6));
  CHECK(half.ci95_high == Approx(0.7634069).epsilon(1e-6));
  const ProbabilityEstimate none = WilsonEstimate(0, 10);
  CHECK(none.ci95_low == 0.0);
  CHECK(none.ci95_high == Approx(0.2775328).epsilon(1e-6));  // not empty at p = 0
  const ProbabilityEstimate all = WilsonEstimate(10, 10);
  CHECK(all.ci95_high == 1.0);
  CHECK(all.ci95_low == Approx(1.0 - 0.2775328).epsilon(1e-6));
  CHECK_THROWS_WITH(WilsonEstimate(0, 0), Contains("at least one sample"));
  CHECK_THROWS_WITH(WilsonEstimate(11, 10), Contains("exceeds"));
}

TEST_CASE("Draws are reproducible, inside their ranges and follow their distributions", "[robust][sampling]") {
  const std::vector<UncertainInput> inputs = {
      {"head-mass", 3.7, 5.8},
      {"scalp.thickness", 0.002, 0.005, InputDistribution::kNormal, 0.003, 0.0007},
      {"head-radius", 0.07, 0.09, InputDistribution::kLognormal, 0.08, 0.004},
      {"scalp-modulus", 16.7e6, 16.7e6}};  // a point
  const UncertaintyBox box = UncertaintyBox::FromScene(Scene{}, inputs);
  CHECK(box.inputs()[1].field == "scalp-thickness");  // canonical names
  CHECK(DrawInputs(box, 7, 12345) == DrawInputs(box, 7, 12345));
  CHECK(DrawInputs(box, 7, 12345) != DrawInputs(box, 8, 12345));
  CHECK(DrawInputs(box, 7, 12345) != DrawInputs(box, 7, 12346));
  const int n = 40000;
  std::vector<double> sum(4, 0.0), sum_squares(4, 0.0);
  for (int i = 0; i < n; ++i) {
    const std::vector<double> x = DrawInputs(box, 2011, static_cast<std::uint64_t>(i));
    for (std::size_t j = 0; j < 4; ++j) {
      REQUIRE(x[j] >= inputs[j].low);
      REQUIRE(x[j] <= inputs[j].high);
      sum[j] += x[j];
      sum_squares[j] += x[j] * x[j];
    }
    CHECK(x[3] == 16.7e6);
  }
  auto mean = [&](std::size_t j) { return sum[j] / n; };
  auto sd = [&](std::size_t j) { return std::sqrt(sum_squares[j] / n - mean(j) * mean(j)); };
  // Uniform: mean 4.75, sd 2.1/sqrt(12); 4 standard errors.
  CHECK(std::abs(mean(0) - 4.75) < 4 * 0.6062 / std::sqrt(n));
  CHECK(sd(0) == Approx(2.1 / std::sqrt(12.0)).epsilon(0.01));
  // Truncated normal on [α, β] = [-10/7, 20/7] sd: mean μ + σ (φ(α) − φ(β)) / (Φ(β) − Φ(α)).
  const double alpha = -1.0 / 0.7, beta = 2.0 / 0.7;
  auto phi = [](double z) { return std::exp(-0.5 * z * z) / std::sqrt(2 * M_PI); };
  const double mass = StandardNormalCdf(beta) - StandardNormalCdf(alpha);
  const double truncated_mean = 0.003 + 0.0007 * (phi(alpha) - phi(beta)) / mass;
  CHECK(std::abs(mean(1) - truncated_mean) < 4 * 0.0007 / std::sqrt(n));
  // Lognormal mean 80 mm, sd 4 mm: the truncation at ±2.5 sd barely moves the mean.
  CHECK(std::abs(mean(2) - 0.08) < 4 * 0.004 / std::sqrt(n) + 1e-5);
  CHECK(sd(2) == Approx(0.004).epsilon(0.05));
}

// ---------------------------------------------------------------------------------------------
// Bad boxes
// ---------------------------------------------------------------------------------------------

TEST_CASE("Bad ranges are refused naming the field, the value and the range", "[robust][validation]") {
  const Scene scene;
  auto refuse = [&](std::vector<UncertainInput> inputs, const std::string& words, const Scene& nominal) {
    INFO(words);
    CHECK_THROWS_WITH(UncertaintyBox::FromScene(nominal, inputs), Contains(words));
  };
  auto refuse_default = [&](std::vector<UncertainInput> inputs, const std::string& words) {
    refuse(std::move(inputs), words, scene);
  };
  refuse_default({{"head-mass", 5.8, 3.7}}, "head.mass range 5.8 kg..3.7 kg: low must not exceed high");
  refuse_default({{"head-mass", 3.7, kFixed}}, "head.mass range 3.7 kg..fixed: both ends must be finite");
  refuse_default({{"robot-radius", 0.01, kFlat}}, "both ends must be finite");
  refuse_default({{"head-mass", std::nan(""), 5.0}}, "head.mass range nan..5 kg");
  refuse_default({{"head-volume", 1, 2}}, "no scene quantity 'head-volume'; the quantities are robot-mass");
  refuse_default({{"head-mass", 3.7, 5.8}, {"head.mass", 4, 5}}, "head.mass is given a range twice");
  Scene fixed_head;
  fixed_head.head.mass_kg = kFixed;
  refuse({{"head-mass", 3.7, 5.8}}, "head.mass range 3.7 kg..5.8 kg: the scene holds head.mass at fixed", fixed_head);
  refuse_default({{"covering-thickness", 0.0, 0.005}}, "covering.thickness range 0 mm..5 mm: must not include 0");
  refuse_default({{"head-mass", 4.5, 4.5, InputDistribution::kNormal, 4.5, 0.5}},
                 "head.mass: a normal distribution needs a range (low < high)");
  refuse_default({{"head-mass", 3.7, 5.8, InputDistribution::kNormal, 4.5, 0.0}},
                 "head.mass: the normal standard deviation must be finite and > 0 (got 0 kg)");
  refuse_default({{"head-mass", 3.7, 5.8, InputDistribution::kNormal, 6.5, 0.5}},
                 "head.mass: the normal mean must lie in the range 3.7 kg..5.8 kg (got 6.5 kg)");
  refuse_default({{"robot-poisson", -0.2, 0.4, InputDistribution::kLognormal, 0.3, 0.05}},
                 "robot.poisson: a lognormal distribution needs a range within [0, inf)");
  refuse_default({{"damping", 0.0, 0.2}}, "model.damping cannot be uncertain");
  Scene damped;
  damped.model.damping_s_per_m = 0.1;
  refuse({{"head-mass", 3.7, 5.8}}, "the scene has contact damping or a neck", damped);
  // Corners: the scalp must stay thinner than the head radius everywhere in the box.
  refuse_default({{"head-radius", 0.004, 0.09}, {"scalp-thickness", 0.002, 0.005}},
                 "the box leaves the model's input range at the corner head-radius = 4 mm, scalp-thickness = 5 mm: "
                 "head.radius must be at least scalp.thickness + 0.0001 m");
  refuse_default({{"speed", 0.5, 200}}, "robot.speed must be in [1e-06, 100] m/s (got 200)");
  Scene bad = scene;
  bad.head.radius_m = -1;
  refuse({}, "head.radius must be in [0.0001, 10] m", bad);

  // A valid box: a point range and a normal distribution inside its range.
  const UncertaintyBox box = UncertaintyBox::FromScene(
      scene, std::vector<UncertainInput>{{"head-mass", 4.5, 4.5}, {"speed", 1.5, 2.5, InputDistribution::kNormal, 2.0, 0.2}});
  CHECK(box.size() == 2);
  CHECK(box.Find("robot.speed") != nullptr);
  CHECK(box.Find("head-radius") == nullptr);
  CHECK(box.SceneAt(std::vector<double>{5.0, 1.7}).head.mass_kg == 5.0);
  CHECK_THROWS_WITH(box.SceneAt(std::vector<double>{5.0}), Contains("1 values for 2 uncertain inputs"));

  // Ranges the questions themselves exclude.
  const UncertaintyBox with_speed = UncertaintyBox::FromScene(scene, std::vector<UncertainInput>{{"speed", 1.5, 2.5}});
  CHECK_THROWS_WITH(MaxSafeSpeedOverBox(with_speed), Contains("robot.speed range 1.5 m/s..2.5 m/s: the speed limit is what is computed"));
  const UncertaintyBox with_mass = UncertaintyBox::FromScene(scene, std::vector<UncertainInput>{{"robot-mass", 5, 10}});
  CHECK_THROWS_WITH(MaxSafeMassOverBox(with_mass), Contains("robot.mass range 5 kg..10 kg: the mass limit is what is computed"));
  const UncertaintyBox with_covering =
      UncertaintyBox::FromScene(scene, std::vector<UncertainInput>{{"covering-thickness", 0.01, 0.02}});
  CHECK_THROWS_WITH(FindRobustThinnestCovering(with_covering, SomeMaterials()),
                    Contains("covering.thickness range 10 mm..20 mm: the design chooses the covering"));
  CHECK_THROWS_WITH(FindProbabilityDesign(with_covering, SomeMaterials()), Contains("the design chooses the covering"));
  CHECK_NOTHROW(FindWorstCase(with_covering));  // a thickness tolerance on a given covering is fine

  // Bad options.
  WorstCaseOptions bad_sf;
  bad_sf.safety_factor = 0.5;
  CHECK_THROWS_WITH(FindWorstCase(box, bad_sf), Contains("safety factor must be in [1, 100] (got 0.5)"));
  WorstCaseOptions bad_search;
  bad_search.search.local_starts = 50;
  CHECK_THROWS_WITH(FindWorstCase(box, bad_search), Contains("local starts must be in [0, 20] (got 50)"));
  InjuryProbabilityOptions no_samples;
  no_samples.samples = 0;
  CHECK_THROWS_WITH(EstimateInjuryProbability(box, no_samples), Contains("samples must be in [1, 1e10] (got 0)"));
  const UncertaintyBox head = UncertaintyBox::FromScene(scene, std::vector<UncertainInput>{{"head-mass", 3.7, 5.8}});
  ProbabilityDesignOptions certain;
  certain.max_probability = 1.0;
  CHECK_THROWS_WITH(FindProbabilityDesign(head, SomeMaterials(), certain),
                    Contains("max injury probability must be in (0, 1) (got 1)"));
  ElasticityOptions step;
  step.log_step = 0.5;
  CHECK_THROWS_WITH(ComputeElasticities(scene, step), Contains("log step must be in [1e-6, 0.1] (got 0.5)"));
}

// ---------------------------------------------------------------------------------------------
// Worst case
// ---------------------------------------------------------------------------------------------

TEST_CASE("The worst head mass is the heaviest, and the corners find it", "[robust][worst-case]") {
  const Scene scene;  // the paper's covering
  const UncertaintyBox box = UncertaintyBox::FromScene(scene, std::vector<UncertainInput>{{"head-mass", 3.7, 5.8}});
  // Brute force: g grows with the head mass (the impact energy grows), so the heavier end is the worst.
  double previous = 0.0, brute = 0.0;
  for (int i = 0; i <= 2000; ++i) {
    Scene s = scene;
    s.head.mass_kg = 3.7 + 2.1 * i / 2000;
    const double g = Governing(s);
    CHECK(g >= previous);
    previous = g;
    brute = std::max(brute, g);
  }
  for (bool pinned : {true, false}) {
    WorstCaseOptions options;
    options.search.pin_energy_inputs = pinned;
    const WorstCase worst = FindWorstCase(box, options);
    INFO("pinned " << pinned);
    CHECK(worst.values.at(0) == 5.8);
    CHECK(worst.governing_ratio == brute);
    CHECK(worst.found_by == (pinned ? "pinned" : "corner"));
    CHECK(worst.binding == LimitingCriterion::kContusion);
    CHECK_FALSE(worst.admissible);  // the paper's 15 mm is not safe even at 4.5 kg (docs/model.md §8)
    CHECK(worst.scene.head.mass_kg == 5.8);
    if (!pinned) {
      REQUIRE(worst.corner_governing_ratio);
      CHECK(*worst.corner_governing_ratio == brute);
    }
  }
}

TEST_CASE("An interior worst case: the global search beats the corners", "[robust][worst-case]") {
  // At the paper's covering the contusion ratio rises with the scalp thickness, then falls: its
  // maximum lies near 4.7 mm, inside 3..6 mm.
  const Scene scene;
  const UncertaintyBox box =
      UncertaintyBox::FromScene(scene, std::vector<UncertainInput>{{"scalp-thickness", 0.003, 0.006}});
  double brute = 0.0, argmax = 0.0;
  const int n = 30000;
  for (int i = 0; i <= n; ++i) {
    Scene s = scene;
    s.scalp.thickness_m = 0.003 + 0.003 * i / n;
    const double g = Governing(s);
    if (g > brute) {
      brute = g;
      argmax = s.scalp.thickness_m;
    }
  }
  REQUIRE(argmax > 0.0031);
  REQUIRE(argmax < 0.0059);
  const WorstCase worst = FindWorstCase(box);
  CHECK(worst.governing_ratio >= brute * (1 - 1e-12));  // at least the scan's maximum
  CHECK(worst.governing_ratio <= brute * (1 + 1e-9));   // and the scan resolves it (flat top)
  CHECK(worst.values.at(0) == Approx(argmax).margin(2e-6));
  CHECK(worst.binding == LimitingCriterion::kContusion);
  CHECK((worst.found_by == "global" || worst.found_by == "local"));
  REQUIRE(worst.corner_governing_ratio);
  CHECK(*worst.corner_governing_ratio < worst.governing_ratio * (1 - 0.01));  // the corners miss by > 1 %

  // Two inputs: the heavy head and the interior scalp, against a 101 x 101 grid (searched, not pinned).
  const UncertaintyBox two = UncertaintyBox::FromScene(
      scene, std::vector<UncertainInput>{{"head-mass", 3.7, 5.8}, {"scalp-thickness", 0.002, 0.006}});
  WorstCaseOptions searched;
  searched.search.pin_energy_inputs = false;
  const WorstCase both = FindWorstCase(two, searched);
  double grid = 0.0;
  for (int i = 0; i <= 100; ++i) {
    for (int j = 0; j <= 100; ++j) {
      Scene s = scene;
      s.head.mass_kg = 3.7 + 2.1 * i / 100;
      s.scalp.thickness_m = 0.002 + 0.004 * j / 100;
      grid = std::max(grid, Governing(s));
    }
  }
  CHECK(both.governing_ratio >= grid);
  CHECK(both.values.at(0) == 5.8);
  CHECK(both.values.at(1) > 0.0045);
  CHECK(both.values.at(1) < 0.0055);
  CHECK(*both.corner_governing_ratio < both.governing_ratio * (1 - 0.005));
  const WorstCase pinned = FindWorstCase(two);  // the same maximum with the head mass pinned
  CHECK(pinned.governing_ratio == Approx(both.governing_ratio).epsilon(1e-10));
  CHECK(pinned.evaluations < both.evaluations);
}

// ---------------------------------------------------------------------------------------------
// Probability of injury
// ---------------------------------------------------------------------------------------------

TEST_CASE("Monte Carlo matches the closed-form probability of a head-mass interval", "[robust][probability]") {
  // 18 mm of 16 MPa: contusion reaches its limit at a head mass m* inside 3.7..5.8 kg, and every
  // heavier head is injured: P(injury) = P(m > m*).
  const Scene scene = WithCovering(Scene{}, 16e6, 0.25, 0.018);
  const double lo = 3.7, hi = 5.8;
  const double m_star = LargestSafeHeadMass(scene, lo, hi);
  CHECK(m_star == Approx(5.2).margin(0.1));
  InjuryProbabilityOptions options;
  options.samples = 200000;
  options.threads = 2;
  auto check = [&](const UncertainInput& input, double exact) {
    const UncertaintyBox box = UncertaintyBox::FromScene(scene, std::vector<UncertainInput>{input});
    const InjuryProbability p = EstimateInjuryProbability(box, options);
    INFO(ToString(input.distribution) << ": exact " << exact << ", estimate " << p.any.probability << " ["
                                      << p.any.ci95_low << ", " << p.any.ci95_high << "]");
    CHECK(p.any.ci95_low <= exact);
    CHECK(exact <= p.any.ci95_high);
    const double sigma = std::sqrt(exact * (1 - exact) / static_cast<double>(options.samples));
    CHECK(std::abs(p.any.probability - exact) < 4 * sigma);
    CHECK(p.laceration.count == 0);  // contusion binds first
    CHECK(p.contusion.count == p.any.count);
    CHECK(p.inadmissible.count == p.any.count);  // not fully compressed before contusion
    CHECK(p.any.samples == options.samples);
  };
  check({"head-mass", lo, hi}, (hi - m_star) / (hi - lo));
  // Truncated normal: P = (Φ(β) − Φ(z*)) / (Φ(β) − Φ(α)).
  const double mean = 4.5, sd = 0.6;
  auto cdf = [&](double m) { return StandardNormalCdf((m - mean) / sd); };
  check({"head-mass", lo, hi, InputDistribution::kNormal, mean, sd}, (cdf(hi) - cdf(m_star)) / (cdf(hi) - cdf(lo)));
  // Truncated lognormal (mean and sd of the mass): the same in ln m.
  const double sigma = std::sqrt(std::log1p(sd * sd / (mean * mean))), mu = std::log(mean) - sigma * sigma / 2;
  auto log_cdf = [&](double m) { return StandardNormalCdf((std::log(m) - mu) / sigma); };
  check({"head-mass", lo, hi, InputDistribution::kLognormal, mean, sd},
        (log_cdf(hi) - log_cdf(m_star)) / (log_cdf(hi) - log_cdf(lo)));
}

TEST_CASE("Seeds reproduce, thread counts and blocks do not change a bit", "[robust][probability]") {
  const Scene scene = WithCovering(Scene{}, 16e6, 0.25, 0.0155);
  const UncertaintyBox box = UncertaintyBox::FromScene(
      scene, std::vector<UncertainInput>{{"head-mass", 3.7, 5.8, InputDistribution::kNormal, 4.6, 0.6},
                                         {"scalp-thickness", 0.002, 0.005, InputDistribution::kLognormal, 0.003, 0.0008},
                                         {"head-radius", 0.07, 0.09}});
  InjuryProbabilityOptions options;
  options.samples = 30001;  // not a multiple of any block size
  options.block_samples = 1000;
  options.threads = 1;
  const InjuryProbability one = EstimateInjuryProbability(box, options);
  REQUIRE(one.any.count > options.samples / 10);  // a case with many events of both kinds
  REQUIRE(one.any.count < options.samples * 9 / 10);
  REQUIRE(one.fully_compressed.count > 0);
  for (unsigned threads : {2U, 7U}) {
    options.threads = threads;
    const InjuryProbability many = EstimateInjuryProbability(box, options);
    CHECK(many.threads == threads);
    RequireSameProbability(one, many);
  }
  options.block_samples = 4096;
  options.threads = 3;
  RequireSameProbability(one, EstimateInjuryProbability(box, options));
  options.threads = 1;
  options.block_samples = 1000;
  RequireSameProbability(one, EstimateInjuryProbability(box, options));  // again: the same
  options.seed += 1;
  const InjuryProbability other = EstimateInjuryProbability(box, options);
  CHECK(other.seed == options.seed);
  CHECK(other.any.count != one.any.count);
  CHECK(std::abs(other.any.probability - one.any.probability) < 5 * std::sqrt(0.25 / options.samples));

  // Progress: non-decreasing fractions ending at 1, on the calling thread; an exception stops it.
  std::vector<double> fractions;
  options.threads = 2;
  options.progress = [&](double fraction) { fractions.push_back(fraction); };
  (void)EstimateInjuryProbability(box, options);
  REQUIRE_FALSE(fractions.empty());
  CHECK(std::is_sorted(fractions.begin(), fractions.end()));
  CHECK(fractions.back() == 1.0);
  options.progress = [](double fraction) {
    if (fraction > 0.2) throw std::runtime_error("cancelled");
  };
  CHECK_THROWS_WITH(EstimateInjuryProbability(box, options), "cancelled");
}

// ---------------------------------------------------------------------------------------------
// Robust design and limits
// ---------------------------------------------------------------------------------------------

TEST_CASE("The robust thinnest covering is admissible over the whole box and the thinnest", "[robust][design]") {
  const Scene scene;
  const std::vector<UncertainInput> inputs = {{"head-mass", 3.7, 5.8}, {"scalp-thickness", 0.002, 0.006}};
  const UncertaintyBox box = UncertaintyBox::FromScene(scene, inputs);
  RobustDesignOptions options;
  options.design.threads = 1;
  const RobustThinnestCovering robust = FindRobustThinnestCovering(box, SomeMaterials(), options);
  REQUIRE(robust.verdict == DesignVerdict::kCoveringFound);
  REQUIRE(robust.recommendation == std::size_t{0});
  CHECK_FALSE(robust.bare_robot.admissible);

  // The box on a grid: every point admissible at the answer; the thinnest is thinnest.
  auto admissible_everywhere = [&](const CoveringSpec& covering, int n) {
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; j <= n; ++j) {
        Scene s = scene;
        s.covering = covering;
        s.head.mass_kg = 3.7 + 2.1 * i / n;
        s.scalp.thickness_m = 0.002 + 0.004 * j / n;
        if (!Admissible(s)) return false;
      }
    }
    return true;
  };
  const DesignOptions nominal_options;
  for (const RobustCandidate& c : robust.candidates) {
    const CandidateMaterial& m = c.outcome.material;
    INFO(m.name);
    REQUIRE(c.outcome.safe);
    REQUIRE(c.worst_case_at_thinnest);
    const double thinnest = *c.outcome.min_safe_thickness_m;
    CHECK(admissible_everywhere({m.youngs_modulus_Pa, m.poisson_ratio, *c.outcome.recommended_thickness_m}, 40));
    CHECK(admissible_everywhere({m.youngs_modulus_Pa, m.poisson_ratio, thinnest}, 40));
    // 2 µm thinner, the worst case found at the thinnest is no longer admissible.
    Scene thinner = c.worst_case_at_thinnest->scene;
    thinner.covering.thickness_m = thinnest - 2e-6;
    CHECK_FALSE(Admissible(thinner));
    CHECK(c.worst_case_at_thinnest->governing_ratio == Approx(1.0).margin(1e-3));
    // At least the nominal design of the centre of the box (4.75 kg, 4 mm).
    Scene centre = scene;
    centre.head.mass_kg = 4.75;
    centre.scalp.thickness_m = 0.004;
    const ThinnestSafeCovering nominal = FindThinnestSafeCovering(centre, std::vector<CandidateMaterial>{m}, nominal_options);
    REQUIRE(nominal.candidates.front().min_safe_thickness_m);
    CHECK(thinnest > *nominal.candidates.front().min_safe_thickness_m);
  }
  // The continuous optimum: admissible over the grid, set by a worst case at the heavy head.
  REQUIRE(robust.continuous);
  const RobustContinuousOptimum& optimum = *robust.continuous;
  REQUIRE(optimum.feasible);
  CHECK(admissible_everywhere({optimum.design.youngs_modulus_Pa, 0.25, optimum.design.thickness_m}, 40));
  CHECK(optimum.worst_case.values.at(0) == 5.8);
  CHECK(optimum.worst_case.governing_ratio == Approx(1.0).margin(1e-6));
  CHECK(optimum.design.thickness_m <= *robust.candidates.front().outcome.min_safe_thickness_m);
  Scene thinner = optimum.worst_case.scene;
  thinner.covering.thickness_m -= 1e-6;
  CHECK_FALSE(Admissible(thinner));

  // The same answer on 3 threads.
  options.design.threads = 3;
  const RobustThinnestCovering threaded = FindRobustThinnestCovering(box, SomeMaterials(), options);
  REQUIRE(threaded.candidates.size() == robust.candidates.size());
  for (std::size_t i = 0; i < robust.candidates.size(); ++i) {
    CHECK(threaded.candidates[i].outcome.material.name == robust.candidates[i].outcome.material.name);
    CHECK(threaded.candidates[i].outcome.min_safe_thickness_m == robust.candidates[i].outcome.min_safe_thickness_m);
    CHECK(threaded.candidates[i].worst_case.values == robust.candidates[i].worst_case.values);
  }
}

TEST_CASE("The speed and mass limits over a box are the minima over it", "[robust][limits]") {
  const Scene scene;
  const UncertaintyBox box = UncertaintyBox::FromScene(
      scene, std::vector<UncertainInput>{{"head-mass", 3.7, 5.8}, {"scalp-thickness", 0.002, 0.006}});
  const RobustSpeedLimit speed = MaxSafeSpeedOverBox(box);
  const RobustMassLimit mass = MaxSafeMassOverBox(box);
  CHECK(speed.values.at(0) == 5.8);
  CHECK(mass.values.at(0) == 5.8);
  double grid_speed = std::numeric_limits<double>::infinity(), grid_mass = grid_speed;
  for (int i = 0; i <= 30; ++i) {
    for (int j = 0; j <= 60; ++j) {
      Scene s = scene;
      s.head.mass_kg = 3.7 + 2.1 * i / 30;
      s.scalp.thickness_m = 0.002 + 0.004 * j / 60;
      grid_speed = std::min(grid_speed, MaxSafeSpeed(s).max_safe_speed_m_per_s);
      grid_mass = std::min(grid_mass, MaxSafeMass(s).max_safe_mass_kg);
    }
  }
  CHECK(speed.limit.max_safe_speed_m_per_s <= grid_speed);
  CHECK(speed.limit.max_safe_speed_m_per_s >= grid_speed * (1 - 1e-3));
  CHECK(mass.limit.max_safe_mass_kg <= grid_mass);
  CHECK(mass.limit.max_safe_mass_kg >= grid_mass * (1 - 1e-3));
  // At the limit, the worst scene is at its limit (a ratio binds) and the rest of the box is safe.
  Scene at_limit = speed.scene;
  at_limit.robot.speed_m_per_s = speed.limit.max_safe_speed_m_per_s;
  CHECK(Governing(at_limit) == Approx(1.0).margin(1e-9));
  CHECK(speed.limit.max_safe_speed_m_per_s < MaxSafeSpeed(scene).max_safe_speed_m_per_s);  // below the nominal
}

TEST_CASE("The probability design meets its target on common samples, and a thinner one does not",
          "[robust][probability][design]") {
  const UncertaintyBox box = UncertaintyBox::FromScene(
      Scene{}, std::vector<UncertainInput>{{"head-mass", 3.7, 5.8}, {"scalp-thickness", 0.002, 0.006}});
  ProbabilityDesignOptions options;
  options.sampling.samples = 4000;
  options.sampling.threads = 2;
  options.max_probability = 0.05;
  options.design.thickness_scan_points = 60;
  options.design.bracket_thickness_points = 40;
  options.design.modulus_points_per_decade = 5;
  const std::vector<CandidateMaterial> materials = SomeMaterials();
  const ProbabilityDesign design = FindProbabilityDesign(box, materials, options);
  REQUIRE(design.verdict == DesignVerdict::kCoveringFound);
  CHECK(design.bare_robot.any.probability == 1.0);
  // The target is met on the upper end of the 95 % interval: fewer failures than 5 % of 4000.
  const std::uint64_t allowed = *MostEventsWithUpperBoundWithin(0.05, 4000);
  CHECK(allowed < 200);
  CHECK(design.allowed_failures == allowed);
  InjuryProbabilityOptions sampling = options.sampling;
  for (const ProbabilityCandidate& c : design.candidates) {
    INFO(c.material.name);
    REQUIRE(c.meets_target);
    CHECK(c.at_design.inadmissible.count <= allowed);
    CHECK(c.at_design.inadmissible.ci95_low <= c.at_design.inadmissible.probability);
    // Independently: the same samples (same seed) at the thinnest thickness and just below it.
    const double b = *c.min_thickness_m;
    auto estimate_at = [&](double thickness) {
      const UncertaintyBox at = UncertaintyBox::FromScene(
          WithCovering(Scene{}, c.material.youngs_modulus_Pa, c.material.poisson_ratio, thickness),
          std::vector<UncertainInput>{{"head-mass", 3.7, 5.8}, {"scalp-thickness", 0.002, 0.006}});
      return EstimateInjuryProbability(at, sampling).inadmissible.count;
    };
    CHECK(estimate_at(b) <= allowed);
    CHECK(estimate_at(b - 2 * options.design.thickness_resolution_m) > allowed);
  }
  // Less demanding than the robust design (which allows no injury in the box at all).
  RobustDesignOptions robust_options;
  robust_options.continuous = false;
  const RobustThinnestCovering robust = FindRobustThinnestCovering(box, materials, robust_options);
  for (const ProbabilityCandidate& c : design.candidates) {
    for (const RobustCandidate& r : robust.candidates) {
      if (r.outcome.material.name == c.material.name) CHECK(*c.min_thickness_m < *r.outcome.min_safe_thickness_m);
    }
  }
  REQUIRE(design.continuous);
  CHECK(design.continuous->feasible);
  CHECK(design.continuous->at_design.inadmissible.count <= allowed);
}

// ---------------------------------------------------------------------------------------------
// Sensitivities
// ---------------------------------------------------------------------------------------------

TEST_CASE("Elasticities agree with an independent finite difference", "[robust][sensitivity]") {
  Scene literal;
  literal.model.thresholds = ThresholdReading::kLiteral;
  literal.covering.thickness_m = 0.02;
  for (const Scene& scene : {Scene{}, WithCovering(Scene{}, 16e6, 0.25, 0.018), literal}) {
    const ElasticityTable table = ComputeElasticities(scene);
    REQUIRE(table.compression_ratio);
    REQUIRE(table.rows.size() == 15);  // the conservative fields, all finite and non-zero
    CHECK(table.laceration_ratio == Approx(RatiosOf(scene).laceration).epsilon(1e-15));
    for (const InputElasticity& row : table.rows) {
      INFO(row.field);
      CHECK(row.reliable);
      const SceneField& field = *FindSceneField(row.field);
      // Linear relative steps ±1e-5 x (not in ln x), Richardson-free: error ~1e-9.
      const double x = field.value(scene), h = 1e-5 * x;
      Scene plus = scene, minus = scene;
      field.field(plus) = x + h;
      field.field(minus) = x - h;
      const Ratios rp = RatiosOf(plus), rm = RatiosOf(minus), r0 = RatiosOf(scene);
      CHECK(row.laceration == Approx(x * (rp.laceration - rm.laceration) / (2 * h) / r0.laceration).margin(1e-6));
      CHECK(row.contusion == Approx(x * (rp.contusion - rm.contusion) / (2 * h) / r0.contusion).margin(1e-6));
      REQUIRE(row.compression);
      CHECK(*row.compression == Approx(x * (rp.compression - rm.compression) / (2 * h) / r0.compression).margin(1e-6));
      const bool analytic = row.field == "covering-modulus" || row.field == "covering-thickness";
      CHECK((row.method == DerivativeMethod::kAnalytic) == analytic);
    }
    // Tornado order: by the elasticity of the larger injury ratio (contusion here).
    REQUIRE(table.contusion_ratio > table.laceration_ratio);
    for (std::size_t i = 1; i < table.rows.size(); ++i) {
      CHECK(std::abs(table.rows[i - 1].contusion) >= std::abs(table.rows[i].contusion));
    }
  }
  // The impact energy: r depends on m_r, m_h and v only through ½ μ v², so the elasticities
  // follow d ln E: speed 2, robot mass 2 μ/m_r... exactly in ratio: e_v / e_mr = 2 / (μ/m_r).
  const ElasticityTable paper = ComputeElasticities(Scene{});
  auto row_of = [&](const ElasticityTable& t, const std::string& name) {
    return *std::find_if(t.rows.begin(), t.rows.end(), [&](const InputElasticity& r) { return r.field == name; });
  };
  const double mu = 1.0 / (1.0 / 10.0 + 1.0 / 4.5);
  CHECK(row_of(paper, "speed").contusion / row_of(paper, "robot-mass").contusion == Approx(2.0 / (mu / 10.0)).epsilon(1e-6));
  CHECK(row_of(paper, "speed").contusion / row_of(paper, "head-mass").contusion == Approx(2.0 / (mu / 4.5)).epsilon(1e-6));
  CHECK(std::abs(row_of(paper, "robot-modulus").contusion) < 1e-3);

  // Without a covering: no covering rows, no compression.
  const ElasticityTable bare = ComputeElasticities(WithCovering(Scene{}, 27.6e6, 0.25, 0.0));
  CHECK(bare.rows.size() == 12);
  CHECK_FALSE(bare.compression_ratio);
  for (const InputElasticity& row : bare.rows) CHECK_FALSE(row.compression);

  // At the top of the Poisson range a step up leaves it: one-sided differences, still checked.
  Scene rubber = WithCovering(Scene{}, 5e6, 0.5, 0.02);
  const ElasticityTable one_sided = ComputeElasticities(rubber);
  const InputElasticity nu = row_of(one_sided, "covering-poisson");
  CHECK(nu.method == DerivativeMethod::kOneSidedDifference);
  CHECK(nu.reliable);
  Scene below = rubber;
  below.covering.poisson_ratio = 0.5 * (1 - 1e-5);
  const double back = 0.5 * (RatiosOf(rubber).contusion - RatiosOf(below).contusion) / (0.5e-5) / RatiosOf(rubber).contusion;
  CHECK(nu.contusion == Approx(back).margin(1e-5));

  // A kink: the covering bottoms out (δ_max = t2) between the two steps' reach in the speed.
  Scene at_t2 = WithCovering(Scene{}, 27.6e6, 0.22, 0.015);
  at_t2.robot.speed_m_per_s = 2.52586265789 * std::exp(-3e-4);  // δ_max = t2 at 2.5259 m/s (docs/model.md §8)
  const ElasticityTable kink = ComputeElasticities(at_t2);
  CHECK_FALSE(row_of(kink, "speed").reliable);
  CHECK(row_of(kink, "speed").discrepancy > 1e-3);
  CHECK(row_of(kink, "covering-modulus").reliable);  // analytic
}
