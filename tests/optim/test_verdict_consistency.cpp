// One target, one verdict (issue 34): over a grid of scenes, designs and targets, the verdict of
// `simulate` (optim::SimulationVerdict, the CLI's and Python's call), the speed limit at that
// speed (safe iff speed <= the limit), the design score of `optimize` for that design, the limit
// search's own judgement and the trajectory check at one sample all agree; the head's verdict
// (optim::HeadVerdict) and a body region's (BodyRegionJudgement::verdict) count full compression
// and crush as design rules of the covering, apart from the injury criteria.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/materials/body_regions.hpp>
#include <covopt/materials/catalog.hpp>
#include <covopt/optim/body_region_check.hpp>
#include <covopt/optim/body_region_trajectory.hpp>
#include <covopt/optim/covering_design.hpp>
#include <covopt/optim/oracle.hpp>
#include <covopt/optim/speed_limit.hpp>
#include <covopt/optim/trajectory_check.hpp>
#include <covopt/optim/verdicts.hpp>

using namespace covopt;
using namespace covopt::optim;

namespace {

/// Materials of known crush behaviour: two that crush (a stiff board, a soft bead foam), two that
/// do not (an elastomer, a soft PU foam that bottoms out).
const std::vector<std::string> kMaterials = {"XPS Foamular 250", "EPS geofoam EPS15", "elastomer Shore A40",
                                             "PU foam HR 40/28"};

CandidateMaterial CandidateOf(const materials::Material& m) {
  CandidateMaterial c{m.name, m.youngs_modulus_Pa, materials::PoissonRatioOrDefault(m)};
  c.crush_behaviour = m.crush_behaviour;
  c.compressive_strength_Pa = m.compressive_strength_Pa.value_or(0.0);
  return c;
}

/// Away from the limit by more than rounding: "speed <= limit" is then the verdict.
bool ClearOf(double speed, double limit) { return std::abs(speed / limit - 1.0) > 1e-6; }

}  // namespace

TEST_CASE("The head's verdict agrees across simulate, speed-limit, optimize's score and the trajectory check",
          "[verdict][consistency]") {
  const materials::Catalog& catalog = materials::Catalog::BuiltIn();
  int cases = 0, unsafe = 0, design_rule_only = 0;
  for (const std::string& name : kMaterials) {
    const materials::Material* m = catalog.Find(name);
    REQUIRE(m != nullptr);
    REQUIRE(m->crush_behaviour != materials::CrushBehaviour::kUnknown);
    const CandidateMaterial candidate = CandidateOf(*m);
    for (const double thickness : {0.0, 3e-3, 10e-3, 16e-3}) {
      for (const double mass : {2.0, 5.145, 20.0}) {
        for (const double speed : {0.3, 1.0, 2.3}) {
          for (const double sf : {1.0, 1.5}) {
           // keep: the travel rule as a limit (optimize's design rule, --keep-travel); without it
           // the judging commands' default: injury, the law's validity and crushing.
           for (const bool keep : {true, false}) {
            Scene scene;
            scene.robot.mass_kg = mass;
            scene.robot.speed_m_per_s = speed;
            scene.covering = {candidate.youngs_modulus_Pa, candidate.poisson_ratio, thickness};
            const materials::Material* material = thickness > 0.0 ? m : nullptr;
            const CoveringCrushCheck crush = CrushCheckFor(scene, material, true);
            const ImpactPeaks peaks = SolveExact(ImpactModel::FromScene(scene)).peaks;
            const Verdict simulate = SimulationVerdict(scene, peaks, InjuryLimits{}, sf, crush, false, keep);
            INFO(name << ", " << thickness * 1e3 << " mm, " << mass << " kg, " << speed << " m/s, SF " << sf
                      << (keep ? ", travel kept" : ""));
            ++cases;
            if (!simulate.safe()) ++unsafe;
            if (simulate.injury_safe() && !simulate.design_rules_met()) ++design_rule_only;

            SpeedLimitOptions limit;
            limit.keep_travel = keep;
            limit.safety_factor = sf;
            limit.covering_compressive_strength_Pa = crush.compressive_strength_Pa;
            CHECK(JudgeImpact(scene, limit).admissible == simulate.safe());
            const SpeedLimit v_max = MaxSafeSpeed(scene, limit);
            if (ClearOf(speed, v_max.max_safe_speed_m_per_s)) {
              CHECK(simulate.safe() == (speed <= v_max.max_safe_speed_m_per_s));
            }

            const MotionSample sample{0.0, speed, mass};
            const TrajectoryCheck trajectory = CheckTrajectory(scene, std::span(&sample, 1), {limit});
            REQUIRE(trajectory.samples.size() == 1);
            CHECK(trajectory.samples[0].safe == simulate.safe());
            CHECK(trajectory.samples[0].verdict.governing_name() == simulate.governing_name());
            if (!keep) continue;  // optimize's score keeps the travel rule (its design rule)

            const DesignRule rule{sf, DesignCriterion::kNoFullCompression, false, false};
            const ExactPathOracle oracle(scene, candidate.poisson_ratio);
            DesignScore score = thickness > 0.0
                                    ? oracle.ScoreMaterial({candidate.youngs_modulus_Pa, thickness}, candidate.poisson_ratio)
                                    : oracle.ScoreBare();
            if (thickness > 0.0) CheckCrush(candidate, score);
            CHECK(score.admissible(rule) == simulate.safe());
            const Verdict scored = HeadVerdict(score, InjuryLimits{}, rule, candidate.compressive_strength_Pa);
            CHECK(scored.safe() == simulate.safe());
            CHECK(scored.margin() == Approx(score.margin(rule)).margin(1e-12));
           }
          }
        }
      }
    }
  }
  // The grid is not trivial: unsafe scenes, and scenes that only the covering's design rules fail.
  CHECK(unsafe > cases / 5);
  CHECK(design_rule_only > 0);
}

