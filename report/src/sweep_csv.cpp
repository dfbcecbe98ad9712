#include "covopt/report/sweep_csv.hpp"

#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <string>

#include <fmt/compile.h>

#include "covopt/report/csv.hpp"

namespace covopt::report {
namespace {

using covopt::SweepRow;

/// An axis value for the CSV: SI, or the word for an infinite mass/radius.
std::string AxisValueText(const SweepAxisArgument& axis, double value) {
  if (std::isinf(value) && value > 0) {
    return axis.field->spec.allow_flat ? "flat" : "fixed";
  }
  return fmt::format("{}", value);
}

/// Appends the warnings' messages joined by " | " as one free-text CSV field (nothing when
/// the joined text is empty).
void AppendCsvWarnings(fmt::memory_buffer& out, std::span<const covopt::ValidityWarning> warnings) {
  if (warnings.empty()) return;
  std::string joined;
  for (std::size_t i = 0; i < warnings.size(); ++i) {
    if (i > 0) joined += " | ";
    joined += warnings[i].message;
  }
  AppendCsvField(out, joined, CsvQuote::kAlways);
}

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

}  // namespace

std::span<const ResultColumn> ResultColumns() noexcept { return kResultColumns; }

const ResultColumn* FindResultColumn(std::string_view name) noexcept {
  for (const ResultColumn& column : kResultColumns) {
    if (column.name == name) return &column;
  }
  return nullptr;
}

std::span<const std::string_view> SweepResultColumns() noexcept { return kResultColumnNames; }

SweepCsvWriter::SweepCsvWriter(const SweepAxisArgument& x, const SweepAxisArgument* y, Sink sink)
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
  for (const ResultColumn& column : ResultColumns()) fmt::format_to(out, ",{}", column.name);
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
    for (const ResultColumn& column : ResultColumns()) {
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
    AppendCsvField(buffer_, row.error, CsvQuote::kAlways);
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

}  // namespace covopt::report
