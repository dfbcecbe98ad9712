#pragma once
/// @file sweep.hpp
/// A parameter sweep, streamed: one or two scene quantities, by name, over
/// lists of values; every grid point solved on worker threads; rows handed to a consumer in
/// grid order, block by block, so memory stays flat however large the grid (a 1000 x 1000
/// sweep holds a few blocks of rows at a time, never the grid).
///
///     covopt::SweepSpec spec;                          // the paper's scene
///     spec.x = {"speed", {0.5, 1.0, 1.5, 2.0}};        // m/s
///     spec.y = covopt::SweepAxis{"covering-thickness", {0.005, 0.010, 0.020}};  // m
///     const covopt::SweepResult result = covopt::Sweep(spec, {}, [](std::span<const covopt::SweepRow> rows) {
///       for (const covopt::SweepRow& row : rows) use(row.x, row.y, row.worst_ratio);
///     });
///     std::puts(result.BriefReport().c_str());
///
/// Each point's scene is the spec's scene with the swept fields set; it is validated
/// (ImpactModel::FromScene) and solved on its own, so a scene outside the model's input range
/// is an invalid row carrying the library's message, never a failure of the sweep and never
/// NaN. A point is solved on the exact path (SolveExact) where the scene has the energy
/// integral it needs (the two-mass impact, conservative or damped), and on the time path
/// (SimulateImpact with SweepOptions::time_path) where it does not: a braking robot or a neck
/// (docs/model.md §10.4); SweepRow::method says which.
/// A time-path point whose integration fails is an invalid row with the integrator's message. A row depends on its scene alone: rows are bit-identical for any
/// number of threads and any block size. The summary (SweepResult) is gathered on the stream.
/// The library never prints; progress goes through SweepOptions::progress.

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "covopt/core/exact.hpp"
#include "covopt/core/time_integration.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/scene.hpp"

