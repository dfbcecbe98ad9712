#pragma once
/// @file sweep_csv.hpp
/// The CSV of `covopt sweep`: its result columns and the writer that streams the rows as
/// they arrive, by covopt's one CSV rule (covopt/report/csv.hpp).

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "covopt/core/sweep.hpp"
#include "covopt/report/sweep_axis.hpp"

namespace covopt::report {

/// The result columns and how each is read; the names are the keys of simulate --json
/// (report::SimulationJson), which tests/cli/test_sweep.cpp checks.
struct ResultColumn {
  std::string_view name;
  double (*value)(const covopt::SweepRow&);
  /// The value is always one of 0..9 (a phase number or a 0/1 flag): the CSV writes its
  /// digit directly, the text "{}" gives.
  bool digit = false;
};
/// Every result column, in the CSV's order.
std::span<const ResultColumn> ResultColumns() noexcept;

/// The result column called `name`; nullptr if none.
const ResultColumn* FindResultColumn(std::string_view name) noexcept;

/// The result columns of the CSV after the swept quantities and `status`, in order: the
/// numeric top-level keys of `simulate --json` (booleans as 0/1), then laceration_ratio,
/// contusion_ratio, worst_ratio.
std::span<const std::string_view> SweepResultColumns() noexcept;

/// Writes the sweep's CSV as its rows arrive: header `<x name>[,<y name>],status,<result
/// columns>,warnings,error`, then one row per point in the order received (grid order: x
/// varying slowest). status is "ok" or "invalid"; an invalid point has empty result fields
/// and the library's message in `error`; `warnings` holds the validity warnings joined by
/// " | ". Numbers are SI, shortest round-trip decimals; an axis value of +inf is "fixed" or
/// "flat". The text is built in one buffer and handed to the sink in pieces of about
/// 1 MiB, so no row costs an allocation.
class SweepCsvWriter {
 public:
  /// Receives the CSV text in order, piece by piece; may throw (OutputError) to stop.
  using Sink = std::function<void(std::string_view text)>;

  /// Buffers the header. `x` and `y` must outlive the writer.
  SweepCsvWriter(const SweepAxisArgument& x, const SweepAxisArgument* y, Sink sink);

  /// Appends the rows (SweepRow::ix, iy index the axes' values).
  void Write(std::span<const covopt::SweepRow> rows);
  /// Hands what is buffered to the sink. Call once after the last rows.
  void Finish();

 private:
  void Flush();

  const SweepAxisArgument& x_;
  const SweepAxisArgument* y_;
  Sink sink_;
  std::vector<std::string> x_texts_;  // each axis value as the CSV shows it
  std::vector<std::string> y_texts_;
  fmt::memory_buffer buffer_;
};

}  // namespace covopt::report
