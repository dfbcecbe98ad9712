#pragma once
/// @file design.hpp
/// The whole design request of `covopt optimize` as one library call: a scene, the candidate
/// materials (from a catalog, by name or family, or given directly), the design options, and
/// optionally a fixed thickness; the answer is a DesignResult value with the verdict, the
/// recommendation, the continuous optimum, every candidate, the stages' reports and the
/// warnings a safety engineer must read. Nothing is printed; the CLI and the Python module
/// format this value.
///
///     covopt::optim::DesignRequest request;            // the paper's scene, every catalog material
///     request.scene.robot.speed_m_per_s = 1.5;
///     request.materials = covopt::optim::SelectCandidates(covopt::materials::Catalog::BuiltIn());
///     const covopt::optim::DesignResult design = covopt::optim::Design(request);
///     if (design.recommendation) { const auto& best = design.candidates[*design.recommendation]; }

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <covopt/core/scene.hpp>
#include <covopt/materials/catalog.hpp>

#include "covopt/optim/covering_design.hpp"
#include "covopt/optim/material_range.hpp"

namespace covopt::optim {

/// Which question a design request asks.
enum class DesignProblem {
  kThinnestSafeCovering,    ///< the thinnest admissible covering (problem a)
  kLeastInjuryAtThickness,  ///< the least injury at a given thickness (problem b)
};
/// "thinnest-safe-covering" or "least-injury-at-thickness".
std::string_view ToString(DesignProblem problem) noexcept;

/// Everything `covopt optimize` is asked.
struct DesignRequest {
  /// The scene (SI); its covering is what is designed and is ignored. Default: the paper's.
  Scene scene;
  /// The discrete choices, in catalog order (SelectCandidates). Default: none (the
  /// continuous optimum alone).
  std::vector<CandidateMaterial> materials;
  /// Set: problem (b), the least injury at this thickness [m], in (0, 1]. Default: empty,
  /// problem (a).
  std::optional<double> thickness_m;
  /// Search space, criterion, safety factor, limits, solver settings. Default: DesignOptions{}.
  DesignOptions options;
};

/// How the request ended. A scene where nothing is admissible is kSuccess (an answer).
enum class DesignStatus {
  kSuccess,       ///< the answer below is usable (its verdict may be "nothing is safe")
  /// The oracle failed where the answer needs it (the bare robot, or every design the
  /// continuous search tried): time-path integrations that did not succeed (OracleReport).
  kOracleFailed,
};
/// "success", "oracle-failed".
std::string_view ToString(DesignStatus status) noexcept;

/// The answer to a DesignRequest.
struct DesignResult {
  DesignStatus status = DesignStatus::kSuccess;
  /// One sentence answering the question, e.g. "Recommended: XPS Foamular 250 at 16.00 mm."
  std::string message;
  DesignProblem problem = DesignProblem::kThinnestSafeCovering;
  DesignCriterion criterion = DesignCriterion::kNoFullCompression;
  /// Every criterion the verdicts apply (injury, full compression, crush) and the safety factor.
  DesignRule rule;
  /// What the verdicts cover and what they do not, one sentence each: the criteria (Park et
  /// al.'s skin model for the head), and that ISO/TS 15066 (A.3.2) permits no transient
  /// contact with the skull, forehead or face, with its quasi-static limits (HeadStandardNote).
  std::vector<std::string> scope;
  DesignVerdict verdict = DesignVerdict::kNothingSafe;
  /// The thickness of problem (b) [m]; empty for problem (a).
  std::optional<double> thickness_m;
  DesignScore bare_robot;
  ContinuousOptimum continuous;
  /// Admissible candidates first (problem a: by stock thickness, then margin; problem b: by
  /// margin), then the others by margin.
  std::vector<CandidateOutcome> candidates;
  /// Index into `candidates` of the recommendation, when one is admissible.
  std::optional<std::size_t> recommendation;
  /// What the answer's reader must know: a stage that failed (with its status and the
  /// fallback taken), failed oracle evaluations, a recommendation or optimum fully compressed
  /// (paper's criterion), the recommended design's validity warnings (docs/model.md §7).
  std::vector<std::string> warnings;
  long evaluations = 0;  ///< oracle evaluations in all stages
  double seconds = 0.0;  ///< wall time [s]
  /// Which oracle scored the designs (exact or time path), why, with which integrator and
  /// gradient, and how many of its evaluations failed.
  OracleReport oracle;
  /// The default answer (material_range.hpp, design_answer.hpp): the recommended material's
  /// verdicts over its stated uncertainty at the recommended thickness; empty without one.
  std::optional<MaterialRangeCheck> material_range;
  /// Per candidate (in `candidates`' order): how its stated uncertainty changed it (a thicker
  /// layer, or not admissible over its range, and why); empty for the others.
  std::vector<std::string> range_notes;
  /// No catalog material is admissible over its range: what would make the nearest one work.
  std::optional<NearestChanges> nearest_changes;
  /// The bare robot is safe: no covering is needed (the continuous optimum is not a design
  /// anyone needs then).
  bool covering_needed() const noexcept { return verdict != DesignVerdict::kBareRobotSafe; }
  bool ok() const noexcept { return status == DesignStatus::kSuccess; }
  /// One line: verdict, recommendation or best worst ratio, continuous optimum, evaluations
  /// and the oracle.
  std::string BriefReport() const;
};

/// One catalog material as a candidate: its Poisson ratio or materials::kDefaultPoissonRatio
/// (poisson_assumed), its family, crush behaviour and compressive strength (0 when unknown).
CandidateMaterial CandidateOf(const materials::Material& material);

/// Candidate materials from a catalog: the entries named in `names` (catalog names, compared
/// ignoring case, in the order given) or, when `names` is empty, every entry in catalog order;
/// then only those of the `families` (ignoring case), when any are given. A material without a
/// Poisson ratio gets materials::kDefaultPoissonRatio and poisson_assumed.
/// @throws std::invalid_argument for an unknown name ("no material 'X' in the catalog; did you
///         mean 'Y'?") or family ("no family 'X' in the catalog (families: ...)").
std::vector<CandidateMaterial> SelectCandidates(const materials::Catalog& catalog,
                                                std::span<const std::string> names = {},
                                                std::span<const std::string> families = {});

/// Under `law` foam, drops the candidates without a compressive curve (the foam law needs one);
/// under auto and hertz, keeps every candidate.
void KeepCandidatesForLaw(std::vector<CandidateMaterial>& candidates, CoveringLaw law);

/// Under `law` auto, on a scene the foam law does not model (a braking robot, a neck, contact
/// damping, literal thresholds: docs/model.md §16), drops the candidates with a curve and
/// returns one warning saying how many and why ("--covering-law hertz reads them with the Hertz
/// law"); otherwise keeps every candidate and returns nothing. (Under foam such a scene is
/// refused by the design, naming the field.)
std::vector<std::string> KeepCandidatesTheSceneModels(std::vector<CandidateMaterial>& candidates, CoveringLaw law,
                                                      const Scene& scene);

/// Runs the request: problem (a) or (b), the catalog snap, the verdict and the warnings, on
/// the oracle request.options.oracle chooses (ChooseOracle).
/// @throws std::invalid_argument naming the field for bad input (scene, options, thickness),
///         or for oracle exact on a scene with braking or a neck.
DesignResult Design(const DesignRequest& request);

}  // namespace covopt::optim
