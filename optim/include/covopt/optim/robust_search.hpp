#pragma once
/// @file robust_search.hpp
/// The global search over an uncertainty box (robust_design.hpp): the worst impact over the
/// box (FindWorstCase) and the speed and mass limits safe for every value in it
/// (MaxSafeSpeedOverBox, MaxSafeMassOverBox).

#include <optional>
#include <string>
#include <vector>

#include <covopt/core/scene.hpp>

#include "covopt/optim/covering_design.hpp"
#include "covopt/optim/problem.hpp"
#include "covopt/optim/robust_box.hpp"
#include "covopt/optim/speed_limit.hpp"
#include "covopt/optim/speed_limit_table.hpp"

namespace covopt::optim {

// ----------------------------------------------------------------------------------------
// Worst case over the box
// ----------------------------------------------------------------------------------------

/// The global search over a box, used by every worst-case question here. The searched inputs
/// (those with low < high that are not pinned) are scaled to [0, 1]; the search evaluates
///   1. every corner, when there are at most max_corner_inputs searched inputs;
///   2. the centre and a Halton sequence of space_filling_points points;
///   3. NLopt DIRECT-L with global_evaluations evaluations;
///   4. NLopt COBYLA from the local_starts best distinct points found so far (one of them
///      DIRECT-L's), each with local_evaluations evaluations, to a relative step of 1e-10;
/// and keeps the best point evaluated. Deterministic.
struct GlobalSearchOptions {
  /// Enumerate all 2^k corners when k <= this, in [0, 16]. Default: 10 (1024 corners).
  int max_corner_inputs = 10;
  /// Halton points after the centre, >= 0; -1 = 32 + 32 k. Default: -1.
  int space_filling_points = -1;
  /// DIRECT-L's evaluation budget, >= 0 (0: skip the stage); -1 = 500 + 200 k. Default: -1.
  long global_evaluations = -1;
  /// COBYLA refinements, in [0, 20]. Default: 3.
  int local_starts = 3;
  /// Evaluations per refinement, >= 10; -1 = 100 + 50 k. Default: -1.
  long local_evaluations = -1;
  /// Hold robot-mass, head-mass and speed at their worst end (the top of the range for a
  /// worst impact, see the file comment) instead of searching them. Default: true. Not
  /// applied to a box with a braking robot (UncertaintyBox::brakes()): the brake acts from a
  /// time and on the robot alone, so the energy argument does not hold and they are searched.
  bool pin_energy_inputs = true;
};

/// Options of FindWorstCase.
struct WorstCaseOptions {
  /// false (default): criterion "no-full-compression"; true: the paper's, ratios only.
  bool allow_full_compression = false;
  DesignCriterion criterion() const noexcept {
    return allow_full_compression ? DesignCriterion::kPaper : DesignCriterion::kNoFullCompression;
  }
  /// Ratios must be <= 1/safety_factor, in [1, 100] [-]. Default: 1.
  double safety_factor = 1.0;
  /// The laceration [Pa] and contusion [J/m²] limits. Default: 1 MPa and 2.52 J/cm².
  InjuryLimits limits;
  /// The covering material's compressive strength [Pa] when it crushes (docs/model.md §12):
  /// the crush ratio σ_c,max / strength is judged, and counts unless allow_crushing. 0
  /// (default): no material of known strength, no crush check.
  double compressive_strength_Pa = 0.0;
  /// A sacrificial liner: the crush ratio is reported but does not count. Default: false.
  bool allow_crushing = false;
  GlobalSearchOptions search;
  /// The time path's integrator and tolerances for a braking robot (UncertaintyBox::brakes()):
  /// checked then only. Default: ARKODE ERK 5(4), rtol 1e-8.
  TimeIntegrationOptions time_path;
};

/// The worst impact over a box.
struct WorstCase {
  /// The inputs at the worst case [SI], in the order of UncertaintyBox::inputs().
  std::vector<double> values;
  /// The nominal scene with those values.
  Scene scene;
  double laceration_ratio = 0.0;   ///< σ_t,max / laceration limit [-]
  double contusion_ratio = 0.0;    ///< e_A,max / contusion limit [-]
  /// The covering's travel used [-] (DesignScore::compression_ratio); 0 without a covering.
  double compression_ratio = 0.0;
  bool fully_compressed = false;   ///< the covering is fully compressed at the peak
  /// σ_c,max / the material's compressive strength [-] when a crushing material is judged; else 0.
  double crush_ratio = 0.0;
  /// F_max / the struck area's lowest published fracture force [-] (docs/model.md §7.1).
  double fracture_ratio = 0.0;
  /// g = SF × max(r_L, r_C, r_F, r_δ (default criterion, with a covering), r_crush (a material
  /// of known strength, crushing not allowed)) [-]: what the search maximised.
  double governing_ratio = 0.0;
  /// The criterion that attains g (kNone never).
  LimitingCriterion binding = LimitingCriterion::kLaceration;
  /// g <= 1 and, under the default criterion, not fully compressed: the whole box is
  /// admissible (as far as the search can tell).
  bool admissible = false;
  /// The largest g over the corners, when they were enumerated (GlobalSearchOptions::
  /// max_corner_inputs): how far a corners-only check would have fallen short.
  std::optional<double> corner_governing_ratio;
  /// The stage whose point was kept: "corner", "centre", "space-filling", "global" (DIRECT-L),
  /// "local" (COBYLA), or "pinned" (nothing left to search); "scenarios" in a robust design
  /// with a braking robot, for a material with no design: the worst of the scenario set at the
  /// maximum thickness, already inadmissible (RobustCandidate), the box not searched again.
  std::string found_by;
  SolverReport global;  ///< the DIRECT-L stage (backend empty when skipped)
  SolverReport local;   ///< the refinement that gave the best point (or the last one)
  long evaluations = 0;  ///< impacts evaluated (exact path, or screened / time path with braking)
  /// A braking robot: how the impacts were judged, and any failed time-path run (a failure
  /// makes its point the worst case, inadmissible).
  TimePathUse time_path;
  double seconds = 0.0;
};

/// The worst impact over the box for the nominal scene's covering (or bare robot). With a
/// braking robot the search runs on the time path, screened by the exact path's bound
/// (docs/model.md §11, "A braking robot").
/// @throws std::invalid_argument for bad options.
WorstCase FindWorstCase(const UncertaintyBox& box, const WorstCaseOptions& options = {});

// ----------------------------------------------------------------------------------------
// Speed and mass limits over the box
// ----------------------------------------------------------------------------------------

/// MaxSafeSpeedOverBox's answer.
struct RobustSpeedLimit {
  /// MaxSafeSpeed at the worst case: the largest speed safe for every value in the box.
  SpeedLimit limit;
  std::vector<double> values;  ///< the inputs there [SI], in the box's order
  Scene scene;                 ///< the scene there
  std::string found_by;        ///< as WorstCase::found_by
  long evaluations = 0;        ///< MaxSafeSpeed evaluations
  double seconds = 0.0;
};

/// MaxSafeMassOverBox's answer.
struct RobustMassLimit {
  MassLimit limit;  ///< MaxSafeMass at the worst case
  std::vector<double> values;
  Scene scene;
  std::string found_by;
  long evaluations = 0;
  double seconds = 0.0;
};

/// One row of a speed-limit table over a box (`covopt speed-limit` with scene ranges): the
/// value the row sets and the limit safe for every value in the box.
using RobustSpeedLimitRow = BasicSpeedLimitRow<RobustSpeedLimit, RobustMassLimit>;

/// min over the box of MaxSafeSpeed (the same global search; robot and head mass pinned at
/// the top of their ranges when `search.pin_energy_inputs`: a heavier body only lowers it).
/// @throws std::invalid_argument for a range on the speed ("speed: the speed limit is what is
///   computed; it cannot be uncertain") or bad options.
RobustSpeedLimit MaxSafeSpeedOverBox(const UncertaintyBox& box, const SpeedLimitOptions& options = {},
                                     const GlobalSearchOptions& search = {});

/// min over the box of MaxSafeMass (speed and head mass pinned at the top when
/// `search.pin_energy_inputs`).
/// @throws std::invalid_argument for a range on robot-mass or bad options.
RobustMassLimit MaxSafeMassOverBox(const UncertaintyBox& box, const SpeedLimitOptions& options = {},
                                   const GlobalSearchOptions& search = {});

}  // namespace covopt::optim
