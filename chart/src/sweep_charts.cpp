#include "covopt/chart/sweep_charts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "covopt/core/quantity.hpp"

namespace covopt::chart {

using report::kMaxFamilies;
using report::SweepAxisArgument;
using report::ResultColumn;
namespace {

using covopt::SweepRow;

/// How a kind is shown on a chart axis: SI value / scale, in unit.
struct DisplayUnit {
  double scale;
  std::string_view unit;
};
DisplayUnit DisplayFor(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::kMass: return {1.0, "kg"};
    case QuantityKind::kLength: return {1e-3, "mm"};
    case QuantityKind::kSpeed: return {1.0, "m/s"};
    case QuantityKind::kModulus: return {1e6, "MPa"};
    case QuantityKind::kDensity: return {1.0, "kg/m³"};
    case QuantityKind::kDimensionless: return {1.0, ""};
    case QuantityKind::kEnergyDensity: return {1e4, "J/cm²"};
    case QuantityKind::kTime: return {1e-3, "ms"};
    case QuantityKind::kAcceleration: return {1.0, "m/s²"};
    case QuantityKind::kDampingCoefficient: return {1.0, "s/m"};
    case QuantityKind::kStiffness: return {1e3, "kN/m"};
    case QuantityKind::kViscousDamping: return {1.0, "N·s/m"};
    case QuantityKind::kArea: return {1e-4, "cm²"};
  }
  return {1.0, ""};
}

/// One number for a gnuplot data block; NaN marks a point gnuplot must skip.
std::string PlotNumber(double v) { return std::isfinite(v) ? fmt::format("{}", v) : "NaN"; }

/// How a result column is shown on a chart: value / scale, in unit.
struct ColumnDisplay {
  double scale;
  std::string_view unit;
};
ColumnDisplay DisplayFor(std::string_view column) {
  const auto ends = [&](std::string_view suffix) {
    return column.size() >= suffix.size() && column.substr(column.size() - suffix.size()) == suffix;
  };
  if (ends("_Pa")) return {1e6, "MPa"};
  if (ends("_J_per_m2")) return {1e4, "J/cm²"};
  if (ends("_m_per_s")) return {1.0, "m/s"};
  if (ends("_m")) return {1e-3, "mm"};
  if (ends("_s")) return {1e-3, "ms"};
  if (ends("_N")) return {1.0, "N"};
  return {1.0, ""};
}

std::size_t PointIndex(const PlotInput& in, std::size_t ix, std::size_t iy) {
  const std::size_t ny = in.y ? in.y->values.size() : 1;
  return ix * ny + iy;
}
const ChartPoint& At(const PlotInput& in, std::size_t ix, std::size_t iy) {
  return in.points[PointIndex(in, ix, iy)];
}

/// The indices of an axis's finite values in ascending order of value, each value once:
/// the order a chart draws them in (a mixed list is typed in any order).
std::vector<std::size_t> ChartOrder(const SweepAxisArgument& axis) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < axis.values.size(); ++i) {
    if (std::isfinite(axis.values[i])) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return axis.values[a] < axis.values[b]; });
  order.erase(std::unique(order.begin(), order.end(),
                          [&](std::size_t a, std::size_t b) {
                            return axis.values[a] == axis.values[b];
                          }),
              order.end());
  return order;
}

/// The gnuplot title: `lines` joined by gnuplot's line breaks.
std::string TitleText(const std::vector<std::string>& lines) {
  return fmt::format("{}", fmt::join(lines, "\\n"));
}

