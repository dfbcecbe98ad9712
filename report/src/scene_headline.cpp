#include "covopt/report/scene_headline.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "covopt/core/quantity.hpp"
#include "covopt/core/scene_fields.hpp"

namespace covopt::report {

std::string SceneHeadline(const Scene& scene, std::span<const std::string_view> omitted_fields) {
  const auto shown = [&](std::string_view field) {
    return std::find(omitted_fields.begin(), omitted_fields.end(), field) == omitted_fields.end();
  };
  // Which body moves: the speed belongs to the one that is not fixed. A swept mass may be
  // fixed at some points only, so then neither is called fixed.
  const bool robot_fixed = shown("robot.mass") && std::isinf(scene.robot.mass_kg);
  const bool head_fixed = shown("head.mass") && std::isinf(scene.head.mass_kg);
  const std::string speed =
      shown("robot.speed") ? fmt::format("{:g} m/s", scene.robot.speed_m_per_s) : std::string();

  std::vector<std::string> parts;
  std::string robot = robot_fixed            ? std::string("fixed robot")
                      : shown("robot.mass") ? FormatQuantity(scene.robot.mass_kg, QuantityKind::kMass)
                                             : std::string("robot");
  if (!robot_fixed && !speed.empty()) robot += " at " + speed;
  if (shown("robot.radius")) robot += ", R " + FormatQuantity(scene.robot.radius_m, QuantityKind::kLength);
  parts.push_back(robot);

  const bool show_thickness = shown("covering.thickness");
  const bool show_modulus = shown("covering.modulus");
  if (show_thickness && !(scene.covering.thickness_m > 0.0)) {
    parts.emplace_back("no covering");
  } else if (show_thickness && show_modulus) {
    parts.push_back(fmt::format("covering {}, {}", FormatQuantity(scene.covering.thickness_m, QuantityKind::kLength),
                                FormatQuantity(scene.covering.youngs_modulus_Pa, QuantityKind::kModulus)));
  } else if (show_thickness) {
    parts.push_back(fmt::format("covering {}", FormatQuantity(scene.covering.thickness_m, QuantityKind::kLength)));
  } else if (show_modulus) {
    parts.push_back(fmt::format("covering {}", FormatQuantity(scene.covering.youngs_modulus_Pa, QuantityKind::kModulus)));
  }

  std::string head = head_fixed           ? std::string("head fixed")
                     : shown("head.mass") ? "head " + FormatQuantity(scene.head.mass_kg, QuantityKind::kMass)
                                          : std::string("head");
  if (robot_fixed && !head_fixed) {
    head += speed.empty() ? " dropped onto it" : " dropped onto it at " + speed;
  } else if (head_fixed && !robot_fixed) {
    head += ", hit by the robot";
  }
  if (head != "head") parts.push_back(head);
  return fmt::format("{}", fmt::join(parts, "; "));
}

std::vector<std::string> SceneDetailsBeyondHeadline(const Scene& scene,
                                                    std::span<const std::string_view> omitted_fields) {
  constexpr std::array<std::string_view, 6> kInHeadline{"robot.mass",         "robot.speed",
                                                        "robot.radius",       "covering.modulus",
                                                        "covering.thickness", "head.mass"};
  const Scene defaults;
  std::vector<std::string> details;
  for (const SceneField& field : SceneFields()) {
    const std::string name = field.dotted_name();
    if (std::find(kInHeadline.begin(), kInHeadline.end(), name) != kInHeadline.end() ||
        std::find(omitted_fields.begin(), omitted_fields.end(), name) != omitted_fields.end()) {
      continue;
    }
    Scene copy = scene, reference = defaults;
    const double value = field.field(copy);
    if (value == field.field(reference)) continue;
    details.push_back(fmt::format("{} {}", field.name, FormatQuantity(value, field.spec.kind)));
  }
  if (scene.model.thresholds != defaults.model.thresholds) {
    details.push_back(fmt::format("{} thresholds", ToString(scene.model.thresholds)));
  }
  return details;
}

std::string DesignedSceneHeadline(const Scene& scene) {
  Scene bare = scene;
  bare.covering.thickness_m = 0.0;
  std::string headline = SceneHeadline(bare);
  if (const auto at = headline.find("no covering"); at != std::string::npos) {
    headline.replace(at, 11, "covering to be designed");
  }
  return headline;
}

}  // namespace covopt::report
