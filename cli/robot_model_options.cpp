#include "robot_model_options.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string_view>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "covopt/core/scene.hpp"
#include "errors.hpp"
#include "quantity.hpp"

namespace covopt::cli {
namespace {

std::string_view Trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

std::vector<std::string> SplitList(std::string_view text) {
  std::vector<std::string> items;
  if (Trim(text).empty()) return items;  // "": no values (a chain without movable joints)
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    items.emplace_back(Trim(text.substr(start, comma == std::string_view::npos ? text.npos : comma - start)));
    if (comma == std::string_view::npos) return items;
    start = comma + 1;
  }
}

/// One joint position: a number with an optional unit fitting the joint's type.
double ParseJoint(const std::string& item, std::size_t index, const robot::ChainJoint& joint,
                  const std::string& typed) {
  const bool prismatic = joint.type == robot::JointType::kPrismatic;
  const std::string where = fmt::format("--joints: joint {} ({}, {})", index + 1, joint.name,
                                        robot::ToString(joint.type));
  const std::string allowed = prismatic ? "a length: 0.1, 0.1m or 100mm" : "an angle: 0.5, 0.5rad or 30deg";
  double value = 0.0;
  const char* begin = item.data();
  const char* end = item.data() + item.size();
  const auto [stop, ec] = std::from_chars(begin, end, value);
  if (item.empty() || ec != std::errc() || !std::isfinite(value)) {
    throw InputError(fmt::format("{}: expected {} (got '{}' in '{}')", where, allowed, item, typed));
  }
  const std::string_view unit = Trim(std::string_view(stop, static_cast<std::size_t>(end - stop)));
  double scale = 1.0;
  if (unit.empty()) {
    // A bare number is SI (rad or m) and must be plausible: beyond a full turn it is almost
    // surely degrees, beyond 10 m almost surely millimetres.
    if (!prismatic && std::abs(value) > 2.0 * std::numbers::pi) {
      throw InputError(fmt::format("{}: a bare number is in radians ({} rad is more than a full turn); "
                                   "write {}deg or {}rad",
                                   where, item, item, item));
    }
    if (prismatic && std::abs(value) > 10.0) {
      throw InputError(fmt::format("{}: a bare number is in metres ({} m); write {}mm or {}m", where, item,
                                   item, item));
    }
  } else if (!prismatic && unit == "rad") {
    scale = 1.0;
  } else if (!prismatic && unit == "deg") {
    scale = std::numbers::pi / 180.0;
  } else if (prismatic && unit == "m") {
    scale = 1.0;
  } else if (prismatic && unit == "mm") {
    scale = 1e-3;
  } else if (prismatic && unit == "cm") {
    scale = 1e-2;
  } else {
    throw InputError(fmt::format("{}: unit '{}' does not fit; expected {} (got '{}')", where, unit,
                                 allowed, item));
  }
  // With a unit too: 1e300deg or 1e300mm is no position (robot::kMaxRotationRad, kMaxTranslationM).
  const double bound = prismatic ? robot::kMaxTranslationM : robot::kMaxRotationRad;
  if (!(std::abs(value * scale) <= bound)) {
    throw InputError(fmt::format("{}: '{}' is not allowed ({}: -{:.6g}..{:.6g} {})", where, item,
                                 prismatic ? "within 10 m" : "within a full turn", bound, bound,
                                 prismatic ? "m" : "rad, -360deg..360deg"));
  }
  return value * scale;
}

Eigen::VectorXd ParseJoints(const std::string& typed, const robot::KinematicChain& chain) {
  std::vector<const robot::ChainJoint*> movable;
  for (const robot::ChainJoint& joint : chain.joints()) {
    if (joint.type != robot::JointType::kFixed) movable.push_back(&joint);
  }
  const std::vector<std::string> items = SplitList(typed);
  if (items.size() != movable.size()) {
    std::string names;
    for (const robot::ChainJoint* joint : movable) names += (names.empty() ? "" : ", ") + joint->name;
    throw InputError(fmt::format("--joints: {} value{} given, but the chain {} -> {} has {} movable joint{}{} "
                                 "(got '{}')",
                                 items.size(), items.size() == 1 ? "" : "s", chain.base_link(),
                                 chain.tip_link(), movable.size(), movable.size() == 1 ? "" : "s",
                                 names.empty() ? "" : ": " + names, typed));
  }
  Eigen::VectorXd q(static_cast<Eigen::Index>(items.size()));
  for (std::size_t i = 0; i < items.size(); ++i) {
    q[static_cast<Eigen::Index>(i)] = ParseJoint(items[i], i, *movable[i], typed);
  }
  return q;
}

Eigen::Vector3d ParseTriple(const std::string& typed, const char* flag, bool lengths) {
  const std::vector<std::string> items = SplitList(typed);
  if (items.size() != 3) {
    throw InputError(fmt::format("{}: expected 3 comma-separated {} X,Y,Z (got {} in '{}')", flag,
                                 lengths ? "lengths" : "numbers", items.size(), typed));
  }
  Eigen::Vector3d v;
  static constexpr QuantitySpec kCoordinate{QuantityKind::kLength, false, false, 0.0, 10.0, {"mm", "cm"},
                                            "contact point coordinate"};
  for (int i = 0; i < 3; ++i) {
    const std::string& item = items[static_cast<std::size_t>(i)];
    if (lengths) {
      v[i] = ParseQuantity(item, kCoordinate, flag);
    } else {
      const char* end = item.data() + item.size();
      const auto [stop, ec] = std::from_chars(item.data(), end, v[i]);
      if (item.empty() || ec != std::errc() || stop != end || !std::isfinite(v[i])) {
        throw InputError(fmt::format("{}: component {} must be a finite number (got '{}' in '{}')", flag,
                                     i + 1, item, typed));
      }
    }
  }
  return v;
}

std::string FormatVector(Eigen::Vector3d v, int precision) {
  for (int i = 0; i < 3; ++i) {
    if (std::abs(v[i]) < 1e-12 * std::max(1.0, v.norm())) v[i] = 0.0;  // rounding noise
  }
  return fmt::format("({:.{}g}, {:.{}g}, {:.{}g})", v[0], precision, v[1], precision, v[2], precision);
}

/// The first URDF-only flag given ("--tip"), for the ISO fallback's refusal; none: nullopt.
std::optional<std::string> FirstUrdfFlag(const RobotModelOptions& options) {
  if (options.payload_com) return "--payload-com";
  if (options.payload_inertia) return "--payload-inertia";
  if (options.base) return "--base";
  if (options.tip) return "--tip";
  if (options.joints) return "--joints";
  if (options.point) return "--point";
  if (options.direction) return "--direction";
  if (options.ignore_joint_limits) return "--ignore-joint-limits";
  return std::nullopt;
}

/// ISO/TS 15066's M/2 + m_L for the scene's robot mass (options.iso_fallback()).
RobotModelMass IsoRobotMass(const RobotModelOptions& options, bool robot_mass_flag_given) {
  if (!options.robot_moving_mass) {
    throw InputError(fmt::format(
        "--payload-mass '{}' needs --urdf FILE (the payload on the robot model's tip) or --robot-moving-mass M "
        "(ISO/TS 15066's robot mass M/2 + m_L, M the mass of the robot's moving parts){}",
        *options.payload_mass, robot_mass_flag_given ? "; --robot-mass is the robot's effective mass, payload included" : ""));
  }
  if (robot_mass_flag_given) {
    throw InputError(fmt::format("--robot-mass and --robot-moving-mass '{}' both give the robot mass; give one "
                                 "(--robot-moving-mass M with --payload-mass m_L is ISO/TS 15066's M/2 + m_L)",
                                 *options.robot_moving_mass));
  }
  if (const auto flag = FirstUrdfFlag(options)) {
    throw InputError(fmt::format("{} needs --urdf FILE; --robot-moving-mass '{}' (ISO/TS 15066's M/2 + m_L) takes "
                                 "only the payload's mass, --payload-mass",
                                 *flag, *options.robot_moving_mass));
  }
  static constexpr QuantitySpec kMovingMass{QuantityKind::kMass, false, false, 0.0, 1e4, {"g", ""},
                                            "robot moving mass"};
  const double moving_kg = ParseQuantity(*options.robot_moving_mass, kMovingMass, "--robot-moving-mass");
  if (!(moving_kg > 0.0 && moving_kg <= robot::kMaxLinkMassKg)) {
    throw InputError(fmt::format("--robot-moving-mass: the total mass of the robot's moving parts must be in "
                                 "(0, 1e6] kg (got '{}')",
                                 *options.robot_moving_mass));
  }
  const double payload_kg = PayloadFromOptions(options).mass_kg;
  RobotModelMass mass;
  mass.mass_kg = robot::IsoEffectiveMassKg(moving_kg, payload_kg);
  mass.source = fmt::format("--robot-moving-mass '{}'{} (ISO/TS 15066 M/2 + m_L)", *options.robot_moving_mass,
                            options.payload_mass ? fmt::format(" --payload-mass '{}'", *options.payload_mass) : "");
  mass.notes.push_back(fmt::format(
      "robot mass {:.6g} kg: ISO/TS 15066:2016 Annex A's estimate m_R = M/2 + m_L = {:.6g}/2 + {:.6g} kg "
      "(--robot-moving-mass, --payload-mass), not a reflected mass: it ignores the pose and the direction of "
      "the impact; --urdf FILE gives the reflected mass of the robot model",
      mass.mass_kg, moving_kg, payload_kg));
  mass.inputs = {.source = "iso-estimate", .moving_mass_kg = moving_kg, .payload_mass_kg = payload_kg,
                 .reflected_mass_kg = mass.mass_kg};
  return mass;
}

}  // namespace