TEST_CASE("A body region's verdict agrees across its judgement, its speed limit and the trajectory check",
          "[verdict][consistency]") {
  const materials::Catalog& catalog = materials::Catalog::BuiltIn();
  const std::vector<materials::BodyLimits> all =
      materials::BodyRegionTable::BuiltIn().AllLimits(ContactType::kTransient);
  int cases = 0, unsafe = 0, design_rule_only = 0;
  for (std::size_t r = 0; r < all.size(); r += 4) {
    const materials::BodyLimits& limits = all[r];
    for (const std::string& name : kMaterials) {
      const CandidateMaterial candidate = CandidateOf(*catalog.Find(name));
      for (const double thickness : {0.0, 5e-3, 16e-3}) {
        for (const double speed : {0.2, 0.8, 2.0}) {
          for (const double sf : {1.0, 1.2}) {
            BodyContactScene scene;
            scene.robot_mass_kg = 8.0;
            scene.speed_m_per_s = speed;
            scene.robot_radius_m = 0.03;
            scene.covering = {candidate.youngs_modulus_Pa, candidate.poisson_ratio, thickness};
            if (thickness == 0.0) scene.contact_area_m2 = 1e-4;
            const BodyRegionOptions options{DesignRule{sf}, thickness > 0.0 ? std::optional(candidate) : std::nullopt,
                                            /*keep_travel=*/true};
            INFO(limits.Describe() << ", " << name << ", " << thickness * 1e3 << " mm, " << speed << " m/s, SF " << sf);
            const BodyRegionJudgement j = JudgeBodyContact(scene, limits, options);
            ++cases;
            CHECK(j.admissible == j.verdict.safe());
            CHECK(j.margin == j.verdict.margin());
            CHECK(j.verdict.governing_name() == ToString(j.governing));
            if (!j.admissible) ++unsafe;
            if (j.verdict.injury_safe() && !j.verdict.design_rules_met()) ++design_rule_only;
            // Every criterion's derated limit is its limit / SF, but the law's validity (the model's range).
            for (const Criterion& c : j.verdict.criteria) {
              if (c.name != covopt::kLawValidityRule) CHECK(c.derated_limit == Approx(c.limit / sf));
            }

            const BodyRegionSpeedLimit v_max = MaxSafeSpeed(scene, limits, options);
            if (ClearOf(speed, v_max.max_safe_speed_m_per_s)) {
              CHECK(j.admissible == (speed <= v_max.max_safe_speed_m_per_s));
            }
            const MotionSample sample{0.0, speed, scene.robot_mass_kg};
            const BodyRegionTrajectoryCheck t =
                CheckTrajectoryForBodyRegions(scene, std::span(&limits, 1), std::span(&sample, 1), options);
            CHECK(t.samples.at(0).safe == j.admissible);
          }
        }
      }
    }
  }
  CHECK(unsafe > cases / 5);
  CHECK(design_rule_only > 0);
}