namespace covopt {

/// The most values one axis may have (`covopt sweep`'s N, covopt.sweep's and speed_limit's
/// value lists).
inline constexpr std::size_t kMaxSweepAxisValues = 100000;
/// The most points of a grid (a 1000 x 1000 sweep; covopt.sweep's result arrays, 13 numbers
/// and 5 flags a point, then take 109 MB).
inline constexpr std::size_t kMaxSweepPoints = 1000000;

/// One swept quantity: a Scene field by name and the values it takes.
struct SweepAxis {
  /// The field: its name ("speed", "robot-mass", "covering-thickness", ...: the command
  /// line's scene flags without the dashes) or its dotted name ("robot.speed"); see
  /// SceneFields().
  std::string quantity;
  /// The values in the field's SI unit (kg, m, m/s, Pa or -), in the order swept; at least
  /// one. +inf (covopt::kFixed, covopt::kFlat) for a fixed body or a flat robot. A value
  /// the model refuses (a negative mass, +inf where no body may be fixed) gives invalid rows.
  std::vector<double> values;
};

/// What to sweep: a scene, one or two axes, and the limits the ratios are taken against.
struct SweepSpec {
  /// Every quantity not swept. Default: the paper's scene (Scene{}).
  Scene scene;
  /// The first axis; it varies slowest (row index = ix * y.values.size() + iy).
  SweepAxis x;
  /// The second axis, if any; it varies fastest. Default: none (one row per x value).
  std::optional<SweepAxis> y;
  /// The injury limits the ratios are taken against. Default: 1 MPa, 2.52 J/cm².
  InjuryLimits limits;
  /// The limits are divided by this [-], in [1, 100]: ratios stay value / limit, and a
  /// verdict is safe when safety_factor x ratio <= 1. Default: 1.
  double safety_factor = 1.0;
};

/// How to sweep.
struct SweepOptions {
  /// Worker threads, counting the calling thread (which also computes while it waits for
  /// the next block), 0..4096; 0 = std::thread::hardware_concurrency() (1 if unknown).
  /// Never more threads than blocks are started. Default: 0.
  unsigned threads = 0;
  /// Rows per consumer call, 1..1'000'000; also the unit of work of a thread. At most
  /// 2 x threads blocks are held at once. Default: 1024.
  std::size_t block_rows = 1024;
  /// What the exact path computes at each point. Default: peaks and contact duration.
  ExactOptions exact;
  /// The time path's integrator and tolerances, for the points the exact path cannot answer,
  /// a braking robot or a neck (any method but kExact, rtol in [1e-14, 1e-2]; it always computes the duration).
  /// Default: TimeIntegrationOptions{} (ARKODE ERK 5(4), rtol 1e-8).
  TimeIntegrationOptions time_path;
  /// Called from the calling thread after each block is consumed, with (rows delivered,
  /// rows in total), last with delivered == total. May be empty. An exception it throws
  /// stops the sweep as one from the consumer does. Default: empty.
  std::function<void(std::size_t delivered, std::size_t total)> progress;
};

/// One grid point, as the consumer receives it.
struct SweepRow {
  std::size_t index = 0;  ///< position in the grid: ix * (number of y values) + iy
  std::size_t ix = 0;     ///< index into SweepSpec::x.values
  std::size_t iy = 0;     ///< index into SweepSpec::y->values; 0 without a y axis
  double x = 0.0;         ///< x.values[ix] [SI unit of the x field]
  double y = 0.0;         ///< y->values[iy] [SI unit of the y field]; 0 without a y axis
  /// The scene is inside the model's input range and was solved. When false, only the
  /// indices, x, y and `error` mean anything.
  bool valid = false;
  /// ImpactModel::FromScene's message for an invalid scene, e.g.
  /// "head.radius must exceed scalp.thickness ..."; empty for a valid one.
  std::string error;
  /// δ_max [m], F_max [N], σ_c,max and σ_t,max [Pa], e_A,max [J/m²], the phase at δ_max,
  /// the compression flags and t2 [m] (see ImpactPeaks).
  ImpactPeaks peaks;
  /// The path the point's scene needs: kExact, or the time path's integrator (set for
  /// invalid rows too).
  ComputationMethod method = ComputationMethod::kExact;
  /// Contact duration [s]; empty when SweepOptions::exact.compute_duration is off (exact
  /// path points).
  std::optional<double> contact_duration_s;
  /// Time of maximum compression [s] (half the contact duration on the exact path: the model
  /// has no dissipation); empty when the duration is not computed.
  std::optional<double> time_of_max_compression_s;
  /// Relative speed at separation [m/s] (the impact speed, less with damping, braking or a
  /// damped neck).
  double rebound_speed_m_per_s = 0.0;
  /// Rebound speed / impact speed [-] (ImpactResult::coefficient_of_restitution).
  double coefficient_of_restitution = 0.0;
  /// Laceration (σ_t,max) and contusion (e_A,max) against SweepSpec::limits: ratios are
  /// value / limit [-]; `safe` is safety_factor x ratio <= 1.
  InjuryAssessment assessment;
  /// max(laceration ratio, contusion ratio) [-].
  double worst_ratio = 0.0;
  /// δ_max / t2 [-], t2 = peaks.full_compression_penetration_m where the robot reaches bone
  /// through everything soft: above 1 the point is fully compressed, 1 is the boundary.
  double compression_ratio = 0.0;
  /// The scene has a covering (covering.thickness > 0).
  bool covered = false;
  /// The design criterion (docs/model.md §6): both verdicts safe and, with a covering, the
  /// covering not fully compressed at the peak (a bare robot has nothing to bottom out).
  bool admissible = false;
  /// Where the result leaves the model's domain (CheckValidity), with stable codes.
  std::vector<ValidityWarning> warnings;
};

/// Receives the rows, a block at a time, in grid order (index 0, 1, 2, ...), always on the
/// calling thread. The rows are valid only during the call. It may throw: see Sweep.
using SweepConsumer = std::function<void(std::span<const SweepRow> rows)>;

/// How a sweep ended. Invalid points are rows, not failures: every status delivered every row.
enum class SweepStatus {
  kAllValid,      ///< every point was solved
  kSomeInvalid,   ///< some points are outside the model's input range (rows with `error`)
  kNoneValid,     ///< every point is outside the model's input range
};
/// "all-valid", "some-invalid", "none-valid".
std::string_view ToString(SweepStatus status) noexcept;

/// A row singled out by the summary: its index and ratios [-].
struct SweepExtreme {
  std::size_t index = 0;          ///< the row's SweepRow::index
  double worst_ratio = 0.0;       ///< max(laceration, contusion) ratio
  double laceration_ratio = 0.0;  ///< σ_t,max / laceration limit
  double contusion_ratio = 0.0;   ///< e_A,max / contusion limit
};

/// What a sweep delivered, counted on the stream.
struct SweepResult {
  SweepStatus status = SweepStatus::kAllValid;
  /// One line for people: "1000 points, all valid", or the first invalid point's message.
  std::string message;

