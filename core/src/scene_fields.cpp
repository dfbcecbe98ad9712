// The settable Scene fields (covopt/core/scene_fields.hpp), listed once.
#include "covopt/core/scene_fields.hpp"

#include <array>

namespace covopt {
namespace {

namespace specs = covopt::quantity_specs;

// clang-format off
const std::array kFields{
  SceneField{"robot", "mass", "robot-mass", specs::kRobotMass,
             [](Scene& s) -> double& { return s.robot.mass_kg; },
             "robot reflected mass, e.g. 10kg, or 'fixed'"},
  SceneField{"robot", "speed", "speed", specs::kSpeed,
             [](Scene& s) -> double& { return s.robot.speed_m_per_s; },
             "impact speed, e.g. 2m/s, 250mm/s, 7.2km/h"},
  SceneField{"robot", "radius", "robot-radius", specs::kRobotRadius,
             [](Scene& s) -> double& { return s.robot.radius_m; },
             "robot surface radius under the covering, e.g. 15mm, or 'flat'"},
  SceneField{"robot", "modulus", "robot-modulus", specs::kRobotModulus,
             [](Scene& s) -> double& { return s.robot.youngs_modulus_Pa; },
             "robot Young's modulus"},
  SceneField{"robot", "poisson", "robot-poisson", specs::kPoissonRatio,
             [](Scene& s) -> double& { return s.robot.poisson_ratio; },
             "robot Poisson ratio"},
  SceneField{"covering", "modulus", "covering-modulus", specs::kCoveringModulus,
             [](Scene& s) -> double& { return s.covering.youngs_modulus_Pa; },
             "covering Young's modulus"},
  SceneField{"covering", "poisson", "covering-poisson", specs::kPoissonRatio,
             [](Scene& s) -> double& { return s.covering.poisson_ratio; },
             "covering Poisson ratio"},
  SceneField{"covering", "thickness", "covering-thickness", specs::kCoveringThickness,
             [](Scene& s) -> double& { return s.covering.thickness_m; },
             "covering thickness; 0 = no covering"},
  SceneField{"head", "mass", "head-mass", specs::kHeadMass,
             [](Scene& s) -> double& { return s.head.mass_kg; },
             "head mass, or 'fixed' for a head held still"},
  SceneField{"head", "radius", "head-radius", specs::kHeadRadius,
             [](Scene& s) -> double& { return s.head.radius_m; },
             "outer head radius, at the scalp surface"},
  SceneField{"scalp", "modulus", "scalp-modulus", specs::kScalpModulus,
             [](Scene& s) -> double& { return s.scalp.youngs_modulus_Pa; },
             "scalp Young's modulus"},
  SceneField{"scalp", "poisson", "scalp-poisson", specs::kPoissonRatio,
             [](Scene& s) -> double& { return s.scalp.poisson_ratio; },
             "scalp Poisson ratio"},
  SceneField{"scalp", "thickness", "scalp-thickness", specs::kScalpThickness,
             [](Scene& s) -> double& { return s.scalp.thickness_m; },
             "scalp thickness"},
  SceneField{"skull", "modulus", "skull-modulus", specs::kSkullModulus,
             [](Scene& s) -> double& { return s.skull.youngs_modulus_Pa; },
             "skull bone Young's modulus"},
  SceneField{"skull", "poisson", "skull-poisson", specs::kPoissonRatio,
             [](Scene& s) -> double& { return s.skull.poisson_ratio; },
             "skull bone Poisson ratio"},
  SceneField{"model", "damping", "damping", specs::kContactDamping,
             [](Scene& s) -> double& { return s.model.damping_s_per_m; },
             "Hunt-Crossley contact damping, e.g. 0.2s/m; 0 = none"},
  SceneField{"robot", "reaction_delay", "reaction-delay", specs::kReactionDelay,
             [](Scene& s) -> double& { return s.robot.reaction_delay_s; },
             "time from first contact until the robot brakes, e.g. 20ms"},
  SceneField{"robot", "braking", "braking", specs::kBraking,
             [](Scene& s) -> double& { return s.robot.braking_m_per_s2; },
             "robot braking deceleration after the reaction delay, e.g. 20m/s2; 0 = none"},
  SceneField{"head", "torso_mass", "torso-mass", specs::kTorsoMass,
             [](Scene& s) -> double& { return s.head.torso_mass_kg; },
             "torso mass the head hangs on by the neck, or 'fixed'; 0 = no neck"},
  SceneField{"head", "neck_stiffness", "neck-stiffness", specs::kNeckStiffness,
             [](Scene& s) -> double& { return s.head.neck_stiffness_N_per_m; },
             "neck stiffness between head and torso, e.g. 20kN/m"},
  SceneField{"head", "neck_damping", "neck-damping", specs::kNeckDamping,
             [](Scene& s) -> double& { return s.head.neck_damping_N_s_per_m; },
             "neck damping between head and torso, e.g. 50N*s/m"},
};
// clang-format on

}  // namespace

std::string SceneField::dotted_name() const {
  std::string dotted(table);
  dotted += '.';
  dotted += key;
  return dotted;
}

double SceneField::value(const Scene& scene) const {
  Scene copy = scene;
  return field(copy);
}

std::span<const SceneField> SceneFields() noexcept { return kFields; }

const SceneField* FindSceneField(std::string_view name) noexcept {
  for (const SceneField& field : kFields) {
    if (field.name == name) return &field;
    const std::size_t dot = name.find('.');
    if (dot != std::string_view::npos && name.substr(0, dot) == field.table &&
        name.substr(dot + 1) == field.key) {
      return &field;
    }
  }
  return nullptr;
}

std::string SceneFieldNames() {
  std::string names;
  for (const SceneField& field : kFields) {
    if (!names.empty()) names += ", ";
    names += field.name;
  }
  return names;
}

}  // namespace covopt
