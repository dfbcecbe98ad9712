// libFuzzer target: the surface-file reader (robot::ParseSurfaceFile) for a fixed planar
// two-link arm without collision geometry (the one of tests/robot/data/planar_2link.urdf),
// then robot::SurfaceFromUrdfString with the shapes it accepts, sampled at the default
// spacing (0.05 m). Bad input must end in std::invalid_argument, and a surface over
// kMaxSurfacePoints must be refused from its estimate, before it is made. An accepted surface
// must have at most kMaxSurfacePoints points, no more than the shapes' estimate, each with a
// finite position, a unit normal (zero for a point given alone), and a radius of curvature of
// at least covopt::kMinRadius_m (or kFlat). Anything else is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "covopt/core/physical_floors.hpp"
#include "covopt/robot.hpp"
#include "planar_arm.hpp"

namespace {

using covopt::fuzz::Arm;
using covopt::fuzz::kPlanarArm;

void CheckSurface(const covopt::robot::RobotSurface& surface) {
  using covopt::robot::SurfaceShapeType;
  if (surface.point_count() > covopt::robot::kMaxSurfacePoints) std::abort();
  for (const auto& link : surface.links) {
    double estimate = 0.0;
    for (const auto& shape : link.shapes) estimate += covopt::robot::EstimateShapePoints(shape, surface.spacing_m);
    if (static_cast<double>(link.points.size()) > estimate) std::abort();  // the estimate is an upper bound
    for (const auto& p : link.points) {
      if (p.shape_index >= link.shapes.size() || !p.position_m.allFinite() || !p.normal.allFinite()) std::abort();
      const bool alone = link.shapes[p.shape_index].type == SurfaceShapeType::kPoint;
      if (alone ? !p.normal.isZero() : std::abs(p.normal.norm() - 1.0) > 1e-9) std::abort();
      if (std::isnan(p.radius_of_curvature_m) || !(p.radius_of_curvature_m >= covopt::kMinRadius_m)) std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const covopt::robot::SurfaceFileShapes file = covopt::robot::ParseSurfaceFile(text, "fuzz.toml");
    CheckSurface(covopt::robot::SurfaceFromUrdfString(kPlanarArm, Arm(), {}, "arm", &file));
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
