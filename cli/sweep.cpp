#include "sweep.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <thread>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <fmt/compile.h>
#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include "errors.hpp"
#include "materials_command.hpp"
#include "output.hpp"
#include "plot.hpp"
#include "quantity.hpp"

namespace covopt::cli {
namespace {

constexpr std::size_t kDefaultCount = 50;
constexpr int kMaxThreads = 4096;

constexpr std::string_view kFooter = R"(An axis is NAME=LO..HI[:lin|:log][:N] (N values, default 50, linear unless
:log) or NAME=V1,V2,... (the values as listed; a mass may be 'fixed', the
robot radius 'flat'); a list may mix ranges and values, e.g.
robot-radius=2mm..500mm:log:10,flat (charts draw the values sorted). NAME is
a scene flag without its dashes: robot-mass, speed, robot-radius,
robot-modulus, robot-poisson, covering-modulus, covering-poisson,
covering-thickness, head-mass, head-radius, scalp-modulus, scalp-poisson,
scalp-thickness, skull-modulus, skull-poisson (or its scene-file name, e.g.
robot.speed). Values take units as the scene flags do; a bare number is SI,
so write 0..50mm or 1mm..50mm, not 1..50mm.

Every point is solved on the exact path (as 'covopt simulate'), on all cores;
a point whose scene has no energy integral (a braking robot, a neck) on the
time path (ARKODE ERK 5(4), rtol 1e-8), as 'simulate' chooses.
A point whose scene is outside the model's input range is 'invalid' in the CSV,
with the library's message; the others carry the numeric keys of 'simulate
--json'. Without --csv, stdout gets a summary; '--csv -' prints the CSV instead.

Exit codes: 0 done (also with invalid points); 1 an output could not be written
(e.g. gnuplot missing); 2 bad input.)";

std::string_view Trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

/// The flag without its dashes: "--robot-mass" -> "robot-mass".
std::string_view AxisName(const SceneField& field) {
  std::string_view flag = field.flag;
  while (!flag.empty() && flag.front() == '-') flag.remove_prefix(1);
  return flag;
}

std::string AxisNames() {
  std::string names;
  for (const SceneField& field : SceneFields()) {
    if (!names.empty()) names += ", ";
    names += AxisName(field);
  }
  return names;
}

const SceneField* FindField(std::string_view name) {
  for (const SceneField& field : SceneFields()) {
    if (AxisName(field) == name || field.dotted_name() == name) return &field;
  }
  return nullptr;
}

/// An axis value for the CSV: SI, or the word for an infinite mass/radius.
std::string AxisValueText(const SweepAxis& axis, double value) {
  if (std::isinf(value) && value > 0) {
    return axis.field->spec.allow_flat ? "flat" : "fixed";
  }
  return fmt::format("{}", value);
}

/// Appends `text` with inner quotes doubled and line breaks as spaces, in runs.
void AppendCsvEscaped(fmt::memory_buffer& out, std::string_view text) {
  const char* run = text.data();
  const char* const end = text.data() + text.size();
  for (const char* p = run; p != end; ++p) {
    if (*p != '"' && *p != '\n' && *p != '\r') continue;
    out.append(run, p);
    if (*p == '"') {
      out.push_back('"');
      out.push_back('"');
    } else {
      out.push_back(' ');
    }
    run = p + 1;
  }
  out.append(run, end);
}

/// Appends a CSV text field: quoted, with inner quotes doubled and line breaks as spaces;
/// nothing for an empty text.
void AppendCsvText(fmt::memory_buffer& out, std::string_view text) {
  if (text.empty()) return;
  out.push_back('"');
  AppendCsvEscaped(out, text);
  out.push_back('"');
}

/// Appends the warnings' messages joined by " | " as one CSV text field (nothing when the
/// joined text is empty).
void AppendCsvWarnings(fmt::memory_buffer& out, std::span<const covopt::ValidityWarning> warnings) {
  constexpr std::string_view kSeparator = " | ";
  std::size_t length = 0;
  for (const covopt::ValidityWarning& warning : warnings) length += warning.message.size();
  if (length == 0 && warnings.size() < 2) return;
  out.push_back('"');
  for (std::size_t i = 0; i < warnings.size(); ++i) {
    if (i > 0) out.append(kSeparator.data(), kSeparator.data() + kSeparator.size());
    AppendCsvEscaped(out, warnings[i].message);
  }
  out.push_back('"');
}

