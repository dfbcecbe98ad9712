#pragma once
/// @file body_contact.hpp
/// A robot striking a body region of ISO/TS 15066:2016 Annex A, with or without the covering
/// (docs/model.md §13). The standard models the region as an effective mass m_H on a linear
/// spring k_H; covopt puts the covering in series, as a Hertz layer on the robot's curved
/// surface. This is the body-region model beside the head's (scene.hpp, solve.hpp): the same
/// Scene → Model → Solve shape, an exact path (an energy balance with one monotone root, no
/// integration) and a time path that checks it.
///
///     mu  = 1/(1/m_R + 1/m_H)                          m_H = inf when clamped
///     bare robot (b_c = 0):   F_max = v sqrt(mu k_H)    (Annex A exactly: F²/(2k) = mu v²/2)
///                             p_max = F_max / A         A: the contact area, when given
///     covering (E_c, nu_c, b_c) on a robot surface of radius R_r, R_c = R_r + b_c:
///       K_c = 4/3 E_c/(1 - nu_c²) sqrt(R_c)             [N/m^1.5]
///       delta_c(F) = (F/K_c)^(2/3)  up to  0.8 b_c      the covering's deflection
///       F_b = K_c (0.8 b_c)^1.5                         the force at which it bottoms out
///       mu v²/2 = F²/(2 k_H) + W_c(F),  W_c(F) = 2/5 K_c^(-2/3) min(F, F_b)^(5/3)
///       a² = R_c delta_c(min(F, F_b)),  p_max = 3 F_max / (2 pi a²)   (Hertz peak pressure)
///     a foam layer with its measured curve sigma(eps) (docs/model.md §15; the covering's law,
///     CoveringSpec::law, kAuto takes it where the covering has a compressive_curve), h = b_c,
///     d its compression, W and V the curve's integrals (compressive_curve.hpp):
///       curved face (R_c = R_r + h):  F(d) = 2 pi R_c h W(d/h),  U_c(d) = 2 pi R_c h² V(d/h),
///                                     p = sigma(d/h),  a² = 2 R_c d
///       flat face with contact area A:  F(d) = A sigma(d/h),  U_c(d) = A h W(d/h),  p = F/A
///       mu v²/2 = U_c(d) + F(d)²/(2 k_H): one monotone root in d on [0, d_end], d_end = eps_end h;
///       past d_end the layer is a rigid stop (used up): mu v²/2 = U_c(d_end) + F²/(2 k_H),
///       F >= F(d_end); the pressure past the stop is sigma_end + (F - F(d_end))/A on a curved
///       face (A the bare robot's contact area; not evaluated without one), F/A on a flat face.
///
/// Everything is SI; limits and verdicts are not here (a region's limits are data,
/// covopt/materials/body_regions.hpp; the verdicts and speed limits are optim's,
/// covopt/optim/body_region_check.hpp).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/scene.hpp"
#include "covopt/core/solve.hpp"

