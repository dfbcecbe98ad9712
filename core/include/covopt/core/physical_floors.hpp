#pragma once
/// @file physical_floors.hpp
/// The smallest lengths, areas, masses and times the model can mean (docs/guide/inputs-and-errors.md,
/// "Physical floors"). Below them the physics is no longer the model's: a blunt Hertz or
/// mass-spring contact on a radius thinner than a blade's edge, a "covering" thinner than a coat
/// of paint, a reflected mass lighter than a paper clip. An input below its floor is refused with
/// the input's name, its value and the allowed range (std::invalid_argument, exit 2 on the CLI,
/// ValueError in Python), never computed: a denormal radius once read as SAFE.
///
/// Every reader of such a quantity (scene, scene file, surface file, URDF collision shapes,
/// link-coverings file, body-region inputs, Python) checks it against the same constant here.

namespace covopt {

/// The smallest radius of curvature of a robot surface [m]: 0.1 mm. A sharper edge cuts; the
/// blunt contact of the model (Hertz, ISO/TS 15066's quasi-static contact) does not describe it.
inline constexpr double kMinRadius_m = 1e-4;

/// The smallest thickness of a soft layer that is there [m]: 0.1 mm (a covering, the scalp, a
/// link's covering). A covering's thickness may also be exactly 0, meaning none.
inline constexpr double kMinLayerThickness_m = 1e-4;

/// The smallest mass of a body in an impact [kg]: 1 g (robot, head, torso, a body region's
/// effective mass, a payload).
inline constexpr double kMinMass_kg = 1e-3;

/// The smallest contact area [m²]: 1 mm², a hundredth of the 1 cm² over which ISO/TS 15066's
/// pressures are measured.
inline constexpr double kMinContactArea_m2 = 1e-6;

/// The smallest time that is not zero [s]: 1 µs (a reaction delay; 0 means "at contact").
inline constexpr double kMinTime_s = 1e-6;

/// The smallest elastic modulus or strength of a material [Pa]: 1 kPa, softer than any gel a
/// covering is made of. Also the smallest stress limit (the laceration limit; skin tears at
/// MPa): a catalog strength or a limit of 5e-324 Pa once printed crush ratios of inf.
inline constexpr double kMinModulus_Pa = 1e3;

/// The smallest contusion limit, an energy per area [J/m²]: 1 J/m² (0.1 mJ/cm²), a
/// 25 000th of the paper's 2.52 J/cm²: below it every touch would be a contusion, and a
/// denormal limit once made the contusion ratio infinite.
inline constexpr double kMinEnergyDensity_J_per_m2 = 1.0;

}  // namespace covopt
