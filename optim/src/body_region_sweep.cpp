// One body region's verdict over a grid of scene quantities (body_region_sweep.hpp).
#include "covopt/optim/body_region_sweep.hpp"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <covopt/core/scene.hpp>
#include <covopt/core/scene_fields.hpp>
#include <covopt/core/sweep.hpp>

namespace covopt::optim {
namespace {

const SceneField& AxisField(const SweepAxis& axis, const char* which) {
  const SceneField* field = FindSceneField(axis.quantity);
  if (field == nullptr) {
    throw std::invalid_argument(std::string(which) + ": unknown quantity '" + axis.quantity +
                                "'; a body region is swept over robot-mass, speed, robot-radius or the covering");
  }
  if (!IsBodyContactField(field->dotted_name())) {
    throw std::invalid_argument(std::string(which) + ": the body region does not read " + std::string(field->name) +
                                "; sweep robot-mass, speed, robot-radius or the covering");
  }
  if (axis.values.empty()) throw std::invalid_argument(std::string(which) + ": no values");
  return *field;
}

}  // namespace

bool IsBodyContactField(std::string_view dotted_name) noexcept {
  return dotted_name == "robot.mass" || dotted_name == "robot.speed" || dotted_name == "robot.radius" ||
         dotted_name.rfind("covering.", 0) == 0;
}

std::vector<BodyRegionSweepPoint> SweepBodyRegion(const BodyContactScene& scene, const SweepAxis& x,
                                                  const std::optional<SweepAxis>& y,
                                                  const materials::BodyLimits& limits,
                                                  const BodyRegionOptions& options) {
  const SceneField& x_field = AxisField(x, "x");
  const SceneField* y_field = y ? &AxisField(*y, "y") : nullptr;
  CheckSweepSize(x.values.size(), y ? std::optional(y->values.size()) : std::nullopt);  // before the points
  // The body contact's fields as a core Scene, so the axes set them as core's sweep does.
  Scene base;
  base.robot.mass_kg = scene.robot_mass_kg;
  base.robot.speed_m_per_s = scene.speed_m_per_s;
  base.robot.radius_m = scene.robot_radius_m;
  base.covering = scene.covering;
  const std::vector<double> y_values = y ? y->values : std::vector<double>{0.0};
  std::vector<BodyRegionSweepPoint> points;
  points.reserve(x.values.size() * y_values.size());
  for (const double xv : x.values) {
    for (const double yv : y_values) {
      Scene at = base;
      x_field.field(at) = xv;
      if (y_field) y_field->field(at) = yv;
      BodyContactScene contact = scene;
      contact.robot_mass_kg = at.robot.mass_kg;
      contact.speed_m_per_s = at.robot.speed_m_per_s;
      contact.robot_radius_m = at.robot.radius_m;
      contact.covering = at.covering;
      BodyRegionSweepPoint point;
      point.x = xv;
      point.y = y ? yv : 0.0;
      try {
        if (BareRobotLacksContactArea(contact)) {  // a bare point is its own verdict
          throw std::invalid_argument(
              "contact area: the bare robot's pressure is its force over its contact area, and none is given; this "
              "bare point is not judged");
        }
        point.judgement = JudgeBodyContact(contact, limits, options);
      } catch (const std::invalid_argument& e) {  // a point outside the model's range
        point.error = e.what();
      }
      points.push_back(std::move(point));
    }
  }
  return points;
}

}  // namespace covopt::optim
