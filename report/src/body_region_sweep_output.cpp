#include "covopt/report/body_region_sweep_output.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "covopt/core/quantity.hpp"
#include "covopt/report/csv.hpp"

namespace covopt::report {
namespace {

std::string AxisText(const SweepAxisArgument& axis, double value) {
  if (std::isinf(value) && value > 0) return axis.field->spec.allow_flat ? "flat" : "fixed";
  return fmt::format("{}", value);
}

/// The axis's CSV header: its name and SI unit, "speed [m/s]" ("[-]" for a pure number).
std::string AxisHeader(const SweepAxisArgument& axis) {
  const std::string_view unit = SiUnit(axis.field->spec.kind);
  return fmt::format("{} [{}]", axis.name, unit.empty() ? "-" : unit);
}

/// A value of the axis with its SI unit for the summary: "10 kg", "fixed".
std::string AxisValue(const SweepAxisArgument& axis, double value) {
  const std::string text = AxisText(axis, value);
  const std::string_view unit = SiUnit(axis.field->spec.kind);
  return std::isfinite(value) && !unit.empty() ? fmt::format("{} {}", text, unit) : text;
}

std::string Number(double value) { return std::isfinite(value) ? fmt::format("{}", value) : std::string(); }

constexpr std::string_view kColumns[] = {"peak_force_N",      "peak_pressure_Pa", "covering_deflection_m",
                                         "fully_compressed",  "force_ratio",      "pressure_ratio",
                                         "compression_ratio", "crush_ratio",      "governing",
                                         "governing_ratio",   "admissible",       "error"};

/// The cells of a point with a verdict, after the axes.
std::vector<std::string> VerdictCells(const optim::BodyRegionJudgement& v) {
  const BodyContactResult& c = v.contact;
  return {Number(c.peak_force_N),
          c.peak_pressure_Pa ? Number(*c.peak_pressure_Pa) : std::string(),
          Number(c.covering_deflection_m),
          std::string(c.fully_compressed ? "1" : "0"),
          Number(v.force_ratio),
          v.pressure_ratio ? Number(*v.pressure_ratio) : std::string(),
          Number(v.compression_ratio),
          v.crush_check == optim::CrushCheck::kChecked ? Number(v.crush_ratio) : std::string(),
          std::string(optim::ToString(v.governing)),
          Number(v.governing_ratio),
          std::string(v.admissible ? "1" : "0"),
          std::string()};
}

}  // namespace

BodyRegionSweepTable LayOutBodyRegionSweep(std::span<const optim::BodyRegionSweepPoint> grid,
                                           const SweepAxisArgument& x, const SweepAxisArgument* y) {
  BodyRegionSweepTable t;
  std::vector<std::string> header{AxisHeader(x)};
  if (y) header.push_back(AxisHeader(*y));
  header.insert(header.end(), std::begin(kColumns), std::end(kColumns));
  AppendCsvRecord(t.csv, header);
  const std::vector<double> y_values = y ? y->values : std::vector<double>{0.0};
  for (std::size_t iy = 0; iy < y_values.size(); ++iy) {
    const double yv = y_values[iy];
    for (std::size_t ix = 0; ix < x.values.size(); ++ix) {
      const double xv = x.values[ix];
      const optim::BodyRegionSweepPoint& point = grid[ix * y_values.size() + iy];
      std::vector<std::string> row{AxisText(x, xv)};
      if (y) row.push_back(AxisText(*y, yv));
      ++t.points;
      if (point.judgement) {
        const optim::BodyRegionJudgement& v = *point.judgement;
        for (std::string& cell : VerdictCells(v)) row.push_back(std::move(cell));
        if (v.admissible) ++t.admissible;
        if (v.governing_ratio > t.worst) {
          t.worst = v.governing_ratio;
          t.worst_at = fmt::format("{} = {}{}, {}", x.name, AxisValue(x, xv),
                                   y ? fmt::format(", {} = {}", y->name, AxisValue(*y, yv)) : std::string(),
                                   optim::ToString(v.governing));
        }
      } else {  // a point outside the model's range
        ++t.invalid;
        row.resize(row.size() + std::size(kColumns) - 1);
        row.push_back(point.error);
      }
      AppendCsvRecord(t.csv, row);
    }
  }
  return t;
}

BodyRegionSweepColumns BodyRegionSweepColumnsOf(std::span<const optim::BodyRegionSweepPoint> grid,
                                                const materials::BodyLimits& limits) {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  using Judgement = optim::BodyRegionJudgement;
  struct Column {
    std::string_view name;
    double (*value)(const Judgement&);
    bool flag;
  };
  // clang-format off
  static constexpr Column kColumns[] = {
    {"peak_force_N", [](const Judgement& v) { return v.contact.peak_force_N; }, false},
    {"peak_pressure_Pa", [](const Judgement& v) { return v.contact.peak_pressure_Pa.value_or(kNaN); }, false},
    {"covering_deflection_m", [](const Judgement& v) { return v.contact.covering_deflection_m; }, false},
    {"fully_compressed", [](const Judgement& v) { return v.contact.fully_compressed ? 1.0 : 0.0; }, true},
    {"force_ratio", [](const Judgement& v) { return v.force_ratio; }, false},
    {"pressure_ratio", [](const Judgement& v) { return v.pressure_ratio.value_or(kNaN); }, false},
    {"compression_ratio", [](const Judgement& v) { return v.compression_ratio; }, false},
    {"crush_ratio", [](const Judgement& v) { return v.crush_check == optim::CrushCheck::kChecked ? v.crush_ratio : kNaN; }, false},
    {"governing_ratio", [](const Judgement& v) { return v.governing_ratio; }, false},
    {"admissible", [](const Judgement& v) { return v.admissible ? 1.0 : 0.0; }, true},
  };
  // clang-format on
  BodyRegionSweepColumns out;
  for (const Column& column : kColumns) {
    BodyRegionSweepColumn& c = out.columns.emplace_back(BodyRegionSweepColumn{column.name, column.flag, {}});
    c.values.reserve(grid.size());
    for (const optim::BodyRegionSweepPoint& point : grid) {
      c.values.push_back(point.judgement ? column.value(*point.judgement) : (column.flag ? 0.0 : kNaN));
    }
  }
  std::size_t admissible = 0;
  std::size_t invalid = 0;
  for (const optim::BodyRegionSweepPoint& point : grid) {
    out.valid.push_back(point.judgement.has_value());
    out.governing.push_back(point.judgement ? std::string(optim::ToString(point.judgement->governing)) : std::string());
    out.errors.push_back(point.error);
    if (point.judgement && point.judgement->admissible) ++admissible;
    if (!point.judgement) ++invalid;
  }
  out.message = fmt::format("{} ({}) ({} contact): {} points, {} within every limit, {} outside the model's range",
                            limits.region->name, limits.area->name, ToString(limits.contact), grid.size(), admissible,
                            invalid);
  return out;
}

}  // namespace covopt::report
