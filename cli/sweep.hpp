#pragma once
/// @file sweep.hpp
/// `covopt sweep`: the exact path over a grid of one or two scene quantities.
///
///     covopt sweep --x covering-modulus=0.1MPa..1GPa:log:200 --y covering-thickness=0..50mm:200
///                  [scene flags] [--scene FILE] [--material NAME] [--threads N]
///                  [--csv FILE|-] [--plot FILE.png|FILE.svg]
///
/// An axis is NAME=LO..HI[:lin|:log][:N] (N points, default 50, linear by default),
/// NAME=V1,V2,... (the values as listed; masses may be 'fixed', the robot radius 'flat'), or
/// a comma list mixing both: robot-radius=2mm..500mm:log:10,flat.
/// NAME is a scene flag without its dashes (speed, robot-mass, covering-thickness, ...) or
/// its scene-file name (robot.speed). Values take units as the scene flags do; a bare
/// number is SI, and a bare nonzero number with a unit on the other end is refused
/// ("10..100MPa" would mean 10 Pa to 100 MPa). Every other quantity comes from the scene
/// flags, --scene and --material exactly as in `covopt simulate`.
///
/// The computation is one library call, covopt::Sweep (covopt/core/sweep.hpp): each point
/// is solved on the exact path on all cores, and the rows stream here in grid order, block
/// by block, into the CSV writer (SweepCsvWriter) and, with --plot, into the few numbers a
/// chart needs; so a 1000 x 1000 sweep to CSV runs in flat memory. A point whose scene is
/// outside the model's input range is reported as invalid with the library's message
/// (never NaN). The summary is the library's, counted on the stream.
/// Exit codes: 0 done (also when some points are invalid), 1 an output could not be
/// written, 2 bad input.

#include <cstddef>
#include <functional>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "covopt/core/sweep.hpp"
#include "scene_fields.hpp"
#include "simulate.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The options of `covopt sweep`, as typed.
struct SweepCommandOptions {
  /// --x NAME=SPEC: the first swept quantity (required).
  std::string x;
  /// --y NAME=SPEC: the second swept quantity, if any.
  std::optional<std::string> y;
  /// The scene: --scene, the scene flags, --thresholds, --material, --catalog/--no-builtin,
  /// read as `covopt simulate` reads them (the other members stay unset).
  SimulateOptions scene;
  /// --threads N: worker threads, 1..4096. Default: the hardware's concurrency.
  std::optional<int> threads;
  /// --csv FILE: one row per point; "-" writes it to stdout instead of the summary.
  std::optional<std::string> csv_file;
  /// --plot FILE.png|FILE.svg: the worst-ratio map with both limit contours and the
  /// full-compression boundary (δ_max = t2, the fully compressed side dotted), or line
  /// families of the two ratios (fully compressed points ringed) when an axis has at most
  /// kMaxFamilies values. Titles name the scene's quantities that are not swept.
  std::optional<std::string> plot_file;
  /// --plot-quantity COLUMN: chart this result column (e.g. max_compressive_stress_Pa)
  /// instead of the injury ratios; the map keeps the two limit contours.
  std::optional<std::string> plot_quantity;
  /// --no-progress: no progress bar even on a terminal.
  bool no_progress = false;
};

/// One item of an axis spec: a range LO..HI of `count` values, or a single value.
struct SweepAxisPart {
  double low = 0.0;        ///< SI; the value itself for a single value
  double high = 0.0;       ///< SI; equals `low` for a single value
  std::size_t count = 1;   ///< values the item gives (1 for a single value)
  bool log = false;        ///< a :log range
  bool range = false;      ///< LO..HI rather than a single value
};

/// One swept quantity.
struct SweepAxisArgument {
  const SceneField* field = nullptr;  ///< the scene field it sets
  std::string name;                   ///< the flag without dashes: "covering-modulus"
  /// SI, in the order typed (each range expanded in place); kFixed/kFlat where listed as
  /// 'fixed'/'flat'. Charts draw them sorted; the CSV keeps this order.
  std::vector<double> values;
  /// Drawn on a log axis: some range is :log and every finite value is above 0.
  bool log = false;
  std::vector<SweepAxisPart> parts;  ///< the items of the spec, in order
  std::string spec;                  ///< as typed after '='
};

/// An axis with at most this many values is drawn as a family of lines.
inline constexpr std::size_t kMaxFamilies = 8;
/// Limits on the grid: values per axis and points in total (the library's, covopt/core/sweep.hpp).
inline constexpr std::size_t kMaxAxisValues = covopt::kMaxSweepAxisValues;
inline constexpr std::size_t kMaxSweepPoints = covopt::kMaxSweepPoints;

/// Reads "NAME=SPEC".
/// @param flag "--x" or "--y", for messages.
/// @throws InputError naming the flag, the value and what is allowed.
SweepAxisArgument ParseSweepAxis(std::string_view text, std::string_view flag);

/// Refuses a grid over the library's caps (covopt::CheckSweepSize), before any point.
/// @throws InputError "the grid has 1000 x 2000 = 2000000 points; at most 1000000 are allowed".
void CheckGridSize(const SweepAxisArgument& x, const SweepAxisArgument* y);

/// The library's sweep of these axes over `plan`'s scene, limits and safety factor: what
/// `covopt sweep` computes.
covopt::SweepSpec MakeSweepSpec(const SweepAxisArgument& x, const SweepAxisArgument* y,
                                const SimulationPlan& plan);

/// Rows per block for a grid of `points` on `threads` threads: about eight blocks per
/// thread, 16..1024 rows, so small grids still spread over the threads.
std::size_t SweepBlockRows(std::size_t points, unsigned threads);

/// Registers the options of the `sweep` subcommand `sub` (made by RunCli with its name and
/// summary), storing what is typed into `options`.
void SetupSweep(CLI::App* sub, SweepCommandOptions& options);

/// Runs the subcommand; returns the exit code (0, 1 or 2).
int RunSweep(const SweepCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace covopt::cli