using covopt::SweepRow;

/// The result columns and how each is read; the names are the keys of simulate --json
/// (cli/output.cpp ToJson), which tests/cli/test_sweep.cpp checks.
struct ResultColumn {
  std::string_view name;
  double (*value)(const SweepRow&);
  /// The value is always one of 0..9 (a phase number or a 0/1 flag): the CSV writes its
  /// digit directly, the text "{}" gives.
  bool digit = false;
};
double Optional(const std::optional<double>& v) {
  return v ? *v : std::numeric_limits<double>::quiet_NaN();
}
// clang-format off
const std::array kResultColumns{
  ResultColumn{"max_penetration_m", [](const SweepRow& p) { return p.peaks.max_penetration_m; }, false},
  ResultColumn{"peak_force_N", [](const SweepRow& p) { return p.peaks.peak_force_N; }, false},
  ResultColumn{"contact_duration_s", [](const SweepRow& p) { return Optional(p.contact_duration_s); }, false},
  ResultColumn{"time_of_max_compression_s", [](const SweepRow& p) { return Optional(p.time_of_max_compression_s); }, false},
  ResultColumn{"max_compressive_stress_Pa", [](const SweepRow& p) { return p.peaks.max_compressive_stress_Pa; }, false},
  ResultColumn{"max_tensile_stress_Pa", [](const SweepRow& p) { return p.peaks.max_tensile_stress_Pa; }, false},
  ResultColumn{"max_energy_density_J_per_m2", [](const SweepRow& p) { return p.peaks.max_energy_density_J_per_m2; }, false},
  ResultColumn{"rebound_speed_m_per_s", [](const SweepRow& p) { return p.rebound_speed_m_per_s; }, false},
  ResultColumn{"coefficient_of_restitution", [](const SweepRow& p) { return p.coefficient_of_restitution; }, false},
  ResultColumn{"phase_at_max", [](const SweepRow& p) { return static_cast<double>(PhaseNumber(p.peaks.phase_at_max)); }, true},
  ResultColumn{"scalp_fully_compressed", [](const SweepRow& p) { return p.peaks.scalp_fully_compressed ? 1.0 : 0.0; }, true},
  ResultColumn{"fully_compressed", [](const SweepRow& p) { return p.peaks.fully_compressed ? 1.0 : 0.0; }, true},
  ResultColumn{"safe", [](const SweepRow& p) { return p.assessment.safe() ? 1.0 : 0.0; }, true},
  ResultColumn{"laceration_ratio", [](const SweepRow& p) { return p.assessment.laceration.ratio; }, false},
  ResultColumn{"contusion_ratio", [](const SweepRow& p) { return p.assessment.contusion.ratio; }, false},
  ResultColumn{"worst_ratio", [](const SweepRow& p) { return p.worst_ratio; }, false},
};
// clang-format on
const std::array<std::string_view, kResultColumns.size()> kResultColumnNames = [] {
  std::array<std::string_view, kResultColumns.size()> names{};
  for (std::size_t i = 0; i < names.size(); ++i) names[i] = kResultColumns[i].name;
  return names;
}();

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
  }
  return {1.0, ""};
}

std::string AxisLabel(const SweepAxis& axis) {
  const DisplayUnit unit = DisplayFor(axis.field->spec.kind);
  return unit.unit.empty() ? axis.name : fmt::format("{} [{}]", axis.name, unit.unit);
}

