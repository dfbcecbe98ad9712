// A streamed sweep, each point on the exact path or, where the scene has no energy integral,
// on the time path (covopt/core/sweep.hpp).
//
// The grid is cut into blocks of block_rows rows, computed on ParallelForOrdered's threads
// into a ring of 2 x threads slots and handed to the consumer strictly in order on the calling
// thread, which bounds memory by the ring whatever the grid's size (parallel_for.hpp).
// Each row is written only by the thread that computed it from its own scene, so neither
// the order of work nor the number of threads changes a result.
#include "covopt/core/sweep.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/number_format.hpp"
#include "covopt/core/parallel_for.hpp"
#include "covopt/core/scene_fields.hpp"
#include "covopt/core/solve.hpp"
#include "numeric_format.hpp"

namespace covopt {
namespace {

constexpr unsigned kMaxThreads = 4096;
constexpr std::size_t kMaxBlockRows = 1000000;
constexpr double kMaxSafetyFactor = 100.0;

using internal::FormatNumber;

/// The field an axis sweeps, checked; `name` is "x" or "y" for messages.
const SceneField& CheckAxis(const SweepAxis& axis, const char* name) {
  const SceneField* field = FindSceneField(axis.quantity);
  if (field == nullptr) {
    throw std::invalid_argument(std::string(name) + ".quantity: no scene quantity '" +
                                axis.quantity + "'; the quantities are " + SceneFieldNames() +
                                " (or their dotted names, e.g. robot.speed)");
  }
  if (axis.values.empty()) {
    throw std::invalid_argument(std::string(name) + ".values: no values for " +
                                std::string(field->name) + "; give at least one");
  }
  for (std::size_t i = 0; i < axis.values.size(); ++i) {
    if (std::isnan(axis.values[i])) {
      throw std::invalid_argument(std::string(name) + ".values[" + std::to_string(i) +
                                  "] must be a number, or +inf for fixed/flat (got nan)");
    }
  }
  return *field;
}

/// Solves one grid point into `row` (every field overwritten: slots are reused).
void SolveRow(const SweepSpec& spec, const SweepOptions& options, const SceneField& x_field,
              const SceneField* y_field, std::size_t ny, std::size_t index, SweepRow& row) {
  row.index = index;
  row.ix = index / ny;
  row.iy = index % ny;
  row.x = spec.x.values[row.ix];
  row.y = y_field ? spec.y->values[row.iy] : 0.0;
  Scene scene = spec.scene;
  x_field.field(scene) = row.x;
  if (y_field) y_field->field(scene) = row.y;
  row.covered = scene.covering.thickness_m > 0.0;
  row.warnings.clear();
  SolveOptions solve;  // the automatic choice, without a history
  solve.exact = options.exact;
  solve.time_path = options.time_path;
  const bool exact = ChoosePath(scene, solve) == PathChoice::kExact;
  row.method = exact ? ComputationMethod::kExact : options.time_path.method;
  try {
    ImpactResult result = Solve(scene, solve);
    if (!result.ok()) {
      throw std::invalid_argument("the time path (" + std::string(ToString(solve.time_path.method)) + ") failed: " +
                                  std::string(ToString(result.status)) + ": " + result.message);
    }
    row.valid = true;
    row.error.clear();
    row.peaks = result.peaks;
    row.contact_duration_s = result.contact_duration_s;
    row.time_of_max_compression_s = result.time_of_max_compression_s;
    row.rebound_speed_m_per_s = result.rebound_speed_m_per_s.value_or(0.0);
    row.coefficient_of_restitution = result.coefficient_of_restitution.value_or(0.0);
    row.assessment = Assess(result.peaks, spec.limits, scene.head.area);
    for (InjuryVerdict* verdict :
         {&row.assessment.laceration, &row.assessment.contusion, &row.assessment.fracture}) {
      verdict->safe = spec.safety_factor * verdict->ratio <= 1.0;
    }
    row.worst_ratio = std::max(row.assessment.laceration.ratio, row.assessment.contusion.ratio);
    row.compression_ratio = result.peaks.covering_compression_ratio();
    row.admissible = row.assessment.safe() &&
                     !(row.covered && (result.peaks.fully_compressed ||
                                       spec.safety_factor * row.compression_ratio > 1.0));
    row.warnings = std::move(result.warnings);
  } catch (const std::invalid_argument& e) {
    row.valid = false;
    row.error = e.what();
    row.peaks = {};
    row.contact_duration_s.reset();
    row.time_of_max_compression_s.reset();
    row.rebound_speed_m_per_s = 0.0;
    row.coefficient_of_restitution = 0.0;
    row.assessment = {};
    row.worst_ratio = 0.0;
    row.compression_ratio = 0.0;
    row.admissible = false;
  }
}

/// The summary, one row at a time, in grid order.
void Count(const SweepRow& row, SweepResult& r) {
  ++r.rows;
  if (row.method != ComputationMethod::kExact) ++r.time_path_rows;
  if (!row.valid) {
    if (!r.first_invalid) {
      r.first_invalid = row.index;
      r.first_invalid_error = row.error;
    }
    return;
  }
  ++r.valid;
  if (row.assessment.safe()) ++r.safe;
  if (!row.assessment.laceration.safe) ++r.laceration_unsafe;
  if (!row.assessment.contusion.safe) ++r.contusion_unsafe;
  if (row.covered) {
    ++r.covered;
    if (row.peaks.fully_compressed) ++r.fully_compressed;
  }
  if (row.admissible) ++r.admissible;
  if (!row.warnings.empty()) {
    ++r.warned;
    if (!r.first_warned) {
      r.first_warned = row.index;
      r.first_warning = row.warnings.front();
    }
  }
  const SweepExtreme extreme{row.index, row.worst_ratio, row.assessment.laceration.ratio,
                             row.assessment.contusion.ratio};
  if (!r.least || row.worst_ratio < r.least->worst_ratio) r.least = extreme;
  if (!r.most || row.worst_ratio > r.most->worst_ratio) r.most = extreme;
}

std::string Percent(std::size_t n, std::size_t of) {
  return FormatFixed(of == 0 ? 0.0 : 100.0 * static_cast<double>(n) / static_cast<double>(of), 1) + " %";
}

std::string Short(double value) { return FormatSignificant(value, 4); }

}  // namespace

std::string_view ToString(SweepStatus status) noexcept {
  switch (status) {
    case SweepStatus::kAllValid: return "all-valid";
    case SweepStatus::kSomeInvalid: return "some-invalid";
    case SweepStatus::kNoneValid: return "none-valid";
  }
  return "unknown";
}

std::string SweepResult::BriefReport() const {
  std::string text = "sweep: " + std::to_string(rows) + " point" + (rows == 1 ? "" : "s");
  if (y_values > 0) {
    text += " (" + std::to_string(x_values) + " x " + std::to_string(y_values) + ")";
  }
  text += " in " + FormatSignificant(wall_time_s, 3) + " s on " + std::to_string(threads) + " thread" +
          (threads == 1 ? ": " : "s: ");
  switch (status) {
    case SweepStatus::kAllValid: text += "all valid"; break;
    case SweepStatus::kSomeInvalid:
      text += std::to_string(valid) + " valid, " + std::to_string(rows - valid) + " invalid";
      break;
    case SweepStatus::kNoneValid: return text + "none valid: " + first_invalid_error;
  }
  if (time_path_rows > 0) text += "; " + std::to_string(time_path_rows) + " on the time path";
  text += "; safe " + Percent(safe, valid) + ", admissible " + Percent(admissible, valid);
  if (least && most) {
    text += "; worst ratio " + Short(least->worst_ratio) + " .. " + Short(most->worst_ratio);
  }
  return text;
}

std::size_t CheckSweepSize(std::size_t nx, std::optional<std::size_t> y_values) {
  const std::size_t ny = y_values.value_or(1);
  for (const auto& [name, count] : {std::pair{"x", nx}, std::pair{"y", y_values.value_or(0)}}) {
    if (count > kMaxSweepAxisValues) {
      throw std::invalid_argument(std::string(name) + ".values: " + std::to_string(count) +
                                  " values is not allowed (at most " + std::to_string(kMaxSweepAxisValues) +
                                  " per axis)");
    }
  }
  // Both at most kMaxSweepAxisValues: the product cannot overflow.
  if (nx * ny > kMaxSweepPoints) {
    throw std::invalid_argument("the grid has " + std::to_string(nx) + " x " + std::to_string(ny) + " = " +
                                std::to_string(nx * ny) + " points; at most " + std::to_string(kMaxSweepPoints) +
                                " are allowed");
  }
  return nx * ny;
}

SweepResult Sweep(const SweepSpec& spec, const SweepOptions& options,
                  const SweepConsumer& consumer) {
  // Check everything before any work.
  const SceneField& x_field = CheckAxis(spec.x, "x");
  const SceneField* y_field = spec.y ? &CheckAxis(*spec.y, "y") : nullptr;
  if (y_field == &x_field) {
    throw std::invalid_argument("y.quantity: " + std::string(x_field.name) +
                                " is already swept by x (got '" + spec.y->quantity + "')");
  }
  const std::size_t nx = spec.x.values.size();
  const std::size_t ny = spec.y ? spec.y->values.size() : 1;
  CheckSweepSize(nx, spec.y ? std::optional(ny) : std::nullopt);
  CheckInjuryLimits(spec.limits);
  if (!(spec.safety_factor >= 1.0 && spec.safety_factor <= kMaxSafetyFactor)) {
    throw std::invalid_argument("safety_factor must be in [1, 100] (got " +
                                FormatNumber(spec.safety_factor) + ")");
  }
  if (options.threads > kMaxThreads) {
    throw std::invalid_argument("threads must be <= " + std::to_string(kMaxThreads) +
                                " (got " + std::to_string(options.threads) + ")");
  }
  if (options.block_rows < 1 || options.block_rows > kMaxBlockRows) {
    throw std::invalid_argument("block_rows must be in 1..1000000 (got " +
                                std::to_string(options.block_rows) + ")");
  }
  ValidateTimeIntegrationOptions(options.time_path, "time_path.");
  if (!consumer) throw std::invalid_argument("consumer: empty; give a function to receive the rows");

  const auto start = std::chrono::steady_clock::now();
  const std::size_t total = nx * ny;
  const std::size_t block_rows = options.block_rows;
  const std::size_t blocks = total / block_rows + (total % block_rows != 0 ? 1 : 0);
  const unsigned threads = ParallelThreads(blocks, options.threads);

  SweepResult result;
  result.x_values = nx;
  result.y_values = spec.y ? ny : 0;
  result.threads = threads;

  // One buffer per slot of ParallelForOrdered's ring: at most 2 x threads blocks at once.
  std::vector<std::vector<SweepRow>> slots(2 * static_cast<std::size_t>(threads));
  for (std::vector<SweepRow>& slot : slots) slot.reserve(std::min(block_rows, total));
  ParallelForOrdered(
      blocks, threads, slots.size(),
      [&](std::size_t block, std::size_t slot) {
        std::vector<SweepRow>& rows = slots[slot];
        const std::size_t begin = block * block_rows;
        const std::size_t end = std::min(total, begin + block_rows);
        rows.resize(end - begin);
        for (std::size_t i = begin; i < end; ++i) {
          SolveRow(spec, options, x_field, y_field, ny, i, rows[i - begin]);
        }
      },
      [&](std::size_t, std::size_t slot) {
        const std::vector<SweepRow>& rows = slots[slot];
        for (const SweepRow& row : rows) Count(row, result);
        consumer(std::span<const SweepRow>(rows));
        if (options.progress) options.progress(result.rows, total);
      });

  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::size_t invalid = result.rows - result.valid;
  if (invalid == 0) {
    result.status = SweepStatus::kAllValid;
    result.message = std::to_string(result.rows) + (result.rows == 1 ? " point" : " points") +
                     ", all valid";
  } else {
    result.status = result.valid == 0 ? SweepStatus::kNoneValid : SweepStatus::kSomeInvalid;
    result.message = (result.valid == 0 ? std::string("every point is")
                                        : std::to_string(invalid) + " of " +
                                              std::to_string(result.rows) + " points are") +
                     " outside the model's input range; the first (row " +
                     std::to_string(*result.first_invalid) + "): " + result.first_invalid_error;
  }
  return result;
}

}  // namespace covopt