  std::size_t rows = 0;                ///< rows delivered (every grid point)
  std::size_t x_values = 0;            ///< SweepSpec::x.values.size()
  std::size_t y_values = 0;            ///< SweepSpec::y->values.size(); 0 without a y axis
  std::size_t valid = 0;               ///< rows with valid == true
  std::size_t safe = 0;                ///< valid rows with both verdicts safe
  std::size_t laceration_unsafe = 0;   ///< valid rows with safety_factor x laceration ratio > 1
  std::size_t contusion_unsafe = 0;    ///< valid rows with safety_factor x contusion ratio > 1
  std::size_t covered = 0;             ///< valid rows with a covering
  std::size_t fully_compressed = 0;    ///< covered rows whose covering is fully compressed
  std::size_t admissible = 0;          ///< valid rows meeting the design criterion
  std::size_t warned = 0;              ///< valid rows with at least one validity warning
  std::size_t time_path_rows = 0;      ///< rows whose scene needs the time path (SweepRow::method)
  /// The first invalid row's index and message.
  std::optional<std::size_t> first_invalid;
  std::string first_invalid_error;
  /// The first warned row's index and its first warning.
  std::optional<std::size_t> first_warned;
  ValidityWarning first_warning;
  /// The valid rows with the smallest and the largest worst ratio (the first such row on a
  /// tie); empty when no row is valid.
  std::optional<SweepExtreme> least;
  std::optional<SweepExtreme> most;
  unsigned threads = 0;        ///< threads used, the calling thread included
  double wall_time_s = 0.0;    ///< the whole sweep, the consumer's time included [s]

  /// At least one row is valid.
  bool ok() const noexcept { return status != SweepStatus::kNoneValid; }
  /// One line: "sweep: 1000000 points (1000 x 1000) in 0.93 s on 2 threads: all valid;
  /// safe 41.2 %, admissible 38.0 %; worst ratio 0.012 .. 3.41".
  std::string BriefReport() const;
};

/// Sweeps spec.x (and spec.y) over the spec's scene, each point on the path its scene needs,
/// handing every row to `consumer` in grid order.
/// @throws std::invalid_argument before any work, naming the field, the value and what is
///         allowed, for: an unknown quantity ("x.quantity: no scene quantity 'foo'; the
///         quantities are robot-mass, speed, ..."), an axis without values, a NaN value,
///         y sweeping the field x sweeps, an axis of more than kMaxSweepAxisValues values or a
///         grid of more than kMaxSweepPoints points (CheckSweepSize), limits not
///         > 0, a safety factor outside [1, 100], threads above 4096, block_rows outside
///         1..1'000'000, time_path options out of range ("time_path.relative_tolerance must
///         be in [1e-14, 1e-2] ..."), or an empty consumer.
/// An exception thrown by the consumer or by the progress callback stops the sweep: the
/// worker threads finish their block and are joined, no further rows are delivered, and
/// the exception propagates to the caller unchanged.
SweepResult Sweep(const SweepSpec& spec, const SweepOptions& options,
                  const SweepConsumer& consumer);

/// The number of points of a grid of `x_values` by `y_values` (none: one axis), checked
/// before anything is allocated for them (Sweep calls it; so do the CLI, Python and the
/// body-region sweep, which allocate per point).
/// @throws std::invalid_argument naming the axis and the count: "x.values: 100001 values is
///         not allowed (at most 100000 per axis)", or "the grid has 2000 x 1000 = 2000000
///         points; at most 1000000 are allowed".
std::size_t CheckSweepSize(std::size_t x_values, std::optional<std::size_t> y_values);

}  // namespace covopt
