// `covopt sweep --body-region R`: the body contact's verdict over the grid (the simplest correct
// form: the exact path point by point, on one thread, into a CSV or a summary, and a chart of the
// governing ratio: a line over one axis, a map with its contour at 1/SF over two).
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/chart/body_region_sweep_chart.hpp"
#include "covopt/optim/body_region_sweep.hpp"
#include "covopt/report/body_region_sweep_output.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "plot.hpp"
#include "sweep.hpp"

namespace covopt::cli {

int RunBodyRegionSweep(const SweepCommandOptions& options, const BodyRegionPlan& regions, std::ostream& out,
                       std::ostream& err) {
  const CommandErrors errors(err, "sweep");
  SweepAxisArgument x;
  std::optional<SweepAxisArgument> y;
  SimulationPlan plan;
  try {
    if (regions.targets.size() != 1 || regions.has_head()) {
      throw InputError("--body-region with sweep: name one ISO region (the CSV's columns are one verdict's); for "
                       "several, run one sweep each, or use speed-limit --body-region");
    }
    if (options.plot_quantity) {
      throw InputError("--plot-quantity with --body-region: the body-region chart draws the governing ratio; drop it");
    }
    if (options.plot_file && !PlotFormatFor(*options.plot_file)) {
      throw InputError(fmt::format("--plot: cannot tell the format of '{}'; name the file *.png or *.svg",
                                   *options.plot_file));
    }
    x = ParseSweepAxis(options.x, "--x");
    if (options.y) y = ParseSweepAxis(*options.y, "--y");
    CheckGridSize(x, y ? &*y : nullptr);
    for (const SweepAxisArgument* axis : {&x, y ? &*y : nullptr}) {
      if (axis && !optim::IsBodyContactField(axis->field->dotted_name())) {
        throw InputError(fmt::format("{} sweeps {}, which the body region does not read; sweep robot-mass, speed, "
                                     "robot-radius or the covering",
                                     axis == &x ? "--x" : "--y", axis->name));
      }
    }
    plan = ResolveSimulation(options.scene);
    CheckBodyRegionScene(regions, plan);
    if (options.csv_file && options.csv_file->empty()) throw InputError("--csv: empty file name");
  } catch (const InputError& e) {
    return errors.BadInput(e.what());
  }
  const materials::BodyLimits limits = *regions.targets.front().limits;
  const optim::BodyRegionOptions rule = BodyRegionOptionsOf(plan, false, false);

  const std::vector<optim::BodyRegionSweepPoint> grid = optim::SweepBodyRegion(
      BodyContactSceneOf(plan.scene, regions), SweepAxis{x.field->dotted_name(), x.values},
      y ? std::optional(SweepAxis{y->field->dotted_name(), y->values}) : std::nullopt, limits, rule);
  const report::BodyRegionSweepTable table = report::LayOutBodyRegionSweep(grid, x, y ? &*y : nullptr);
  const bool csv_to_stdout = options.csv_file && *options.csv_file == "-";
  try {
    if (options.plot_file && !FindOnPath("gnuplot")) return errors.Failed(kGnuplotMissing);
    if (options.csv_file && !csv_to_stdout) WriteFileAtomically(*options.csv_file, table.csv);
    if (options.plot_file) {
      const PlotFormat format = *PlotFormatFor(*options.plot_file);
      RunGnuplot(*options.plot_file, [&](const std::string& output) {
        return chart::BodyRegionSweepChart(grid, x, y ? &*y : nullptr, limits, plan.safety_factor, format, output);
      });
    }
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }
  if (csv_to_stdout) {
    out << table.csv;
  } else {
    fmt::print(out, "Body region {} ({} contact): {} points, {} within every limit, {} outside the model's range\n",
               regions.targets.front().Name(), ToString(limits.contact), table.points, table.admissible, table.invalid);
    if (table.worst >= 0.0) fmt::print(out, "Worst       governing ratio {:.4g} at {}\n", table.worst, table.worst_at);
    fmt::print(out, "Scope       {}\n", limits.Describe());
    if (options.csv_file || options.plot_file) {
      fmt::print(out, "Wrote       {}{}{}\n", options.csv_file.value_or(""), options.csv_file && options.plot_file ? ", " : "",
                 options.plot_file.value_or(""));
    }
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace covopt::cli