/// The map's notes: a limit or the full compression on no side of its line, invalid points.
std::vector<std::string> MapNotes(const PlotInput& in) {
  const double at_limit = 1.0 / in.safety_factor;  // the ratio at the (derated) limit
  std::size_t invalid = 0;
  bool lac_below = false, lac_above = false, con_below = false, con_above = false;
  bool full_below = false, full_above = false;
  for (std::size_t i = 0; i < in.points.size(); ++i) {
    const ChartPoint& p = in.points[i];
    if (!p.valid) {
      ++invalid;
      continue;
    }
    (p.laceration_ratio <= at_limit ? lac_below : lac_above) = true;
    (p.contusion_ratio <= at_limit ? con_below : con_above) = true;
    (p.fully_compressed ? full_above : full_below) = true;
  }
  std::vector<std::string> notes;
  if (!(lac_below && lac_above)) {
    notes.push_back(fmt::format("laceration ratio {} {:.4g} everywhere", lac_above ? ">" : "<=",
                                at_limit));
  }
  if (!(con_below && con_above)) {
    notes.push_back(fmt::format("contusion ratio {} {:.4g} everywhere", con_above ? ">" : "<=",
                                at_limit));
  }
  if (!(full_below && full_above)) {
    notes.push_back(full_above ? "fully compressed everywhere" : "never fully compressed");
  }
  if (invalid > 0) notes.push_back(fmt::format("{} invalid points left blank", invalid));
  return notes;
}

/// The map's data blocks: $grid (x, y, laceration ratio, contusion ratio, the coloured value,
/// compression ratio; a blank line between x values) and $stipple (the fully compressed points
/// of a coarse subgrid).
std::string MapDataBlocks(const PlotInput& in, const std::vector<std::size_t>& x_order,
                          const std::vector<std::size_t>& y_order) {
  const SweepAxisArgument& x = *in.x;
  const SweepAxisArgument& y = *in.y;
  const double sx = DisplayFor(x.field->spec.kind).scale;
  const double sy = DisplayFor(y.field->spec.kind).scale;
  std::string s;
  const double qscale = in.quantity ? DisplayFor(in.quantity->name).scale : 1.0;
  // Columns: x, y, laceration ratio, contusion ratio, the coloured value, compression ratio.
  s += "$grid << EOD\n";
  for (const std::size_t ix : x_order) {
    for (const std::size_t iy : y_order) {
      const ChartPoint& p = At(in, ix, iy);
      const bool ok = p.valid;
      s += fmt::format("{} {} {} {} {} {}\n", x.values[ix] / sx, y.values[iy] / sy,
                       PlotNumber(ok ? p.laceration_ratio : NAN),
                       PlotNumber(ok ? p.contusion_ratio : NAN),
                       PlotNumber(ok ? (in.quantity ? p.quantity / qscale : p.worst_ratio) : NAN),
                       PlotNumber(ok ? p.compression_ratio : NAN));
    }
    s += "\n";
  }
  s += "EOD\n";
  // Dots on the fully compressed side, on a coarse subgrid (about 25 x 25) so the colours
  // stay readable. An empty block still gives the key entry.
  s += "$stipple << EOD\n";
  const std::size_t x_step = std::max<std::size_t>(1, x_order.size() / 25);
  const std::size_t y_step = std::max<std::size_t>(1, y_order.size() / 25);
  bool stippled = false;
  for (std::size_t i = 0; i < x_order.size(); i += x_step) {
    for (std::size_t j = 0; j < y_order.size(); j += y_step) {
      const ChartPoint& p = At(in, x_order[i], y_order[j]);
      if (p.valid && p.fully_compressed) {
        s += fmt::format("{} {}\n", x.values[x_order[i]] / sx, y.values[y_order[j]] / sy);
        stippled = true;
      }
    }
  }
  if (!stippled) s += "NaN NaN\n";
  s += "EOD\n";
  return s;
}

}  // namespace

std::string AxisLabel(const SweepAxisArgument& axis) {
  const DisplayUnit unit = DisplayFor(axis.field->spec.kind);
  return fmt::format("{} [{}]", axis.name, unit.unit.empty() ? "-" : unit.unit);
}

double DisplayScale(const SweepAxisArgument& axis) { return DisplayFor(axis.field->spec.kind).scale; }

std::string Display(const SweepAxisArgument& axis, double si) {
  return FormatQuantity(si, axis.field->spec.kind);
}

