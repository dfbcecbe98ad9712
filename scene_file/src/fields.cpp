#include "covopt/scene_file/fields.hpp"

#include <array>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "covopt/core/physical_floors.hpp"

namespace covopt::scene_file {
namespace {

namespace specs = covopt::quantity_specs;

const std::array kLimitFields{
  LimitField{"laceration", "laceration-limit", specs::kLacerationLimit,
             "laceration limit: the skin's tensile strength, e.g. 1MPa"},
  LimitField{"contusion", "contusion-limit", specs::kContusionLimit,
             "contusion limit: the largest energy density, e.g. 2.52J/cm2"},
  LimitField{"safety_factor", "safety-factor", specs::kSafetyFactor,
             "the limits are divided by this factor, 1-100"},
};

constexpr std::array<std::string_view, 8> kTables{"robot", "covering", "head", "scalp",
                                                  "skull", "model",    "limits", "report"};

constexpr std::array<std::string_view, 6> kReportKeys{"project", "cell", "assessor", "note", "margin_threshold", "appendix"};

}  // namespace

std::span<const std::string_view> SceneTables() noexcept { return kTables; }

std::span<const std::string_view> ReportKeys() noexcept { return kReportKeys; }

std::string LimitField::dotted_name() const { return fmt::format("limits.{}", key); }

std::span<const LimitField> LimitFields() noexcept { return kLimitFields; }

void CheckLimitValue(const LimitField& field, double value, std::string_view name,
                     std::string_view shown) {
  if (field.spec.kind == QuantityKind::kDimensionless) {
    if (!(value >= 1.0 && value <= kMaxSafetyFactor)) {
      throw std::invalid_argument(
          fmt::format("{} must be in [1, {:g}] (got {})", name, kMaxSafetyFactor, shown));
    }
    return;
  }
  // The floors (physical_floors.hpp): 1 kPa for the laceration limit, 1 J/m² for the
  // contusion limit; a denormal limit once made a ratio infinite.
  const bool laceration = field.key == "laceration";
  const double floor = laceration ? kMinModulus_Pa : kMinEnergyDensity_J_per_m2;
  if (!(value >= floor && value <= 1e13)) {
    throw std::invalid_argument(fmt::format("{} must be in [{:g}, 1e+13] {} (got {})", name, floor,
                                            SiUnit(field.spec.kind), shown));
  }
}

ThresholdReading ParseThresholds(std::string_view text, std::string_view name) {
  if (text == "cumulative") return ThresholdReading::kCumulative;
  if (text == "literal") return ThresholdReading::kLiteral;
  throw std::invalid_argument(
      fmt::format("{}: expected 'cumulative' or 'literal' (got '{}')", name, text));
}

CoveringLaw ParseCoveringLawOrThrow(std::string_view text, std::string_view name) {
  if (const std::optional<CoveringLaw> law = ParseCoveringLaw(text)) return *law;
  throw std::invalid_argument(fmt::format("{}: expected 'auto', 'foam' or 'hertz' (got '{}')", name, text));
}

std::string_view ThresholdsName(ThresholdReading reading) noexcept {
  switch (reading) {
    case ThresholdReading::kCumulative: return "cumulative";
    case ThresholdReading::kLiteral: return "literal";
  }
  return "unknown";
}

}  // namespace covopt::scene_file
