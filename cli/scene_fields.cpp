#include "scene_fields.hpp"

#include <array>

#include <fmt/format.h>

#include "errors.hpp"

namespace covopt::cli {
namespace {

namespace specs = covopt::quantity_specs;

// clang-format off
const std::array kFields{
  SceneField{"robot", "mass", "--robot-mass", specs::kRobotMass,
             [](Scene& s) -> double& { return s.robot.mass_kg; },
             "robot reflected mass, e.g. 10kg, or 'fixed'"},
  SceneField{"robot", "speed", "--speed", specs::kSpeed,
             [](Scene& s) -> double& { return s.robot.speed_m_per_s; },
             "impact speed, e.g. 2m/s, 250mm/s, 7.2km/h"},
  SceneField{"robot", "radius", "--robot-radius", specs::kRobotRadius,
             [](Scene& s) -> double& { return s.robot.radius_m; },
             "robot surface radius under the covering, e.g. 15mm, or 'flat'"},
  SceneField{"robot", "modulus", "--robot-modulus", specs::kRobotModulus,
             [](Scene& s) -> double& { return s.robot.youngs_modulus_Pa; },
             "robot Young's modulus"},
  SceneField{"robot", "poisson", "--robot-poisson", specs::kPoissonRatio,
             [](Scene& s) -> double& { return s.robot.poisson_ratio; },
             "robot Poisson ratio"},
  SceneField{"covering", "modulus", "--covering-modulus", specs::kCoveringModulus,
             [](Scene& s) -> double& { return s.covering.youngs_modulus_Pa; },
             "covering Young's modulus"},
  SceneField{"covering", "poisson", "--covering-poisson", specs::kPoissonRatio,
             [](Scene& s) -> double& { return s.covering.poisson_ratio; },
             "covering Poisson ratio"},
  SceneField{"covering", "thickness", "--covering-thickness", specs::kCoveringThickness,
             [](Scene& s) -> double& { return s.covering.thickness_m; },
             "covering thickness; 0 = no covering"},
  SceneField{"head", "mass", "--head-mass", specs::kHeadMass,
             [](Scene& s) -> double& { return s.head.mass_kg; },
             "head mass, or 'fixed' for a head held still"},
  SceneField{"head", "radius", "--head-radius", specs::kHeadRadius,
             [](Scene& s) -> double& { return s.head.radius_m; },
             "outer head radius, at the scalp surface"},
  SceneField{"scalp", "modulus", "--scalp-modulus", specs::kScalpModulus,
             [](Scene& s) -> double& { return s.scalp.youngs_modulus_Pa; },
             "scalp Young's modulus"},
  SceneField{"scalp", "poisson", "--scalp-poisson", specs::kPoissonRatio,
             [](Scene& s) -> double& { return s.scalp.poisson_ratio; },
             "scalp Poisson ratio"},
  SceneField{"scalp", "thickness", "--scalp-thickness", specs::kScalpThickness,
             [](Scene& s) -> double& { return s.scalp.thickness_m; },
             "scalp thickness"},
  SceneField{"skull", "modulus", "--skull-modulus", specs::kSkullModulus,
             [](Scene& s) -> double& { return s.skull.youngs_modulus_Pa; },
             "skull bone Young's modulus"},
  SceneField{"skull", "poisson", "--skull-poisson", specs::kPoissonRatio,
             [](Scene& s) -> double& { return s.skull.poisson_ratio; },
             "skull bone Poisson ratio"},
};
// clang-format on

const std::array kLimitFields{
  LimitField{"laceration", "--laceration-limit", specs::kLacerationLimit,
             "laceration limit: the skin's tensile strength, e.g. 1MPa"},
  LimitField{"contusion", "--contusion-limit", specs::kContusionLimit,
             "contusion limit: the largest energy density, e.g. 2.52J/cm2"},
  LimitField{"safety_factor", "--safety-factor", specs::kSafetyFactor,
             "the limits are divided by this factor, 1-100"},
};

constexpr std::array<std::string_view, 7> kTables{"robot", "covering", "head", "scalp",
                                                  "skull", "model",    "limits"};

}  // namespace

std::string SceneField::dotted_name() const { return fmt::format("{}.{}", table, key); }

std::span<const SceneField> SceneFields() noexcept { return kFields; }

std::span<const std::string_view> SceneTables() noexcept { return kTables; }

std::string LimitField::dotted_name() const { return fmt::format("limits.{}", key); }

std::span<const LimitField> LimitFields() noexcept { return kLimitFields; }

void CheckLimitValue(const LimitField& field, double value, std::string_view name,
                     std::string_view shown) {
  if (field.spec.kind == QuantityKind::kDimensionless) {
    if (!(value >= 1.0 && value <= kMaxSafetyFactor)) {
      throw InputError(
          fmt::format("{} must be in [1, {:g}] (got {})", name, kMaxSafetyFactor, shown));
    }
    return;
  }
  if (!(value > 0.0)) {
    throw InputError(fmt::format("{} must be > 0 {} (got {})", name, SiUnit(field.spec.kind),
                                 shown));
  }
}

ThresholdReading ParseThresholds(std::string_view text, std::string_view name) {
  if (text == "cumulative") return ThresholdReading::kCumulative;
  if (text == "literal") return ThresholdReading::kLiteral;
  throw InputError(
      fmt::format("{}: expected 'cumulative' or 'literal' (got '{}')", name, text));
}

std::string_view ThresholdsName(ThresholdReading reading) noexcept {
  switch (reading) {
    case ThresholdReading::kCumulative: return "cumulative";
    case ThresholdReading::kLiteral: return "literal";
  }
  return "unknown";
}

}  // namespace covopt::cli