namespace covopt {

/// How the body region meets the robot (ISO/TS 15066:2016, 5.5.5.2 and Annex A).
enum class ContactType {
  /// Transient: the region is free and recoils (its effective mass m_H moves). The standard
  /// allows twice the quasi-static limits where Table A.2 permits transient contact at all.
  kTransient,
  /// Quasi-static (clamped): the region is held against a fixed object, m_H = inf; the
  /// quasi-static limits apply.
  kClamped,
};
/// "transient" or "clamped".
std::string_view ToString(ContactType type) noexcept;
/// The inverse of ToString ("quasi-static" is accepted for kClamped); empty for other text.
std::optional<ContactType> ParseContactType(std::string_view text) noexcept;

/// One robot–body-region contact: plain SI inputs, checked by BodyContactModel::FromScene.
struct BodyContactScene {
  /// The robot's effective (reflected) mass m_R along the impact direction [kg], in
  /// [1e-3, 1e6] (the floor kMinMass_kg); kFixed for an immovable robot (then the contact must be transient).
  double robot_mass_kg = 10.0;
  /// Relative approach speed at first contact [m/s], in [1e-6, 100].
  double speed_m_per_s = 0.25;
  /// Radius of curvature of the robot surface under the covering [m], in [1e-4, 100] (the
  /// floor kMinRadius_m); kFlat if flat.
  /// A Hertz covering needs a finite radius (its contact is sphere-on-flat); a foam covering
  /// takes a flat face with a contact area.
  double robot_radius_m = kFlat;
  /// The covering. thickness_m == 0 (the default): the bare robot, modulus and Poisson ratio
  /// ignored.
  CoveringSpec covering{27.6e6, 0.25, 0.0};
  /// The body region's effective spring constant k_H [N/m], > 0 and <= 1e9 (Table A.3).
  double body_stiffness_N_per_m = 25e3;
  /// The body region's effective mass m_H [kg], in [1e-3, 1e6] (Table A.3); not read when clamped.
  double body_mass_kg = 40.0;
  /// Transient (default) or clamped.
  ContactType contact = ContactType::kTransient;
  /// The bare robot's contact area A [m²], in [1e-6, 1] (the floor kMinContactArea_m2); 0 (default): not given, and the bare
  /// robot's pressure is not evaluated. With a Hertz covering the pressure is the Hertz
  /// pressure and this is not read. With a foam covering it is the flat face's area (needed
  /// there), or on a curved face the bare robot's, for the pressure past the stop.
  double contact_area_m2 = 0.0;
  /// The Hertz covering is fully compressed at this fraction of its thickness [-], in (0, 1].
  /// A foam covering's travel is its curve's last strain (not read).
  double full_compression_fraction = 0.8;
  /// The robot's reaction, as the head scene's (RobotSpec, docs/model.md §10.2 and §13.10): from
  /// this long after first contact [s], in [0, 10], the robot brakes with `braking_m_per_s2`
  /// while it still moves forward.
  double reaction_delay_s = 0.0;
  /// Braking deceleration [m/s²], in [0, 1e4]: a force m_R a against the robot's motion once
  /// the reaction delay has passed, until the robot stops (it is not held there). 0 (default):
  /// the robot does not brake. Needs a robot that moves (finite mass). A braking robot has no
  /// energy integral: only the time path answers it.
  double braking_m_per_s2 = 0.0;
  bool has_covering() const noexcept { return covering.thickness_m > 0.0; }
  /// The robot brakes after its reaction delay (braking > 0).
  bool robot_brakes() const noexcept { return braking_m_per_s2 > 0.0; }
};

/// A validated, immutable BodyContactScene with the derived constants and the force law.
class BodyContactModel {
 public:
  /// Checks every field of `scene`.
  /// @throws std::invalid_argument naming the field, the value and the allowed range, e.g.
  ///         "robot_radius_m: a covering needs a finite robot radius (got a flat robot)", or
  ///         "robot_mass_kg: a fixed robot needs a transient contact (the clamped body and the
  ///         robot would both be immovable)".
  static BodyContactModel FromScene(const BodyContactScene& scene);

  const BodyContactScene& scene() const noexcept { return scene_; }
  /// mu = 1/(1/m_R + 1/m_H) [kg]; m_H = inf when clamped.
  double reduced_mass_kg() const noexcept { return reduced_mass_kg_; }
  /// ½ mu v² [J]: the energy the contact stores at its peak (transferred to the springs); an
  /// upper bound of it for a braking robot (the brake takes part of it).
  double impact_energy_J() const noexcept { return impact_energy_J_; }
  bool has_covering() const noexcept { return scene_.has_covering(); }
  /// The covering's law as resolved from CoveringSpec::law (kFoam or kHertz; kHertz bare).
  CoveringLaw covering_law() const noexcept { return law_; }
  /// A foam covering (the law resolved to kFoam).
  bool foam() const noexcept { return law_ == CoveringLaw::kFoam && has_covering(); }
  /// K_c [N/m^1.5]; 0 without a Hertz covering.
  double covering_stiffness() const noexcept { return covering_stiffness_; }
  /// R_c = R_r + b_c [m]; 0 without a covering (and for a foam layer on a flat face).
  double covering_outer_radius_m() const noexcept { return outer_radius_m_; }
  /// The covering's travel [m]: 0.8 b_c (Hertz), d_end = eps_end h (foam: the last strain of
  /// its curve); 0 without a covering.
  double covering_travel_m() const noexcept { return travel_m_; }
  /// The force at which the covering is used up [N]: F_b = K_c (0.8 b_c)^1.5 (Hertz), F(d_end)
  /// (foam); +inf without a covering (nothing to bottom out).
  double bottom_out_force_N() const noexcept { return bottom_out_force_N_; }
  /// The energy both springs hold when the covering is used up [J]: U_c(travel) + F_b²/(2 k_H);
  /// +inf without a covering. Above it the contact is past the stop.
  double bottom_out_energy_J() const noexcept { return bottom_out_energy_J_; }

