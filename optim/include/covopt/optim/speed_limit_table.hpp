#pragma once
/// @file speed_limit_table.hpp
/// A speed-limit table: the max safe speed per reflected robot mass (or the max safe mass per
/// speed) for one or more coverings, one row per (covering, value). `covopt speed-limit` and
/// `covopt.speed_limit()` both compute their rows with SpeedLimitTable; report::SpeedLimitJson
/// writes them out.

#include <cstddef>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <covopt/core/scene.hpp>

#include "covopt/optim/speed_limit.hpp"

namespace covopt::optim {

/// What a speed-limit table solves for.
enum class SpeedLimitQuantity {
  kSpeed,  ///< the max safe speed, one row per reflected mass (MaxSafeSpeed)
  kMass,   ///< the max safe reflected mass, one row per speed (MaxSafeMass)
};
/// "speed" or "mass".
std::string_view ToString(SpeedLimitQuantity quantity) noexcept;

/// One row of a speed-limit table: the input that varies and the library's answer, either a
/// limit for the row's scene (SpeedLimitRow) or one safe over an uncertainty box
/// (RobustSpeedLimitRow, robust_search.hpp).
template <typename SpeedAnswer, typename MassAnswer>
struct BasicSpeedLimitRow {
  /// The catalog name of the row's covering, if it came from the catalog (SpeedLimitTable:
  /// and the scene has a covering).
  std::optional<std::string> material;
  /// The row's reflected robot mass [kg] (+inf: fixed); used when solving for the speed.
  double robot_mass_kg = 0.0;
  /// The row's impact speed [m/s]; used when solving for the mass.
  double speed_m_per_s = 0.0;
  /// The answer when solving for the speed (MaxSafeSpeed, MaxSafeSpeedOverBox) or for the mass
  /// (MaxSafeMass, MaxSafeMassOverBox).
  SpeedAnswer speed_limit;
  MassAnswer mass_limit;
};
/// A row of SpeedLimitTable.
using SpeedLimitRow = BasicSpeedLimitRow<SpeedLimit, MassLimit>;

/// One covering of a table: the scene the rows vary and the options it is judged with.
struct SpeedLimitCovering {
  /// The scene; its robot mass (solving for the speed) or speed (for the mass) is each row's.
  Scene scene;
  /// The catalog name of the covering material, if it came from the catalog.
  std::optional<std::string> material;
  /// The criterion, limits and oracle, with this covering's compressive strength
  /// (CrushCheckFor).
  SpeedLimitOptions options;
};

/// SpeedLimitTable's error for a bad scene or bad options: the library's message, and which
/// covering it was (so that a caller can say where its inputs came from).
class SpeedLimitTableError : public std::invalid_argument {
 public:
  SpeedLimitTableError(const std::string& message, std::size_t covering_index)
      : std::invalid_argument(message), covering_index_(covering_index) {}
  /// The index into SpeedLimitTable's `coverings`.
  std::size_t covering_index() const noexcept { return covering_index_; }

 private:
  std::size_t covering_index_;
};

/// The table: for each covering in order, one row per value of `values` — robot masses [kg]
/// (+inf: fixed) when solving for the speed, speeds [m/s] when solving for the mass — with
/// MaxSafeSpeed / MaxSafeMass of the covering's scene at that value. A row whose oracle failed
/// has status kEvaluationFailed (no answer; see FirstFailedRow).
/// @throws SpeedLimitTableError (a std::invalid_argument) as MaxSafeSpeed / MaxSafeMass for a
///         bad scene or options, naming the covering.
std::vector<SpeedLimitRow> SpeedLimitTable(SpeedLimitQuantity quantity, std::span<const SpeedLimitCovering> coverings,
                                           std::span<const double> values);

/// A row's status: its speed limit's (solving for the speed) or its mass limit's.
SpeedLimitStatus RowStatus(SpeedLimitQuantity quantity, const SpeedLimitRow& row) noexcept;
/// A row's message (MaxSafeSpeed's or MaxSafeMass's).
const std::string& RowMessage(SpeedLimitQuantity quantity, const SpeedLimitRow& row) noexcept;

/// The first row whose oracle failed (status kEvaluationFailed), or nullptr.
const SpeedLimitRow* FirstFailedRow(SpeedLimitQuantity quantity, std::span<const SpeedLimitRow> rows) noexcept;

/// The oracle that judged the rows (they share the scene's kind, so the same choice): the
/// first row's OracleReport with every row's evaluations and failures added up.
OracleReport SpeedLimitOracle(SpeedLimitQuantity quantity, std::span<const SpeedLimitRow> rows);

}  // namespace covopt::optim
