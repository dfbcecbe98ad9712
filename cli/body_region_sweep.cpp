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

#include "body_region_commands.hpp"
#include "covopt/optim/body_region_sweep.hpp"
#include "covopt/report/csv.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "plot.hpp"
#include "sweep.hpp"

namespace covopt::cli {
namespace {

std::string AxisText(const SweepAxisArgument& axis, double value) {
  if (std::isinf(value) && value > 0) return axis.field->spec.allow_flat ? "flat" : "fixed";
  return fmt::format("{}", value);
}

std::string Number(double value) { return std::isfinite(value) ? fmt::format("{}", value) : std::string(); }

}  // namespace

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

  std::string csv;
  const std::vector<std::string_view> columns{"peak_force_N",    "peak_pressure_Pa", "covering_deflection_m",
                                              "fully_compressed", "force_ratio",      "pressure_ratio",
                                              "compression_ratio", "crush_ratio",     "governing",
                                              "governing_ratio",  "admissible",       "error"};
  std::vector<std::string> header{x.name};
  if (y) header.push_back(y->name);
  header.insert(header.end(), columns.begin(), columns.end());
  report::AppendCsvRecord(csv, header);
  std::size_t points = 0, admissible = 0, invalid = 0;
  std::string chart_data;  // x [y] governing ratio, a blank line between y blocks (gnuplot's grid)
  double worst = -1.0;
  std::string worst_at;
  const std::vector<optim::BodyRegionSweepPoint> grid = optim::SweepBodyRegion(
      BodyContactSceneOf(plan.scene, regions), SweepAxis{x.field->dotted_name(), x.values},
      y ? std::optional(SweepAxis{y->field->dotted_name(), y->values}) : std::nullopt, limits, rule);
  const std::vector<double> y_values = y ? y->values : std::vector<double>{0.0};
  for (std::size_t iy = 0; iy < y_values.size(); ++iy) {
    const double yv = y_values[iy];
    for (std::size_t ix = 0; ix < x.values.size(); ++ix) {
      const double xv = x.values[ix];
      const optim::BodyRegionSweepPoint& point = grid[ix * y_values.size() + iy];
      std::vector<std::string> row{AxisText(x, xv)};
      if (y) row.push_back(AxisText(*y, yv));
      ++points;
      if (point.judgement) {
        const optim::BodyRegionJudgement& v = *point.judgement;
        const BodyContactResult& c = v.contact;
        for (const std::string& cell :
             {Number(c.peak_force_N), c.peak_pressure_Pa ? Number(*c.peak_pressure_Pa) : std::string(),
              Number(c.covering_deflection_m), std::string(c.fully_compressed ? "1" : "0"), Number(v.force_ratio),
              v.pressure_ratio ? Number(*v.pressure_ratio) : std::string(), Number(v.compression_ratio),
              v.crush_check == optim::CrushCheck::kChecked ? Number(v.crush_ratio) : std::string(),
              std::string(optim::ToString(v.governing)), Number(v.governing_ratio),
              std::string(v.admissible ? "1" : "0"), std::string()}) {
          row.push_back(cell);
        }
        if (v.admissible) ++admissible;
        if (std::isfinite(xv) && std::isfinite(yv)) {
          chart_data += y ? fmt::format("{} {} {}\n", xv, yv, v.governing_ratio) : fmt::format("{} {}\n", xv, v.governing_ratio);
        }
        if (v.governing_ratio > worst) {
          worst = v.governing_ratio;
          worst_at = fmt::format("{} = {}{}, {}", x.name, AxisText(x, xv),
                                 y ? fmt::format(", {} = {}", y->name, AxisText(*y, yv)) : std::string(),
                                 optim::ToString(v.governing));
        }
      } else {  // a point outside the model's range
        ++invalid;
        row.resize(row.size() + columns.size() - 1);
        row.push_back(point.error);
      }
      report::AppendCsvRecord(csv, row);
    }
    chart_data += "\n";
  }
  const bool csv_to_stdout = options.csv_file && *options.csv_file == "-";
  try {
    if (options.plot_file && !FindOnPath("gnuplot")) return errors.Failed(kGnuplotMissing);
    if (options.csv_file && !csv_to_stdout) WriteFileAtomically(*options.csv_file, csv);
    if (options.plot_file) {
      const PlotFormat format = *PlotFormatFor(*options.plot_file);
      const double bound = 1.0 / plan.safety_factor;
      RunGnuplot(*options.plot_file, [&](const std::string& output) {
        std::string s = "set encoding utf8\n" + GnuplotTerminal(format, 1000, 700);
        s += fmt::format("set output {}\n$data << EOD\n{}EOD\n", GnuplotQuoted(output), chart_data);
        s += fmt::format("set title {}\n", GnuplotQuoted(fmt::format(
                                              "governing ratio (line: {:g}); {}", 1.0 / plan.safety_factor, limits.Describe())));
        s += fmt::format("set xlabel {}\n", GnuplotQuoted(x.name + " [" + std::string(SiUnit(x.field->spec.kind)) + "]"));
        if (x.log) s += "set logscale x\n";
        if (y) {
          s += fmt::format("set ylabel {}\n", GnuplotQuoted(y->name + " [" + std::string(SiUnit(y->field->spec.kind)) + "]"));
          if (y->log) s += "set logscale y\n";
          s += "set view map\nset contour base\nunset surface\nset pm3d at b\nunset key\n";
          s += fmt::format("set cntrparam levels discrete {}\nset cblabel 'governing ratio'\n", bound);
          s += fmt::format("splot $data using 1:2:3 with pm3d notitle, $data using 1:2:3 with lines linewidth 2 "
                           "linecolor rgb '#000000' title 'ratio = {:g}'\n", bound);
        } else {
          s += "set ylabel 'governing ratio'\nset grid\n";
          s += fmt::format("plot $data using 1:2 with lines linewidth 2 title 'governing ratio', {:g} with lines "
                           "dashtype 2 linecolor rgb '#c0392b' title 'limit (1/SF)'\n", bound);
        }
        return s + "unset output\n";
      });
    }
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }
  if (csv_to_stdout) {
    out << csv;
  } else {
    fmt::print(out, "Body region {} ({} contact): {} points, {} within every limit, {} outside the model's range\n",
               regions.targets.front().Name(), ToString(limits.contact), points, admissible, invalid);
    if (worst >= 0.0) fmt::print(out, "Worst       governing ratio {:.4g} at {}\n", worst, worst_at);
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
