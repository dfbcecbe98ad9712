#include "scene_fields.hpp"

#include <array>

#include <fmt/format.h>

#include "errors.hpp"

namespace covopt::cli {
namespace {

constexpr QuantitySpec kMass{QuantityKind::kMass, /*allow_fixed=*/true, /*allow_flat=*/false};
constexpr QuantitySpec kSpeed{QuantityKind::kSpeed};
constexpr QuantitySpec kLength{QuantityKind::kLength};
constexpr QuantitySpec kRobotRadius{QuantityKind::kLength, /*allow_fixed=*/false,
                                    /*allow_flat=*/true};
constexpr QuantitySpec kModulus{QuantityKind::kModulus};
constexpr QuantitySpec kRatio{QuantityKind::kDimensionless};

// clang-format off
const std::array kFields{
  SceneField{"robot", "mass", "--robot-mass", kMass,
             [](Scene& s) -> double& { return s.robot.mass_kg; },
             "robot reflected mass, e.g. 10kg, or 'fixed'"},
  SceneField{"robot", "speed", "--speed", kSpeed,
             [](Scene& s) -> double& { return s.robot.speed_m_per_s; },
             "impact speed, e.g. 2m/s, 250mm/s, 7.2km/h"},
  SceneField{"robot", "radius", "--robot-radius", kRobotRadius,
             [](Scene& s) -> double& { return s.robot.radius_m; },
             "robot surface radius under the covering, e.g. 15mm, or 'flat'"},
  SceneField{"robot", "modulus", "--robot-modulus", kModulus,
             [](Scene& s) -> double& { return s.robot.youngs_modulus_Pa; },
             "robot Young's modulus"},
  SceneField{"robot", "poisson", "--robot-poisson", kRatio,
             [](Scene& s) -> double& { return s.robot.poisson_ratio; },
             "robot Poisson ratio"},
  SceneField{"covering", "modulus", "--covering-modulus", kModulus,
             [](Scene& s) -> double& { return s.covering.youngs_modulus_Pa; },
             "covering Young's modulus"},
  SceneField{"covering", "poisson", "--covering-poisson", kRatio,
             [](Scene& s) -> double& { return s.covering.poisson_ratio; },
             "covering Poisson ratio"},
  SceneField{"covering", "thickness", "--covering-thickness", kLength,
             [](Scene& s) -> double& { return s.covering.thickness_m; },
             "covering thickness; 0 = no covering"},
  SceneField{"head", "mass", "--head-mass", kMass,
             [](Scene& s) -> double& { return s.head.mass_kg; },
             "head mass, or 'fixed' for a head held still"},
  SceneField{"head", "radius", "--head-radius", kLength,
             [](Scene& s) -> double& { return s.head.radius_m; },
             "outer head radius, at the scalp surface"},
  SceneField{"scalp", "modulus", "--scalp-modulus", kModulus,
             [](Scene& s) -> double& { return s.scalp.youngs_modulus_Pa; },
             "scalp Young's modulus"},
  SceneField{"scalp", "poisson", "--scalp-poisson", kRatio,
             [](Scene& s) -> double& { return s.scalp.poisson_ratio; },
             "scalp Poisson ratio"},
  SceneField{"scalp", "thickness", "--scalp-thickness", kLength,
             [](Scene& s) -> double& { return s.scalp.thickness_m; },
             "scalp thickness"},
  SceneField{"skull", "modulus", "--skull-modulus", kModulus,
             [](Scene& s) -> double& { return s.skull.youngs_modulus_Pa; },
             "skull bone Young's modulus"},
  SceneField{"skull", "poisson", "--skull-poisson", kRatio,
             [](Scene& s) -> double& { return s.skull.poisson_ratio; },
             "skull bone Poisson ratio"},
};
// clang-format on

constexpr std::array<std::string_view, 6> kTables{"robot", "covering", "head",
                                                  "scalp", "skull",    "model"};

}  // namespace

std::string SceneField::dotted_name() const { return fmt::format("{}.{}", table, key); }

std::span<const SceneField> SceneFields() noexcept { return kFields; }

std::span<const std::string_view> SceneTables() noexcept { return kTables; }

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