std::string ColumnLabel(const ResultColumn& column) {
  const ColumnDisplay d = DisplayFor(column.name);
  return d.unit.empty() ? std::string(column.name) : fmt::format("{} [{}]", column.name, d.unit);
}

ChartPoint ChartPointOf(const SweepRow& row, const ResultColumn* quantity) {
  if (!row.valid) return {};
  return {true,
          row.peaks.fully_compressed,
          row.assessment.laceration.ratio,
          row.assessment.contusion.ratio,
          row.worst_ratio,
          quantity ? quantity->value(row) : 0.0,
          row.compression_ratio};
}

/// The 2-D map: worst ratio in colour, the ratio-1 contours of laceration and contusion,
/// and the full-compression boundary (δ_max = t2: beyond it the robot reaches bone
/// through the covering).
std::string SweepMapScript(const PlotInput& in, const std::string& output) {
  const SweepAxisArgument& x = *in.x;
  const SweepAxisArgument& y = *in.y;
  const double sx = DisplayFor(x.field->spec.kind).scale;
  const double sy = DisplayFor(y.field->spec.kind).scale;
  const std::vector<std::size_t> x_order = ChartOrder(x);
  const std::vector<std::size_t> y_order = ChartOrder(y);
  const double at_limit = 1.0 / in.safety_factor;  // the ratio at the (derated) limit
  const std::vector<std::string> notes = MapNotes(in);

  std::vector<std::string> title{
      fmt::format("covopt sweep: {} over {} and {}",
                  in.quantity ? fmt::format("{} with the injury limits", in.quantity->name)
                              : std::string("worst injury ratio max(laceration, contusion)"),
                  x.name, y.name),
      "scene: " + in.scene_line};
  if (!notes.empty()) title.push_back(fmt::format("{}", fmt::join(notes, "; ")));

  std::string s = "set encoding utf8\n";
  s += GnuplotTerminal(in.format, 1000, 820);
  s += fmt::format("set output {}\n", GnuplotQuoted(output));
  // gnuplot grows a title downwards onto the plot: lift it by a line per extra line.
  s += fmt::format("set title \"{}\" offset 0, {}\n", TitleText(title), title.size() - 1);
  s += fmt::format("set xlabel {}\nset ylabel {}\n", GnuplotQuoted(AxisLabel(x)),
                   GnuplotQuoted(AxisLabel(y)));
  if (in.quantity) {
    s += fmt::format("set cblabel {}\n", GnuplotQuoted(ColumnLabel(*in.quantity)));
  } else if (in.safety_factor == 1.0) {
    s += "set cblabel 'worst ratio (1 = at a limit; above 2 shown as 2)'\n";
  } else {
    s += fmt::format("set cblabel 'worst ratio ({:.4g} = at a limit / safety factor {:g}; above "
                     "{:.4g} shown as {:.4g})'\n",
                     at_limit, in.safety_factor, 2.0 * at_limit, 2.0 * at_limit);
  }
  if (x.log) s += "set logscale x\n";
  if (y.log) s += "set logscale y\n";
  // The axis ranges: the finite values of each axis.
  if (!x_order.empty() && !y_order.empty()) {
    s += fmt::format("set xrange [{}:{}]\nset yrange [{}:{}]\n", x.values[x_order.front()] / sx,
                     x.values[x_order.back()] / sx, y.values[y_order.front()] / sy,
                     y.values[y_order.back()] / sy);
  }
  if (in.quantity) {
    s += "set palette defined (0 '#f7fbff', 0.35 '#9ecae1', 0.7 '#3182bd', 1 '#08306b')\n";
  } else {
    s += fmt::format("set cbrange [0:{}]\n", 2.0 * at_limit);
    s += "set palette defined (0 '#1a7f3c', 0.5 '#8fd18b', 0.98 '#f4f1bb', 1.02 '#fdd49e', "
         "1.5 '#f0793d', 2 '#a50f15')\n";
  }
  s += MapDataBlocks(in, x_order, y_order);
  // The limit contours and the full-compression boundary, traced by gnuplot into data blocks.
  s += fmt::format("set contour base\nset cntrparam levels discrete {}\nunset surface\n",
                   at_limit);
  s += "set table $lac\nsplot $grid using 1:2:3 notitle\nunset table\n";
  s += "set table $con\nsplot $grid using 1:2:4 notitle\nunset table\n";
  s += "set cntrparam levels discrete 1\n";
  s += "set table $full\nsplot $grid using 1:2:6 notitle\nunset table\n";
  s += "unset contour\nset surface\n";
  s += "set view map\nset pm3d explicit at b\n";
  // Room for the title lines above the plot, and for the key below the axis label.
  s += fmt::format("set tmargin at screen {}\nset bmargin 6.5\n",
                   1.0 - 0.025 * (static_cast<double>(title.size()) + 1.5));
  s += "set key at screen 0.5, screen 0.05 center center horizontal maxrows 2 width 0 "
       "samplen 4\n";
  s += "set grid front linecolor rgb '#888888'\n";
  // "limit (ratio 1)", or with a safety factor "limit / 1.5 (ratio 0.6667)".
  const std::string limit_text =
      in.safety_factor == 1.0
          ? std::string("limit (ratio 1)")
          : fmt::format("limit / {:g} (ratio {:.4g})", in.safety_factor, at_limit);
  s += fmt::format(
      "splot $grid using 1:2:5 with pm3d notitle, \\\n"
      "      $lac using 1:2:(0) with lines linewidth 2.5 linecolor rgb '#1f5fa8' "
      "title 'laceration {0}', \\\n"
      "      $con using 1:2:(0) with lines linewidth 2.5 dashtype 2 linecolor rgb '#000000' "
      "title 'contusion {0}', \\\n",
      limit_text);
  s += "      $full using 1:2:(0) with lines linewidth 3 dashtype (10,4,2,4) linecolor rgb "
       "'#6c3483' title 'full-compression boundary (δ_max = t2)', \\\n"
       "      $stipple using 1:2:(0) with points pointtype 7 pointsize 0.3 linecolor rgb "
       "'#4a235a' title 'fully compressed (dots): the robot reaches bone'\n";
  s += "unset output\n";
  return s;
}