  /// The energy stored at contact force F [J], F >= 0: F²/(2 k_H) + W_c(F). A foam layer's
  /// F(d) may be constant over a plateau of its curve (a flat face): then the largest energy
  /// whose peak force is F (the last compression with that force).
  double EnergyAtForce(double force_N) const noexcept;
  /// The covering's deflection at force F [m]: (min(F, F_b)/K_c)^(2/3) (Hertz); the largest
  /// d with F(d) <= F, at most d_end (foam); 0 bare.
  double CoveringDeflectionAtForce(double force_N) const noexcept;
  /// The total approach (robot toward the region's mass) at force F [m]: F/k_H + deflection.
  double ApproachAtForce(double force_N) const noexcept;
  /// The peak pressure at force F [Pa]: Hertz 3F/(2 pi a²) with a Hertz covering; the foam's
  /// sigma(d/h) (past the stop the rule of the file comment: empty on a curved face without an
  /// area); F/A bare with an area; empty bare without an area.
  std::optional<double> PressureAtForce(double force_N) const noexcept;
  /// The speed [m/s] at which the peak force is F: sqrt(2 EnergyAtForce(F) / mu).
  double SpeedAtPeakForce(double force_N) const noexcept;
  /// The force of the energy balance EnergyAtForce(F) = energy [N], energy >= 0: one
  /// monotone root, solved in s = F^(1/3) (a polynomial: no pow in the iteration), to ~1e-15
  /// relative (Hertz); for a foam layer the root d of EnergyAtDeflection (below).
  double ForceAtEnergy(double energy_J) const noexcept;

  /// A foam layer (foam() true; 0 otherwise) at compression d [m], clamped to [0, d_end]:
  /// its force F(d) [N], its energy U_c(d) [J], both springs' energy U_c(d) + F(d)²/(2 k_H) [J]
  /// and its stress sigma(d/h) [Pa].
  double FoamForceAtDeflection(double deflection_m) const noexcept;
  double FoamEnergyAtDeflection(double deflection_m) const noexcept;
  double EnergyAtDeflection(double deflection_m) const noexcept;
  double FoamStressAtDeflection(double deflection_m) const noexcept;
  /// The foam layer's compression d [m] at which EnergyAtDeflection(d) = energy, energy in
  /// [0, bottom_out_energy_J()] (clamped): one monotone root, located on the curve's pieces and
  /// solved by Newton on the piece's polynomial (convex: it descends onto the root), ~1e-15.
  double FoamDeflectionAtEnergy(double energy_J) const noexcept { return FoamStateAtEnergy(energy_J).deflection_m; }
  /// A foam layer's state at compression d: d [m], F(d) [N], U_c(d) [J], σ(d/h) [Pa].
  struct FoamState {
    double deflection_m = 0.0;
    double force_N = 0.0;
    double covering_energy_J = 0.0;
    double stress_Pa = 0.0;
  };
  /// The state at the root of FoamDeflectionAtEnergy, from the root's own polynomial.
  FoamState FoamStateAtEnergy(double energy_J) const noexcept;
  /// A foam layer's law: on a flat face (F = A σ) or a curved one (F = 2π R_c h W), and the
  /// factors of its force and energy in the curve's integrals: F = foam_force_factor() W(d/h)
  /// curved (σ(d/h) flat) [m²], U_c = foam_energy_factor() V(d/h) curved (W(d/h) flat) [m³].
  bool foam_flat_face() const noexcept { return flat_foam_; }
  double foam_force_factor() const noexcept { return foam_force_factor_; }
  double foam_energy_factor() const noexcept { return foam_energy_factor_; }
  /// The largest foam compression d [m] whose stress sigma(d/h) is <= stress (d_end above
  /// sigma_end): the end of a plateau, so that a limit on the stress is the largest safe d.
  double FoamDeflectionAtStress(double stress_Pa) const noexcept;

