// The design map of `covopt optimize` (--plot and the report): the governing ratio over
// thickness x modulus, a contour per criterion at its limit, the chosen design marked.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "covopt/chart/charts.hpp"
#include "covopt/report/scene_headline.hpp"

#include "chart_script.hpp"

namespace covopt::chart {

using report::SceneHeadline;
using report::SceneDetailsBeyondHeadline;
namespace {

/// The y coordinate of a modulus: log10 of it in MPa.
double Y(double modulus_Pa) { return std::log10(modulus_Pa * 1e-6); }

std::string Value(double v) { return std::isfinite(v) ? fmt::format("{}", v) : std::string("NaN"); }

struct Style {
  std::string_view colour;
  int dashtype;
};
Style StyleOf(optim::LimitingCriterion c) {
  switch (c) {
    case optim::LimitingCriterion::kLaceration: return {"#1f3a93", 1};
    case optim::LimitingCriterion::kContusion: return {"#000000", 2};
    case optim::LimitingCriterion::kFullCompression: return {"#8e44ad", 4};
    case optim::LimitingCriterion::kCrush: return {"#d35400", 5};
    case optim::LimitingCriterion::kFracture: return {"#c0392b", 3};
    case optim::LimitingCriterion::kLawValidity:
    case optim::LimitingCriterion::kNone: break;
  }
  return {"#555555", 1};
}

/// Where a criterion's ratio crosses `level` on the grid, for its label: along the modulus
/// on the columns from `start` (a column index) outwards, the first change of side from the
/// stiffest modulus down, interpolated in log modulus. The labels of the criteria start at
/// different columns so that they do not overlap.
std::optional<std::pair<double, double>> Crossing(const optim::DesignMap& map, optim::LimitingCriterion c,
                                                  double level, std::size_t start) {
  const std::size_t rows = map.modulus_Pa.size(), columns = map.thickness_m.size();
  for (std::size_t k = 0; k < 2 * columns; ++k) {
    const std::size_t i = k % 2 == 0 ? start + k / 2 : start - (k + 1) / 2;  // wraps past 0: skipped
    if (i >= columns) continue;
    for (std::size_t j = rows - 1; j > 0; --j) {
      const double a = optim::CriterionRatio(map.at(i, j), c, map.rule) - level;
      const double b = optim::CriterionRatio(map.at(i, j - 1), c, map.rule) - level;
      if (!std::isfinite(a) || !std::isfinite(b) || (a > 0.0) == (b > 0.0)) continue;
      const double f = a / (a - b);
      const double y = Y(map.modulus_Pa[j]) + f * (Y(map.modulus_Pa[j - 1]) - Y(map.modulus_Pa[j]));
      return std::pair{map.thickness_m[i] * 1e3, y};
    }
  }
  return std::nullopt;
}

/// The grid as a data block ($map: thickness [mm], log10 modulus [MPa], the governing ratio and
/// each criterion's), and each criterion's contour at `level` traced by gnuplot into $contour<k>.
std::string MapData(const optim::DesignMap& map, double level) {
  std::string s = "$map << EOD\n";
  for (std::size_t j = 0; j < map.modulus_Pa.size(); ++j) {
    for (std::size_t i = 0; i < map.thickness_m.size(); ++i) {
      const optim::DesignScore& score = map.at(i, j);
      s += fmt::format("{} {} {}", map.thickness_m[i] * 1e3, Y(map.modulus_Pa[j]),
                       score.failed ? std::string("NaN") : Value(score.governing(map.rule).ratio));
      for (const optim::LimitingCriterion c : map.criteria) {
        s += ' ';
        s += score.failed ? std::string("NaN") : Value(optim::CriterionRatio(score, c, map.rule));
      }
      s += '\n';
    }
    s += '\n';
  }
  s += "EOD\n";
  // Each criterion's contour at its limit, traced by gnuplot into a data block.
  s += "set view map\nset contour base\nunset surface\n";
  s += fmt::format("set cntrparam levels discrete {}\n", level);
  for (std::size_t k = 0; k < map.criteria.size(); ++k) {
    s += fmt::format("set table $contour{}\nsplot $map using 1:2:{} with lines notitle\nunset table\n", k, k + 4);
  }
  s += "unset contour\nset surface\nunset view\n";
  return s;
}

/// "laceration, contusion and full-compression".
std::string CriteriaList(const optim::DesignMap& map) {
  std::string criteria;
  for (std::size_t k = 0; k < map.criteria.size(); ++k) {
    criteria += k == 0 ? "" : k + 1 == map.criteria.size() ? " and " : ", ";
    criteria += optim::ToString(map.criteria[k]);
  }
  return criteria;
}

/// The title: the scene, the oracle, the criteria and safety factor, and the chosen design.
std::string TitleCommand(const optim::DesignMap& map, const std::string& criteria, double level) {
  const std::array<std::string_view, 2> omitted{"covering.thickness", "covering.modulus"};
  std::string scene_line = SceneHeadline(map.scene, omitted);
  if (const auto details = SceneDetailsBeyondHeadline(map.scene, omitted); !details.empty()) {
    for (const std::string& d : details) scene_line += ", " + d;
  }
  std::string chosen_line;
  if (map.chosen && map.chosen_score) {
    const optim::GoverningRatio g = map.chosen_score->governing(map.rule);
    chosen_line = fmt::format("{} ({:.4g} MPa): {} ratio {:.3f} ({}){}", map.chosen->label,
                              map.chosen->design.youngs_modulus_Pa * 1e-6, optim::ToString(g.criterion), g.ratio,
                              map.chosen->admissible ? "admissible" : "NOT admissible",
                              map.material ? fmt::format("; grid with its ν {:g}", map.poisson_ratio) : std::string());
  } else {
    chosen_line = map.message;
  }
  return fmt::format("set title {}\n",
                     internal::GnuplotDoubleQuoted(fmt::format(
                         "covopt optimize: design map, {} ({})\ncriteria {}; safety factor {:g} (every ratio <= {:.4g})\n"
                         "chosen: {}",
                         scene_line, map.oracle.Name(), criteria, map.rule.safety_factor, level, chosen_line)));
}

/// The axes (thickness [mm]; modulus on a log scale with 1-2-5 tics), the colour scale centred
/// on `level`, and the key.
std::string AxesCommands(const optim::DesignMap& map, double level) {
  std::string s = "set xlabel 'covering thickness [mm]'\nset ylabel \"covering Young's modulus [MPa] (log scale)\"\n";
  const double x0 = map.thickness_m.front() * 1e3, x1 = map.thickness_m.back() * 1e3;
  const double y0 = Y(map.modulus_Pa.front()), y1 = Y(map.modulus_Pa.back());
  // with image: each cell centred on its grid point.
  const double dx = (x1 - x0) / static_cast<double>(map.thickness_m.size() - 1) / 2.0;
  const double dy = (y1 - y0) / static_cast<double>(map.modulus_Pa.size() - 1) / 2.0;
  s += fmt::format("set xrange [{}:{}]\nset yrange [{}:{}]\n", x0 - dx, x1 + dx, y0 - dy, y1 + dy);
  s += "set ytics (";
  bool first = true;
  for (int decade = static_cast<int>(std::floor(y0)) - 1; decade <= static_cast<int>(std::ceil(y1)); ++decade) {
    for (const double m : {1.0, 2.0, 5.0}) {
      const double y = decade + std::log10(m);
      if (y < y0 - dy || y > y1 + dy) continue;
      s += fmt::format("{}'{:g}' {}{}", first ? "" : ", ", std::pow(10.0, decade) * m, y, m == 1.0 ? "" : " 1");
      first = false;
    }
  }
  s += ")\nset mxtics\nset tics front\nset grid xtics ytics front linecolor rgb '#ffffff' dashtype 3\n";
  s += fmt::format("set cbrange [0:{}]\n", 2.0 * level);
  s += "set palette defined (0 '#1a7f3c', 0.5 '#8fd18b', 0.98 '#f4f1bb', 1.02 '#fdd49e', 1.5 '#f0793d', 2 '#a50f15')\n";
  s += fmt::format("set cblabel 'governing ratio (the limit 1/safety factor = {:.4g} at the middle)'\n", level);
  s += "set key below maxrows 3 width 2\nset bmargin 7\n";
  return s;
}

/// The labels: each contour's name where it crosses a middle row; the chosen design.
std::string LabelCommands(const optim::DesignMap& map, double level) {
  int label = 1;
  std::string s = "set style textbox opaque fillcolor rgb '#ffffff' noborder margins 2, 1\n";
  const std::size_t columns = map.thickness_m.size();
  for (std::size_t k = 0; k < map.criteria.size(); ++k) {
    const optim::LimitingCriterion c = map.criteria[k];
    const auto start = static_cast<std::size_t>(static_cast<double>(columns - 1) * (0.5 + 0.13 * static_cast<double>(k)));
    if (const auto at = Crossing(map, c, level, std::min(start, columns - 1))) {
      s += fmt::format("set label {} {} at {}, {} front boxed center textcolor rgb '{}'\n", label++,
                       GnuplotQuoted(std::string(optim::ToString(c))), at->first, at->second, StyleOf(c).colour);
    }
  }
  if (map.chosen) {
    s += fmt::format("set label {} {} at {}, {} front boxed offset 1.5, -1 textcolor rgb '#000000'\n", label++,
                     GnuplotQuoted(map.chosen->label), map.chosen->design.thickness_m * 1e3,
                     Y(map.chosen->design.youngs_modulus_Pa));
  }
  return s;
}

/// The plot: the map, each contour, the admissible candidates (when `candidates` holds any) and
/// the chosen design.
std::string PlotCommand(const optim::DesignMap& map, double level, bool candidates) {
  std::string s = "plot $map using 1:2:3 with image notitle";
  for (std::size_t k = 0; k < map.criteria.size(); ++k) {
    const Style style = StyleOf(map.criteria[k]);
    s += fmt::format(
        ", \\\n     $contour{} using 1:2 with lines linewidth 2.5 dashtype {} linecolor rgb '{}' title {}", k,
        style.dashtype, style.colour,
        GnuplotQuoted(fmt::format("{} limit (ratio {:.4g})", optim::ToString(map.criteria[k]), level)));
  }
  if (candidates) {
    s += ", \\\n     $candidates using 1:2 with points pointtype 6 pointsize 1.2 linewidth 1.5 linecolor rgb "
         "'#333333' title 'admissible catalog materials at their recommended thickness (each with its own ν)'";
  }
  if (map.chosen) {
    s += fmt::format(
        ", \\\n     '-' using 1:2 with points pointtype 7 pointsize 2 linecolor rgb '#000000' title {}\n{} {}\ne",
        GnuplotQuoted("chosen: " + map.chosen->label), map.chosen->design.thickness_m * 1e3,
        Y(map.chosen->design.youngs_modulus_Pa));
  }
  return s;
}

}  // namespace

GnuplotChart DesignMapChart(const optim::DesignMap& map) {
  const double level = 1.0 / map.rule.safety_factor;
  const std::string criteria = CriteriaList(map);
  std::string s = MapData(map, level);
  s += TitleCommand(map, criteria, level);
  s += AxesCommands(map, level);
  s += LabelCommands(map, level);
  s += "$candidates << EOD\n";
  std::size_t admissible_candidates = 0;
  for (const optim::DesignMapMark& c : map.candidates) {
    if (!c.admissible) continue;  // an inadmissible one sits at the maximum thickness: nothing to see
    ++admissible_candidates;
    s += fmt::format("{} {}\n", c.design.thickness_m * 1e3, Y(c.design.youngs_modulus_Pa));
  }
  s += "EOD\n";
  s += PlotCommand(map, level, admissible_candidates > 0);
  s += "\nunset output\n";

  return internal::MakeChart(
      "Design map: thickness and modulus of the covering",
      fmt::format("Every covering on a {} x {} grid of thickness [mm] and Young's modulus [MPa, log scale] around the "
                  "answer, scored by the optimiser's {} and coloured by its governing ratio (green: admissible, red: "
                  "not). The lines are the limits of {} at ratio 1/safety factor = {:.4g}: a covering is admissible "
                  "where it is on the safe side of every line. {}",
                  map.thickness_m.size(), map.modulus_Pa.size(), map.oracle.Name(), criteria, level,
                  map.chosen ? fmt::format("The black dot is the chosen design, {}.", map.chosen->label)
                             : std::string("No design is chosen: ") + map.message),
      1100, 800, std::move(s));
}

}  // namespace covopt::chart