std::string Display(const SweepAxis& axis, double si) {
  return FormatQuantity(si, axis.field->spec.kind);
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

const ResultColumn* FindColumn(std::string_view name) {
  for (const ResultColumn& column : kResultColumns) {
    if (column.name == name) return &column;
  }
  return nullptr;
}

std::string ColumnLabel(const ResultColumn& column) {
  const ColumnDisplay d = DisplayFor(column.name);
  return d.unit.empty() ? std::string(column.name) : fmt::format("{} [{}]", column.name, d.unit);
}

/// What a chart needs of one grid point: the rest of its row is not kept.
struct ChartPoint {
  bool valid = false;             ///< SweepRow::valid; nothing else means anything if false
  bool fully_compressed = false;  ///< ImpactPeaks::fully_compressed
  double laceration_ratio = 0.0;  ///< [-]
  double contusion_ratio = 0.0;   ///< [-]
  double worst_ratio = 0.0;       ///< [-]
  double quantity = 0.0;          ///< the --plot-quantity column [SI], if any
  double compression_ratio = 0.0; ///< δ_max / t2 [-]
};

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

struct PlotInput {
  const ResultColumn* quantity = nullptr;  ///< --plot-quantity; null: the injury ratios
  const SweepAxis* x = nullptr;
  const SweepAxis* y = nullptr;
  std::span<const ChartPoint> points;  ///< every grid point, in grid order
  InjuryLimits limits;                 ///< the limits the ratios are taken against
  std::string scene_line;         ///< the quantities not swept, one line
  /// A point is safe when safety_factor x ratio <= 1: the limit lines sit at ratio
  /// 1/safety_factor (the derated limits).
  double safety_factor = 1.0;
  PlotFormat format = PlotFormat::kPng;
};

std::size_t PointIndex(const PlotInput& in, std::size_t ix, std::size_t iy) {
  const std::size_t ny = in.y ? in.y->values.size() : 1;
  return ix * ny + iy;
}
const ChartPoint& At(const PlotInput& in, std::size_t ix, std::size_t iy) {
  return in.points[PointIndex(in, ix, iy)];
}

/// The indices of an axis's finite values in ascending order of value, each value once:
/// the order a chart draws them in (a mixed list is typed in any order).
std::vector<std::size_t> ChartOrder(const SweepAxis& axis) {
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

/// The 2-D map: worst ratio in colour, the ratio-1 contours of laceration and contusion,
/// and the full-compression boundary (δ_max = t2: beyond it the robot reaches bone
/// through the covering).
std::string MapScript(const PlotInput& in, const std::string& output) {
  const SweepAxis& x = *in.x;
  const SweepAxis& y = *in.y;
  const double sx = DisplayFor(x.field->spec.kind).scale;
  const double sy = DisplayFor(y.field->spec.kind).scale;
  const std::vector<std::size_t> x_order = ChartOrder(x);
  const std::vector<std::size_t> y_order = ChartOrder(y);
  std::size_t invalid = 0;
  bool lac_below = false, lac_above = false, con_below = false, con_above = false;
  bool full_below = false, full_above = false;
  const double at_limit = 1.0 / in.safety_factor;  // the ratio at the (derated) limit
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
std::string FamiliesScript(const PlotInput& in, const std::string& output) {
  // along: the horizontal axis; family: one line per value (may be absent).
  const bool families_on_y = in.y == nullptr || in.y->values.size() <= kMaxFamilies;
  const SweepAxis& along = families_on_y ? *in.x : *in.y;
  const SweepAxis* family = families_on_y ? in.y : in.x;
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

/// "0.1 MPa .. 1 GPa, 200 values, log", "3 values: 1 kg, 5 kg, fixed" or, for a mixed
/// list, "11 values: 2 mm .. 500 mm (10, log), flat".
std::string DescribeAxis(const SweepAxis& axis) {
  const auto& v = axis.values;
  const auto& parts = axis.parts;
  if (parts.size() == 1 && parts.front().range) {
    return fmt::format("{} .. {}, {} values{}", Display(axis, v.front()), Display(axis, v.back()),
                       v.size(), parts.front().log ? ", log" : "");
  }
  std::vector<std::string> shown;
  for (std::size_t i = 0; i < parts.size() && i < 6; ++i) {
    const SweepAxisPart& part = parts[i];
    shown.push_back(part.range ? fmt::format("{} .. {} ({}{})", Display(axis, part.low),
                                             Display(axis, part.high), part.count,
                                             part.log ? ", log" : "")
                               : Display(axis, part.low));
  }
  if (parts.size() > 6) shown.push_back("...");
  return fmt::format("{} value{}: {}", v.size(), v.size() == 1 ? "" : "s",
                     fmt::join(shown, ", "));
}

std::string PointName(const SweepAxis& x, const SweepAxis* y, std::size_t index) {
  const std::size_t ny = y ? y->values.size() : 1;
  std::string name = fmt::format("{} {}", x.name, Display(x, x.values[index / ny]));
  if (y) name += fmt::format(", {} {}", y->name, Display(*y, y->values[index % ny]));
  return name;
}

/// A progress bar on a terminal, drawn only once the sweep has run for a while.
class ProgressBar {
 public:
  explicit ProgressBar(bool enabled) : enabled_(enabled) {}
  ~ProgressBar() { Finish(); }
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void Update(std::size_t done, std::size_t total) {
    if (!enabled_ || total == 0) return;
    const auto now = Clock::now();
    if (now - start_ < std::chrono::milliseconds(300)) return;
    if (drawn_ && now - last_ < std::chrono::milliseconds(100) && done < total) return;
    last_ = now;
    drawn_ = true;
    constexpr int kWidth = 40;
    const double fraction = static_cast<double>(done) / static_cast<double>(total);
    const int filled = static_cast<int>(fraction * kWidth);
    fmt::print(stderr, "\rsweep [{}{}] {:3.0f} % {}/{}", std::string(filled, '#'),
               std::string(kWidth - filled, ' '), 100.0 * fraction, done, total);
    std::fflush(stderr);
  }
  void Finish() {
    if (drawn_) {
      fmt::print(stderr, "\r\033[K");
      std::fflush(stderr);
      drawn_ = false;
    }
  }

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  bool drawn_ = false;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_ = start_;
};

}  // namespace

SweepAxis ParseSweepAxis(std::string_view text, std::string_view flag) {
  const auto fail = [&](const std::string& problem) -> void {
    throw InputError(fmt::format("{}: {} (got '{}')", flag, problem, text));
  };
  const std::size_t eq = text.find('=');
  if (eq == std::string_view::npos) {
    fail("expected NAME=LO..HI[:lin|:log][:N] or NAME=V1,V2,... (items may mix ranges and "
         "values), e.g. covering-thickness=0..50mm:101");
  }
  const std::string_view name = Trim(text.substr(0, eq));
  const std::string_view spec = Trim(text.substr(eq + 1));
  SweepAxis axis;
  axis.field = FindField(name);
  if (axis.field == nullptr) {
    fail(fmt::format("unknown quantity '{}'; the quantities are {}", name, AxisNames()));
  }
  axis.name = std::string(AxisName(*axis.field));
  axis.spec = std::string(spec);
  const QuantitySpec& quantity = axis.field->spec;
  if (spec.empty()) fail(fmt::format("no values after '{}='", name));

  // A value's own message names the item; in a list, also say where it is.
  const auto in_spec = [&](const auto& parse) {
    try {
      return parse();
    } catch (const std::invalid_argument& e) {
      throw InputError(fmt::format("{} in '{}'", e.what(), text));
    }
  };

  // A range LO..HI[:lin|:log][:N], appended to the values.
  const auto add_range = [&](std::string_view item) {
    SweepAxisPart part;
    part.range = true;
    part.count = kDefaultCount;
    std::size_t colon = item.find(':');
    const std::string_view range_text = Trim(item.substr(0, colon));
    bool count_given = false, spacing_given = false;
    while (colon != std::string_view::npos) {
      const std::size_t next = item.find(':', colon + 1);
      const std::string_view option = Trim(item.substr(
          colon + 1, next == std::string_view::npos ? std::string_view::npos : next - colon - 1));
      colon = next;
      if (option == "lin" || option == "log") {
        if (spacing_given) fail("give the spacing (lin or log) once per range");
        spacing_given = true;
        part.log = option == "log";
        continue;
      }
      std::size_t n = 0;
      const auto [end, ec] = std::from_chars(option.data(), option.data() + option.size(), n);
      if (ec != std::errc() || end != option.data() + option.size() || option.empty()) {
        fail(fmt::format("after the range, expected ':lin', ':log' or a count ':N', not ':{}'",
                         option));
      }
      if (count_given) fail("give the count :N once per range");
      count_given = true;
      if (n < 2 || n > kMaxAxisValues) {
        fail(fmt::format("the count after ':' must be in 2..{}", kMaxAxisValues));
      }
      part.count = n;
    }
    const materials::Range range = in_spec([&] { return ParseRange(range_text, quantity, flag); });
    if (!range.min || !range.max) fail("a sweep range needs both ends, LO..HI");
    const double lo = *range.min, hi = *range.max;
    if (!std::isfinite(lo) || !std::isfinite(hi)) {
      fail("a range needs finite ends; list 'fixed' or 'flat' as a value instead, e.g. "
           "robot-mass=5kg..50kg:10,fixed");
    }
    if (!(lo < hi)) fail("the range's low end must be below its high end");
    if (part.log && !(lo > 0.0)) fail("a :log range needs a low end above 0");
    if (axis.values.size() + part.count > kMaxAxisValues) {
      fail(fmt::format("more than {} values", kMaxAxisValues));
    }
    part.low = lo;
    part.high = hi;
    const std::size_t first = axis.values.size();
    for (std::size_t i = 0; i < part.count; ++i) {
      const double k = static_cast<double>(i), n = static_cast<double>(part.count - 1);
      axis.values.push_back(
          part.log ? std::pow(10.0, std::log10(lo) + (std::log10(hi) - std::log10(lo)) * k / n)
                   : lo + (hi - lo) * k / n);
    }
    axis.values[first] = lo;
    axis.values.back() = hi;
    axis.parts.push_back(part);
  };

  // A comma list whose items are ranges or single values; one range alone is the old form.
  std::string_view rest = spec;
  while (true) {
    const std::size_t comma = rest.find(',');
    const std::string_view item = Trim(rest.substr(0, comma));
    if (item.empty()) fail("empty value in the list");
    if (item.find("..") != std::string_view::npos) {
      add_range(item);
    } else {
      if (axis.values.size() + 1 > kMaxAxisValues) {
        fail(fmt::format("more than {} values", kMaxAxisValues));
      }
      const double value = in_spec([&] { return ParseQuantity(item, quantity, flag); });
      axis.values.push_back(value);
      axis.parts.push_back(SweepAxisPart{value, value, 1, false, false});
    }
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  // A log axis when a range asked for it and every finite value can sit on it.
  const bool any_log = std::any_of(axis.parts.begin(), axis.parts.end(),
                                   [](const SweepAxisPart& p) { return p.log; });
  const bool all_positive = std::all_of(axis.values.begin(), axis.values.end(),
                                        [](double v) { return !std::isfinite(v) || v > 0.0; });
  axis.log = any_log && all_positive;
  return axis;
}

std::span<const std::string_view> SweepResultColumns() noexcept { return kResultColumnNames; }

SweepCsvWriter::SweepCsvWriter(const SweepAxis& x, const SweepAxis* y, Sink sink)
    : x_(x), y_(y), sink_(std::move(sink)) {
  x_texts_.reserve(x.values.size());
  for (const double value : x.values) x_texts_.push_back(AxisValueText(x, value));
  if (y) {
    y_texts_.reserve(y->values.size());
    for (const double value : y->values) y_texts_.push_back(AxisValueText(*y, value));
  }
  const auto out = std::back_inserter(buffer_);
  fmt::format_to(out, "{}", x.name);
  if (y) fmt::format_to(out, ",{}", y->name);
  fmt::format_to(out, ",status");
  for (const ResultColumn& column : kResultColumns) fmt::format_to(out, ",{}", column.name);
  fmt::format_to(out, ",warnings,error\n");
}

void SweepCsvWriter::Write(std::span<const SweepRow> rows) {
  constexpr std::size_t kFlushBytes = std::size_t{1} << 20;
  const auto append = [this](std::string_view text) {
    buffer_.append(text.data(), text.data() + text.size());
  };
  const auto out = std::back_inserter(buffer_);
  for (const SweepRow& row : rows) {
    append(x_texts_[row.ix]);
    if (y_) {
      buffer_.push_back(',');
      append(y_texts_[row.iy]);
    }
    append(row.valid ? ",ok" : ",invalid");
    for (const ResultColumn& column : kResultColumns) {
      buffer_.push_back(',');
      if (!row.valid) continue;
      const double v = column.value(row);
      if (column.digit) {
        buffer_.push_back(static_cast<char>('0' + static_cast<int>(v)));
      } else if (std::isfinite(v)) {
        fmt::format_to(out, FMT_COMPILE("{}"), v);
      }
    }
    buffer_.push_back(',');
    if (row.valid) AppendCsvWarnings(buffer_, row.warnings);
    buffer_.push_back(',');
    AppendCsvText(buffer_, row.error);
    buffer_.push_back('\n');
    if (buffer_.size() >= kFlushBytes) Flush();
  }
}

void SweepCsvWriter::Finish() { Flush(); }

void SweepCsvWriter::Flush() {
  if (buffer_.size() == 0) return;
  sink_(std::string_view(buffer_.data(), buffer_.size()));
  buffer_.clear();
}

covopt::SweepSpec MakeSweepSpec(const SweepAxis& x, const SweepAxis* y,
                                const SimulationPlan& plan) {
  covopt::SweepSpec spec;
  spec.scene = plan.scene;
  spec.x = {x.name, x.values};
  if (y) spec.y = covopt::SweepAxis{y->name, y->values};
  spec.limits = plan.limits;
  spec.safety_factor = plan.safety_factor;
  return spec;
}

std::size_t SweepBlockRows(std::size_t points, unsigned threads) {
  const std::size_t per_block = points / (8 * std::max(1u, threads)) + 1;
  return std::clamp<std::size_t>(per_block, 16, 1024);
}

CLI::App* SetupSweep(CLI::App& app, SweepOptions& options) {
  CLI::App* sub = app.add_subcommand(
      "sweep", "Sweep one or two scene quantities over a grid (exact path, or the time path where the "
               "scene needs it; all cores): CSV of "
               "every point, and a map or line chart of the injury ratios");
  sub->footer(std::string(kFooter));
  sub->add_option("--x", options.x, "first swept quantity, e.g. covering-modulus=0.1MPa..1GPa:log:200")
      ->type_name("NAME=SPEC")
      ->required()
      ->group("Sweep");
  sub->add_option("--y", options.y, "second swept quantity, e.g. covering-thickness=0..50mm:200")
      ->type_name("NAME=SPEC")
      ->group("Sweep");
  sub->add_option("--threads", options.threads,
                  "worker threads (default: all cores); results do not depend on it")
      ->type_name("N")
      ->group("Sweep");

  AddSceneOptions(*sub, options.scene);

  sub->add_option("--csv", options.csv_file,
                  "write one row per point (SI units); '-' prints it on stdout instead of the "
                  "summary")
      ->type_name("FILE.csv|-")
      ->group("Output");
  sub->add_option("--plot", options.plot_file,
                  "chart with gnuplot: worst-ratio map with both limit contours and the "
                  "full-compression boundary, or line families when an axis has at most 8 "
                  "values")
      ->type_name("FILE.png|FILE.svg")
      ->group("Output");
  sub->add_option("--plot-quantity", options.plot_quantity,
                  "what the chart shows instead of the injury ratios: a CSV result column, "
                  "e.g. max_compressive_stress_Pa, peak_force_N, contact_duration_s")
      ->type_name("COLUMN")
      ->group("Output");
  sub->add_flag("--no-progress", options.no_progress,
                "no progress bar (it is shown only on a terminal, for long sweeps)")
      ->group("Output");
  return sub;
}

int RunSweep(const SweepOptions& options, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "sweep");

  // Axes, scene and outputs.
  SweepAxis x;
  std::optional<SweepAxis> y;
  SimulationPlan plan;
  std::optional<PlotFormat> plot_format;
  unsigned threads = 0;
  const ResultColumn* quantity = nullptr;
  try {
    x = ParseSweepAxis(options.x, "--x");
    if (options.y) {
      y = ParseSweepAxis(*options.y, "--y");
      if (y->field == x.field) {
        throw InputError(fmt::format("--y: {} is already swept by --x (got '{}')", y->name,
                                     *options.y));
      }
    }
    if (x.values.size() * (y ? y->values.size() : 1) > kMaxSweepPoints) {
      throw InputError(fmt::format("the grid has {} x {} = {} points; at most {} are allowed",
                                   x.values.size(), y->values.size(),
                                   x.values.size() * y->values.size(), kMaxSweepPoints));
    }
    for (const SweepAxis* axis : {&x, y ? &*y : nullptr}) {
      if (axis == nullptr) continue;
      const std::string key = axis->field->dotted_name();
      const auto typed = options.scene.scene_values.find(key);
      if (typed != options.scene.scene_values.end()) {
        throw InputError(fmt::format("{} '{}' sets {}, which {} sweeps; give it one way",
                                     axis->field->flag, typed->second, key,
                                     axis == &x ? "--x" : "--y"));
      }
      if (options.scene.material &&
          (key == "covering.modulus" || key == "covering.poisson")) {
        throw InputError(fmt::format("--material '{}' sets {}, which {} sweeps; give it one way",
                                     *options.scene.material, key, axis == &x ? "--x" : "--y"));
      }
    }
    plan = ResolveSimulation(options.scene);
    if (options.threads) {
      if (*options.threads < 0 || *options.threads > kMaxThreads) {  // 0 = all cores, as elsewhere
        throw InputError(
            fmt::format("--threads must be in 0..{}, 0 = all cores (got {})", kMaxThreads, *options.threads));
      }
      threads = static_cast<unsigned>(*options.threads);
    }
    if (options.csv_file && options.csv_file->empty()) throw InputError("--csv: empty file name");
    if (options.plot_quantity) {
      quantity = FindColumn(*options.plot_quantity);
      if (quantity == nullptr) {
        throw InputError(fmt::format("--plot-quantity: no result column '{}'; the columns are {}",
                                     *options.plot_quantity,
                                     fmt::join(kResultColumnNames, ", ")));
      }
      if (!options.plot_file) throw InputError("--plot-quantity applies only with --plot FILE");
    }
    if (options.plot_file) {
      plot_format = PlotFormatFor(*options.plot_file);
      if (!plot_format) {
        throw InputError(fmt::format(
            "--plot: cannot tell the format of '{}'; name the file *.png or *.svg",
            *options.plot_file));
      }
    }
  } catch (const InputError& e) {
    return errors.BadInput(e.what());
  }
  const SweepAxis* y_axis = y ? &*y : nullptr;

  // The scene without the swept quantities, for the summary and the chart titles.
  std::vector<std::string_view> swept_fields;
  std::vector<std::string> swept_names{x.field->dotted_name()};
  if (y) swept_names.push_back(y->field->dotted_name());
  for (const std::string& name : swept_names) swept_fields.push_back(name);
  std::string scene_line = SceneHeadline(plan.scene, swept_fields);
  if (const auto details = SceneDetailsBeyondHeadline(plan.scene, swept_fields); !details.empty()) {
    scene_line += fmt::format("; {}", fmt::join(details, ", "));
  }

  // Outputs that can fail are checked or opened before the sweep: a missing gnuplot or an
  // unwritable CSV file costs no computation and leaves no file.
  const bool csv_to_stdout = options.csv_file && *options.csv_file == "-";
  std::vector<std::string> written;
  if (plot_format && !FindOnPath("gnuplot")) return errors.Failed(kGnuplotMissing);
  std::optional<OutputFile> csv_file;  // cli/output.hpp: the one file writer
  std::optional<SweepCsvWriter> csv;
  try {
    if (options.csv_file && !csv_to_stdout) {
      csv_file.emplace(*options.csv_file);
      csv.emplace(x, y_axis, [&csv_file](std::string_view text) { csv_file->Write(text); });
    } else if (csv_to_stdout) {
      csv.emplace(x, y_axis, [&out](std::string_view text) {
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        if (!out) throw OutputError("cannot write the results to standard output");
      });
    }
  } catch (const OutputError& e) {
    return errors.Failed(e.what());
  }

  // The sweep: rows stream into the CSV and, for a chart, into the few numbers it draws.
  const covopt::SweepSpec spec = MakeSweepSpec(x, y_axis, plan);
  const std::size_t points = x.values.size() * (y ? y->values.size() : 1);
  const unsigned wanted_threads =
      threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
  covopt::SweepOptions sweep;
  sweep.threads = wanted_threads;
  sweep.block_rows = SweepBlockRows(points, wanted_threads);
  const bool terminal =
      !options.no_progress && &err == &std::cerr && ::isatty(STDERR_FILENO) == 1;
  ProgressBar bar(terminal);
  sweep.progress = [&bar](std::size_t done, std::size_t total) { bar.Update(done, total); };
  std::vector<ChartPoint> chart;
  if (plot_format) chart.reserve(points);
  covopt::SweepResult result;
  try {
    result = covopt::Sweep(spec, sweep, [&](std::span<const SweepRow> rows) {
      if (csv) csv->Write(rows);
      if (plot_format) {
        for (const SweepRow& row : rows) chart.push_back(ChartPointOf(row, quantity));
      }
    });
    if (csv) csv->Finish();
    if (csv_file) {
      csv_file->Commit();
      written.push_back(*options.csv_file);
    }
  } catch (const OutputError& e) {
    bar.Finish();
    return errors.Failed(e.what());
  } catch (const std::invalid_argument& e) {  // the library refused the spec
    bar.Finish();
    return errors.BadInput(e.what());
  }
  bar.Finish();

  try {
    if (plot_format) {
      PlotInput input;
      input.quantity = quantity;
      input.x = &x;
      input.y = y_axis;
      input.points = chart;
      input.limits = plan.limits;
      input.scene_line = scene_line;
      input.safety_factor = plan.safety_factor;
      input.format = *plot_format;
      const bool map = y && x.values.size() > kMaxFamilies && y->values.size() > kMaxFamilies;
      RunGnuplot(*options.plot_file, [&](const std::string& output_path) {
        return map ? MapScript(input, output_path) : FamiliesScript(input, output_path);
      });
      written.push_back(*options.plot_file);
    }
  } catch (const OutputError& e) {
    return errors.Failed(e.what());
  }

  if (!csv_to_stdout) {
    // The summary, counted by the library on the stream.
    const std::size_t valid = result.valid;
    const auto percent = [&](std::size_t n) {
      return valid == 0 ? 0.0 : 100.0 * static_cast<double>(n) / static_cast<double>(valid);
    };
    fmt::print(out, "Sweep   {}: {}\n", x.name, DescribeAxis(x));
    if (y) fmt::print(out, "        {}: {}\n", y->name, DescribeAxis(*y));
    fmt::print(out, "Scene   {}\n", scene_line);
    fmt::print(out, "Points  {} in {:.3g} s on {} thread{}: {} valid, {} invalid{}\n",
               result.rows, result.wall_time_s, result.threads, result.threads == 1 ? "" : "s",
               valid, result.rows - valid,
               result.time_path_rows == 0
                   ? std::string()
                   : fmt::format("; {} on the time path (no energy integral)", result.time_path_rows));
    if (valid > 0) {
      // With a safety factor s, a ratio above 1/s is unsafe (InputWarnings says so).
      fmt::print(out, "Safe    {} ({:.1f} %); laceration ratio > {:.4g} at {} ({:.1f} %), "
                      "contusion ratio > {:.4g} at {} ({:.1f} %)\n",
                 result.safe, percent(result.safe), 1.0 / plan.safety_factor,
                 result.laceration_unsafe, percent(result.laceration_unsafe),
                 1.0 / plan.safety_factor, result.contusion_unsafe,
                 percent(result.contusion_unsafe));
      // The design criterion: safe, and a covering not fully compressed (a bare robot has
      // no covering to bottom out, so safe is enough for it).
      if (result.covered > 0) {
        fmt::print(out, "Full    covering fully compressed at {} of {} covered points ({:.1f} %); "
                        "safe and not fully compressed at {} ({:.1f} %)\n",
                   result.fully_compressed, result.covered,
                   100.0 * static_cast<double>(result.fully_compressed) /
                       static_cast<double>(result.covered),
                   result.admissible, percent(result.admissible));
      }
      for (const auto& [label, extreme] :
           {std::pair{"Least", *result.least}, std::pair{"Most", *result.most}}) {
        fmt::print(out, "{:<7} worst ratio {:.4g} at {} (laceration {:.4g}, contusion {:.4g})\n",
                   label, extreme.worst_ratio, PointName(x, y_axis, extreme.index),
                   extreme.laceration_ratio, extreme.contusion_ratio);
      }
    }
    if (result.first_invalid) {
      const std::size_t invalid = result.rows - valid;
      fmt::print(out, "Invalid {} point{} outside the model's input range, e.g. at {}: {}\n",
                 invalid, invalid == 1 ? "" : "s", PointName(x, y_axis, *result.first_invalid),
                 result.first_invalid_error);
    }
    if (result.first_warned) {
      fmt::print(out, "Warned  {} point{} with validity warnings, e.g. at {}: {}\n",
                 result.warned, result.warned == 1 ? "" : "s",
                 PointName(x, y_axis, *result.first_warned), result.first_warning.message);
    }
    for (const std::string& warning : InputWarnings(plan)) {
      fmt::print(out, "Note    {}\n", warning);
    }
    if (!written.empty()) fmt::print(out, "Wrote   {}\n", fmt::join(written, ", "));
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace covopt::cli