/// --payload-mass/--payload-com/--payload-inertia as a robot::Payload (none: all zero).
robot::Payload PayloadFromOptions(const RobotModelOptions& options) {
  robot::Payload payload;
  if (!options.payload_mass) {
    if (options.payload_com || options.payload_inertia) {
      throw InputError(fmt::format("{} needs --payload-mass M (the payload's mass in kg)",
                                   options.payload_com ? "--payload-com" : "--payload-inertia"));
    }
    return payload;
  }
  static constexpr QuantitySpec kPayloadMass{QuantityKind::kMass, false, false, 0.0, robot::kMaxPayloadMassKg,
                                             {"g", ""}, "payload mass"};
  payload.mass_kg = ParseQuantity(*options.payload_mass, kPayloadMass, "--payload-mass");  // 0: none
  if (options.payload_com) payload.center_of_mass_m = ParseTriple(*options.payload_com, "--payload-com", true);
  if (options.payload_inertia) {
    const std::vector<std::string> items = SplitList(*options.payload_inertia);
    if (items.size() != 6) {
      throw InputError(fmt::format("--payload-inertia: expected 6 comma-separated numbers IXX,IYY,IZZ,IXY,IXZ,IYZ "
                                   "in kg m² about the centre of mass (got {} in '{}')",
                                   items.size(), *options.payload_inertia));
    }
    std::array<double, 6> six{};
    for (std::size_t i = 0; i < 6; ++i) {
      const std::string& item = items[i];
      const char* end = item.data() + item.size();
      const auto [stop, ec] = std::from_chars(item.data(), end, six[i]);
      if (item.empty() || ec != std::errc() || stop != end || !std::isfinite(six[i])) {
        throw InputError(fmt::format("--payload-inertia: component {} must be a finite number in kg m² (got '{}' "
                                     "in '{}')",
                                     i + 1, item, *options.payload_inertia));
      }
    }
    payload.inertia_kg_m2 = robot::Payload::InertiaFromSix(six[0], six[1], six[2], six[3], six[4], six[5]);
  }
  try {
    robot::CheckPayload(payload, robot::PayloadInputNames{"--payload-mass", "--payload-com", "--payload-inertia"});
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
  return payload;
}

void AddRobotModelOptions(CLI::App& sub, RobotModelOptions& options, bool direction_required,
                          const std::string& group) {
  sub.add_option("--urdf", options.urdf, "robot model (URDF) whose reflected mass to use")
      ->type_name("FILE")->group(group);
  sub.add_option("--base", options.base, "the chain's base link (default: the URDF's root)")
      ->type_name("LINK")->group(group);
  sub.add_option("--tip", options.tip, "the link that hits")->type_name("LINK")->group(group);
  sub.add_option("--joints", options.joints,
                 "joint positions in chain order: rad, or 30deg (mm/m for prismatic joints)")
      ->type_name("Q1,Q2,...")->group(group);
  sub.add_option("--point", options.point,
                 "contact point in the tip link's frame (default 0,0,0; m, or with units)")
      ->type_name("X,Y,Z")->group(group);
  sub.add_option("--payload-mass", options.payload_mass,
                 "tool and part on the tip link, counted in the reflected mass (kg, or 500g)")
      ->type_name("M")->group(group);
  sub.add_option("--payload-com", options.payload_com,
                 "the payload's centre of mass in the tip link's frame (default 0,0,0; m, or with units)")
      ->type_name("X,Y,Z")->group(group);
  sub.add_option("--payload-inertia", options.payload_inertia,
                 "the payload's inertia about its centre of mass, tip-frame axes [kg m²] (default: a point mass)")
      ->type_name("IXX,IYY,IZZ,IXY,IXZ,IYZ")->group(group);
  sub.add_option("--robot-moving-mass", options.robot_moving_mass,
                 "without --urdf: the total mass M of the robot's moving parts (kg, or with a unit); the robot "
                 "mass is then ISO/TS 15066's M/2 + m_L (m_L: --payload-mass), instead of --robot-mass")
      ->type_name("M")->group(group);
  sub.add_flag("--ignore-joint-limits", options.ignore_joint_limits,
               "do not check joint positions and velocities against the URDF's limits (a warning says so)")
      ->group(group);
  sub.add_option("--direction", options.direction,
                 direction_required ? "impact direction in the base frame (required with --urdf)"
                                    : "impact direction in the base frame (default: only the extremes)")
      ->type_name("X,Y,Z")->group(group);
}

namespace {

/// --robot-moving-mass where a robot model is read: with --urdf it contradicts it; without,
/// the command needs one.
void RefuseMovingMass(const RobotModelOptions& options) {
  if (options.robot_moving_mass) {
    throw InputError(options.urdf ? fmt::format("--robot-moving-mass '{}' and --urdf both give the robot mass; give "
                                                "one (--urdf computes the reflected mass, with the payload on its "
                                                "tip; --robot-moving-mass is ISO/TS 15066's M/2 + m_L without a "
                                                "robot model)",
                                                *options.robot_moving_mass)
                                  : fmt::format("--robot-moving-mass '{}' (ISO/TS 15066's M/2 + m_L) gives simulate, "
                                                "speed-limit and optimize a robot mass without a URDF; this command "
                                                "needs --urdf FILE",
                                                *options.robot_moving_mass));
  }
}

}  // namespace

RobotModelInput ResolveRobotModelChain(const RobotModelOptions& options) {
  RefuseMovingMass(options);
  if (!options.urdf) {
    throw InputError("--urdf FILE is required with --base/--tip/--joints/--point/--direction");
  }
  if (!options.tip) throw InputError(fmt::format("--tip LINK is required with --urdf '{}'", *options.urdf));
  robot::ChainSpec spec;
  spec.base_link = options.base.value_or("");
  spec.tip_link = *options.tip;
  if (options.base && options.base->empty()) throw InputError("--base: empty link name");
  const robot::Payload payload = PayloadFromOptions(options);
  RobotModelInput input{[&] {
                          try {
                            return robot::KinematicChain::FromUrdfFile(*options.urdf, spec).WithPayload(payload);
                          } catch (const std::invalid_argument& e) {
                            throw InputError(std::string("--urdf: ") + e.what());
                          }
                        }(),
                        {}, Eigen::Vector3d::Zero(), std::nullopt};
  if (options.point) input.point_in_tip_m = ParseTriple(*options.point, "--point", true);
  return input;
}

RobotModelInput ResolveRobotModelInput(const RobotModelOptions& options, bool require_direction) {
  RefuseMovingMass(options);
  if (options.urdf && options.tip && !options.joints) {
    throw InputError(fmt::format("--joints Q1,Q2,... is required with --urdf '{}'", *options.urdf));
  }
  if (options.urdf && options.tip && require_direction && !options.direction) {
    throw InputError(fmt::format("--direction X,Y,Z (the impact direction in the base frame) is required "
                                 "with --urdf '{}'",
                                 *options.urdf));
  }
  RobotModelInput input = ResolveRobotModelChain(options);
  input.joint_positions = ParseJoints(*options.joints, input.chain);
  if (options.direction) {
    input.direction = ParseTriple(*options.direction, "--direction", false);
    if (input.direction->norm() == 0.0) {
      throw InputError(fmt::format("--direction: must be a non-zero vector (got '{}')", *options.direction));
    }
  }
  return input;
}

RobotModelMass ResolveRobotModelMass(const RobotModelOptions& options, bool robot_mass_flag_given) {
  if (options.iso_fallback()) return IsoRobotMass(options, robot_mass_flag_given);
  if (robot_mass_flag_given) {
    throw InputError("--robot-mass and --urdf both give the robot mass; give one (--urdf computes "
                     "the reflected mass from the robot model)");
  }
  const RobotModelInput input = ResolveRobotModelInput(options, true);
  RobotModelMass mass;
  try {
    mass.result = robot::ReflectedMass(input.chain, input.joint_positions, input.point_in_tip_m,
                                       input.direction, options.reflected_mass_options());
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("--urdf: ") + e.what());
  }
  mass.mass_kg = std::isfinite(*mass.result.reflected_mass_kg) ? *mass.result.reflected_mass_kg : kFixed;
  mass.source = fmt::format("--urdf '{}' (tip {})", *options.urdf, input.chain.tip_link());
  mass.notes.push_back(fmt::format(
      "robot mass {}: the reflected mass of {} at {} m (base frame) along {}, from {} at joints {}",
      std::isfinite(mass.mass_kg) ? fmt::format("{:.6g} kg", mass.mass_kg) : std::string("fixed"),
      input.chain.tip_link(), FormatVector(mass.result.contact_point_m, 4),
      FormatVector(*mass.result.direction, 4), *options.urdf, *options.joints));
  mass.notes.insert(mass.notes.end(), mass.result.warnings.begin(), mass.result.warnings.end());
  const auto as_list = [](const Eigen::Vector3d& v) { return std::vector<double>{v.x(), v.y(), v.z()}; };
  mass.inputs = {.source = "urdf",
                 .urdf_file = *options.urdf,
                 .base_link = input.chain.base_link(),
                 .tip_link = input.chain.tip_link(),
                 .joint_names = mass.result.joint_names,
                 .joint_positions = {input.joint_positions.data(),
                                     input.joint_positions.data() + input.joint_positions.size()},
                 .contact_point_m = as_list(mass.result.contact_point_m),
                 .direction = as_list(*mass.result.direction),
                 .payload_mass_kg = input.chain.payload().mass_kg,
                 .reflected_mass_kg = mass.mass_kg};
  return mass;
}

}  // namespace covopt::cli