 private:
  BodyContactScene scene_;
  double reduced_mass_kg_ = 0.0;
  double impact_energy_J_ = 0.0;
  double covering_stiffness_ = 0.0;
  double outer_radius_m_ = 0.0;
  double travel_m_ = 0.0;
  double bottom_out_force_N_ = 0.0;
  double compliance_factor_ = 0.0;  // K_c^(-2/3) [m/N^(2/3)]
  double bottom_out_root_ = 0.0;    // F_b^(1/3) [N^(1/3)]
  double bottom_out_energy_J_ = 0.0;
  CoveringLaw law_ = CoveringLaw::kHertz;
  // The foam layer: its curve (owned by scene_.covering), thickness h, and the factors of its
  // force and energy in the curve's W (curved) or sigma (flat): F = force_factor_ W(d/h) or
  // force_factor_ sigma(d/h); U_c = energy_factor_ V(d/h) or energy_factor_ W(d/h).
  const CompressiveCurve* curve_ = nullptr;
  bool flat_foam_ = false;
  double foam_thickness_m_ = 0.0;
  double foam_force_factor_ = 0.0;
  double foam_energy_factor_ = 0.0;
  void SetUpFoam();
  std::optional<double> FoamPressureAtForce(double force_N) const noexcept;
  double FoamDeflectionAtForce(double force_N) const noexcept;
};

/// One sample of a body-contact history (time path).
struct BodyContactSample {
  double time_s = 0.0;
  double approach_m = 0.0;              ///< total approach δ = δ_c + δ_b [m]
  double approach_rate_m_per_s = 0.0;   ///< δ' [m/s]
  double force_N = 0.0;                 ///< contact force [N]
  /// The robot's own speed v_R [m/s], in the frame where the body region starts at rest (the
  /// region's speed is v_R - δ'; 0 when clamped). Without braking it follows from momentum,
  /// v_R = v0 - (mu/m_R)(v0 - δ'); a braking robot's is integrated.
  double robot_speed_m_per_s = 0.0;
  /// The work the brake has taken out so far [J]: ∫ m_R a v_R dt; 0 without braking.
  double braking_work_J = 0.0;
};

/// The peaks of one robot–body-region contact.
struct BodyContactResult {
  /// kSuccess, or the time path's failure (then the peaks are not an answer).
  SolveStatus status = SolveStatus::kSuccess;
  std::string message;  ///< empty on success; the integrator's flag and message otherwise
  /// "exact" (the energy balance, no integration) or the time path's integrator and tolerance,
  /// e.g. "time path (arkode-erk54, rtol 1e-08)".
  std::string method;
  double reduced_mass_kg = 0.0;          ///< mu [kg]
  /// The energy the springs store at the peak [J]: ½ mu v² without braking; less for a braking
  /// robot (body_energy_J + covering_energy_J: the brake slowed the approach).
  double energy_transferred_J = 0.0;
  double peak_force_N = 0.0;             ///< F_max [N]
  /// p_max [Pa]: the covering's Hertz peak pressure, or F_max/A bare with an area; empty bare
  /// without a contact area (not evaluated).
  std::optional<double> peak_pressure_Pa;
  /// The contact radius a at the peak [m]: Hertz's, or a foam's sqrt(2 R_c d) on a curved face
  /// (sqrt(A/pi) on a flat one); 0 bare.
  double contact_radius_m = 0.0;
  double covering_deflection_m = 0.0;    ///< δ_c at the peak [m]; 0 bare
  double body_deflection_m = 0.0;        ///< F_max / k_H [m]
  double max_approach_m = 0.0;           ///< δ_c + δ_b at the peak [m]
  double body_energy_J = 0.0;            ///< F_max²/(2 k_H) [J]
  double covering_energy_J = 0.0;        ///< W_c(F_max) [J]
  /// δ_c / travel at the peak [-] (0.8 b_c Hertz, d_end foam: the share of the measured curve
  /// used): 1 at full compression; 0 bare. Past F_b it is 1 and fully_compressed is set.
  double compression_ratio = 0.0;
  /// The covering bottomed out (used up: F_max > F_b, past a foam's measured curve): the robot
  /// pressed on the region through it, as through a rigid stop.
  bool fully_compressed = false;
  /// The covering's law (kFoam or kHertz); empty bare.
  std::optional<CoveringLaw> covering_law;
  /// Where the law holds (CoveringValidity); within and no note bare.
  CoveringValidity validity;
  /// The covering's nominal strain at the peak, δ_c / b_c [-] (d/h for a foam); 0 bare.
  double peak_strain = 0.0;
  /// The energy the body spring took after the covering was used up [J]: the energy at the
  /// peak less bottom_out_energy_J(); 0 when not used up.
  double energy_past_stop_J = 0.0;
  /// Past a foam's stop on a curved face, the pressure is sigma_end plus the bare robot's
  /// (F - F(d_end))/A (BodyContactModel's file comment): set then (and empty without an area).
  bool pressure_past_stop = false;
  /// The covering's compressive stress at the peak [Pa] (what a crush check compares with its
  /// strength): the peak pressure; past a foam's stop on a curved face without an area, where
  /// the pressure is not evaluated, σ_end (a lower bound); 0 bare.
  double covering_stress_Pa = 0.0;
  /// Contact duration [s]: the time path's; on the exact path the bare robot's pi sqrt(mu/k_H),
  /// and empty with a covering (not computed: the peaks need no integration).
  std::optional<double> contact_duration_s;
  /// Speed of separation [m/s]: the time path's; the impact speed on the exact path (the
  /// contact is conservative).
  double rebound_speed_m_per_s = 0.0;
  /// The time path's own accuracy check [-] (as ImpactResult::energy_residual), empty on the
  /// exact path and for a failed run. The contact conserves energy, so for an exact solution
  ///     max( |(body_energy_J + covering_energy_J) / (½ mu v0²) - 1|,  |rebound speed / v0 - 1| )
  /// vanishes (the second term only with the rebound: not from SolveBodyContactPeaks). A braking
  /// robot: the energy balance with the brake's work, at maximum compression and at separation,
  ///     max | ΔK + U + W | / (½ mu v0²),  K = ½ m_R v_R² + ½ m_H v_H² (v_H = 0 clamped).
  /// Above max(100 rtol, 1e-9) `warnings` says the integrator did not keep its tolerance.
  std::optional<double> energy_residual;
  /// The time path's warnings: ValidityCode::kToleranceNotKept ("the time path did not keep its
  /// tolerance: energy residual ... exceeds max(100 rtol, 1e-9) = ...") where energy_residual
  /// exceeds that bound, as the head's time path; the peaks and the rebound of such a result
  /// are not within the tolerance asked for. Empty on the exact path.
  std::vector<ValidityWarning> warnings;
  /// The time-path history (with SolveOptions::record_history).
  std::vector<BodyContactSample> history;
  bool ok() const noexcept { return status == SolveStatus::kSuccess; }
  /// The messages of `warnings`, in order.
  std::vector<std::string> WarningMessages() const {
    std::vector<std::string> messages;
    for (const ValidityWarning& w : warnings) messages.push_back(w.message);
    return messages;
  }
};

/// Solves one body-region contact. kAuto and kExact take the exact path (a record_history
/// takes the time path under kAuto and is refused under kExact); kTimePath integrates
/// mu δ'' = -F(δ) with SUNDIALS (SolveOptions::time_path), stopping at the covering's
/// bottoming out to restart, at the peak (δ' = 0) and at separation. A braking robot
/// (BodyContactScene::robot_brakes) has no energy integral: kAuto takes the time path, which
/// adds the brake m_R a to the robot's motion after the reaction delay (restarting where the
/// brake starts and where the robot stops), and kExact is refused.
/// @throws std::invalid_argument for a scene field or an option out of range (naming it), or
///         path exact on a braking robot.
BodyContactResult Solve(const BodyContactModel& model, const SolveOptions& options = {});
/// Validates `scene` (BodyContactModel::FromScene) and solves it.
BodyContactResult Solve(const BodyContactScene& scene, const SolveOptions& options = {});

/// The peaks of one body-region contact on the time path, which stops at maximum compression:
/// every peak quantity as Solve's time path gives it (to the bit), but no contact duration
/// (empty) and no rebound speed (0), and no history. For searches that need only the peaks,
/// such as a braking robot's speed limit (optim's MaxSafeSpeed): about half a full run.
/// @throws std::invalid_argument for an option out of range (naming it, "time_path.").
BodyContactResult SolveBodyContactPeaks(const BodyContactModel& model, const TimeIntegrationOptions& options = {});

}  // namespace covopt