/// Line families: laceration and contusion ratio against the long axis, one line per
/// value of the short axis (or one line without a second axis); the points where the
/// covering is fully compressed are ringed.
std::string SweepFamiliesScript(const PlotInput& in, const std::string& output) {
  // along: the horizontal axis; family: one line per value (may be absent).
  const bool families_on_y = in.y == nullptr || in.y->values.size() <= kMaxFamilies;
  const SweepAxisArgument& along = families_on_y ? *in.x : *in.y;
  const SweepAxisArgument* family = families_on_y ? in.y : in.x;
  const double scale = DisplayFor(along.field->spec.kind).scale;
  const std::size_t lines = family ? family->values.size() : 1;
  const double qscale = in.quantity ? DisplayFor(in.quantity->name).scale : 1.0;
  const std::vector<std::size_t> along_order = ChartOrder(along);

  std::string s = "set encoding utf8\n";
  s += GnuplotTerminal(in.format, 1000, in.quantity ? 650 : 900);
  s += fmt::format("set output {}\n", GnuplotQuoted(output));
  // Columns: along, laceration ratio, contusion ratio, quantity, fully compressed (0/1).
  s += "$data << EOD\n";
  bool any_fully_compressed = false;
  for (std::size_t line = 0; line < lines; ++line) {
    for (const std::size_t i : along_order) {
      const ChartPoint& p = families_on_y ? At(in, i, in.y ? line : 0) : At(in, line, i);
      const bool ok = p.valid;
      const bool full = ok && p.fully_compressed;
      any_fully_compressed = any_fully_compressed || full;
      s += fmt::format("{} {} {} {} {}\n", along.values[i] / scale,
                       PlotNumber(ok ? p.laceration_ratio : NAN),
                       PlotNumber(ok ? p.contusion_ratio : NAN),
                       PlotNumber(ok && in.quantity ? p.quantity / qscale : NAN),
                       full ? 1 : 0);
    }
    s += "\n\n";
  }
  s += "EOD\n";
  const std::array<std::string_view, kMaxFamilies> colours{
      "#1f5fa8", "#c0392b", "#2e8b57", "#8e44ad", "#d68910", "#17a2b8", "#555555", "#e84393"};
  const auto clauses = [&](int column, bool limit) {
    std::string c;
    for (std::size_t line = 0; line < lines; ++line) {
      const std::string title =
          family ? fmt::format("{} {}", family->name, Display(*family, family->values[line]))
                 : std::string("covopt");
      c += fmt::format(
          "$data index {} using 1:{} with linespoints linewidth 2 pointtype 7 "
          "pointsize 0.4 linecolor rgb '{}' title {}, ",
          line, column, colours[line % colours.size()], GnuplotQuoted(title));
    }
    if (any_fully_compressed) {
      c += fmt::format(
          "$data using 1:($5 > 0.5 ? ${} : NaN) with points pointtype 6 pointsize 1.3 "
          "linewidth 1.5 linecolor rgb '#000000' title 'fully compressed (δ_max > t2)', ",
          column);
    }
    if (!limit) {
      c.resize(c.size() - 2);  // the last ", "
      return c + "\n";
    }
    return c + fmt::format("{} with lines dashtype 2 linewidth 1.5 linecolor rgb '#000000' "
                           "title {}\n",
                           1.0 / in.safety_factor,
                           GnuplotQuoted(in.safety_factor == 1.0
                                             ? std::string("limit")
                                             : fmt::format("limit / {:g}", in.safety_factor)));
  };

  if (along.log) s += "set logscale x\n";
  s += fmt::format("set xlabel {}\n", GnuplotQuoted(AxisLabel(along)));
  s += "set grid linecolor rgb '#dddddd'\nset key outside right top\nset yrange [0:*]\n";
  const std::string against =
      family ? fmt::format("against {}, one line per {}", along.name, family->name)
             : fmt::format("against {}", along.name);
  std::vector<std::string> title{"", "scene: " + in.scene_line};
  if (std::any_of(along.values.begin(), along.values.end(),
                  [](double v) { return !std::isfinite(v); })) {
    title.push_back(fmt::format("{} {} not on the axis (see the CSV)", along.name,
                                along.field->spec.allow_flat ? "flat" : "fixed"));
  }
  s += "set autoscale xfix\n";
  if (in.quantity) {
    const bool ratio = in.quantity->name.find("ratio") != std::string_view::npos;
    title.front() = fmt::format("covopt sweep: {} {}", in.quantity->name, against);
    s += fmt::format("set title \"{}\"\n", TitleText(title));
    s += fmt::format("set ylabel {}\n", GnuplotQuoted(ColumnLabel(*in.quantity)));
    s += "plot " + clauses(4, ratio);
    s += "unset output\n";
    return s;
  }
  title.front() = fmt::format("covopt sweep: injury ratios {}", against);
  s += fmt::format("set multiplot layout 2,1 title \"{}\"\n", TitleText(title));
  s += fmt::format("set ylabel 'laceration ratio (tensile stress / {:g} MPa)'\n",
                   in.limits.laceration_tensile_stress_Pa / 1e6);
  s += "plot " + clauses(2, true);
  s += fmt::format("set ylabel 'contusion ratio (energy density / {:g} J/cm²)'\n",
                   in.limits.contusion_energy_density_J_per_m2 / 1e4);
  s += "plot " + clauses(3, true);
  s += "unset multiplot\nunset output\n";
  return s;
}


}  // namespace covopt::chart
