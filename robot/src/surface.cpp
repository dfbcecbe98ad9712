#include "covopt/robot/surface.hpp"

#include <algorithm>
#include <iterator>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "covopt/internal/toml.hpp"
#include <urdf_model/model.h>

#include "chain_impl.hpp"
#include "covopt/core/physical_floors.hpp"
#include "covopt/internal/text.hpp"
#include "covopt/internal/toml_text.hpp"
#include "urdf_parse.hpp"

namespace covopt::robot {

const char* ToString(SurfaceShapeType type) noexcept {
  switch (type) {
    case SurfaceShapeType::kSphere: return "sphere";
    case SurfaceShapeType::kCylinder: return "cylinder";
    case SurfaceShapeType::kCapsule: return "capsule";
    case SurfaceShapeType::kBox: return "box";
    case SurfaceShapeType::kPoint: return "point";
  }
  return "unknown";
}

std::size_t RobotSurface::point_count() const noexcept {
  std::size_t count = 0;
  for (const LinkSurface& link : links) count += link.points.size();
  return count;
}

namespace {

constexpr double kPi = std::numbers::pi;
/// Two collision elements form a capsule when the spheres' centres are on the cylinder's end
/// centres and their radii equal the cylinder's, each to this [m] (URDFs round).
constexpr double kCapsuleToleranceM = 1e-6;

std::string Num(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void CheckSpacing(double spacing_m) {
  if (!(spacing_m >= kMinSurfaceSpacingM && spacing_m <= kMaxSurfaceSpacingM)) {
    throw std::invalid_argument("surface spacing = " + Num(spacing_m) +
                                " m is not allowed (a spacing in [0.001, 1] m)");
  }
}

/// The number of intervals of at most `spacing` over `length` (at least 1), as a double (no
/// overflow: EstimateShapePoints takes it for any length).
double IntervalCount(double length, double spacing) { return std::max(1.0, std::ceil(length / spacing - 1e-9)); }

/// The number of intervals of at most `spacing` over `length` (at least 1). Only called on
/// shapes whose estimate is within kMaxSurfacePoints (SampleShape checks it first).
std::size_t Intervals(double length, double spacing) {
  return static_cast<std::size_t>(IntervalCount(length, spacing));
}

/// The number of points around a circle of radius `r`: at most `spacing` apart, at least 4.
std::size_t AroundCount(double r, double spacing) {
  return std::max<std::size_t>(4, Intervals(2.0 * kPi * r, spacing));
}

// ---- the estimate: Sampler's counts without its points ------------------------------------
// Each count below mirrors a loop of Sampler with the same arithmetic (IntervalCount), so it is
// exact, except for the sum of the ring sizes over the rings of a cap or a disc, which is
// bounded above in closed form. A ring of radius ρ has max(4, ⌈x⌉) points, x = 2πρ/s, which is
// at most x + 1 when x >= 3 and at most 4 < x + 4 otherwise: so a set of rings has at most
// Σx + (rings) + 3 · (rings with x < 3) points.

/// A relative margin on the closed-form sums, for the sampler's rounding (its sines against
/// the bound's).
constexpr double kRoundingMargin = 1.0 + 1e-9;

/// Points of Sampler::Cap from the pole (0) to polar angle `to` (π/2 or π) [rad], the last
/// ring included or not. Σ sin(φ_k) over the rings is bounded by the trapezoid rule, which
/// underestimates the integral of the concave sin: h (Σ_{k=0}^{m} sin φ_k − sin(to)/2) <=
/// 1 − cos(to), h = to/m.
double CapCount(double r, double spacing, double to, bool include_to) {
  const double m = IntervalCount(r * to, spacing);
  const double x = 2.0 * kPi * r / spacing;  // the equator's x
  const double rings = m + (include_to ? 1.0 : 0.0);
  const double sum_sin = m / to * (1.0 - std::cos(to)) + 0.5 * std::sin(to) - (include_to ? 0.0 : std::sin(to));
  // Rings with x sin φ < 3 lie within asin(3/x) of a pole (both poles for a whole sphere).
  const double poles = to > 0.5 * kPi ? 2.0 : 1.0;
  const double small =
      x <= 3.0 ? rings : std::min(rings, poles * (std::floor(m * std::asin(3.0 / x) / to) + 1.0));
  return x * std::max(0.0, sum_sin) * kRoundingMargin + rings + 3.0 * small;
}

/// Points of Sampler::Disc: its centre and rings k r/m, k = 1 .. m−1.
double DiscCount(double r, double spacing) {
  const double m = IntervalCount(r, spacing);
  const double x = 2.0 * kPi * r / spacing;  // the rim's x
  const double rings = m - 1.0;
  const double small = std::min(rings, std::floor(3.0 * m / x) + 1.0);  // k x / m < 3
  return 1.0 + x * rings / 2.0 * kRoundingMargin + rings + 3.0 * small;
}

/// Points of Sampler::Side: a ring of radius r at each station (exact).
double SideCount(double length, double r, double spacing) {
  return (IntervalCount(length, spacing) + 1.0) * std::max(4.0, IntervalCount(2.0 * kPi * r, spacing));
}

/// Points of Sampler::Box (exact).
double BoxCount(const Eigen::Vector3d& size, double e, double spacing) {
  const Eigen::Vector3d c = (size.array() / 2.0 - e).max(0.0).matrix();
  const auto midpoints = [&](double ci) { return ci <= 0.0 ? 0.0 : IntervalCount(2.0 * ci, spacing); };
  const auto stations = [&](double ci) { return ci <= 0.0 ? 1.0 : IntervalCount(2.0 * ci, spacing) + 1.0; };
  const double arc = IntervalCount(0.5 * kPi * e, spacing);
  double count = 8.0;  // corners
  for (int k = 0; k < 3; ++k) {
    count += 2.0 * midpoints(c[(k + 1) % 3]) * midpoints(c[(k + 2) % 3]) + 4.0 * arc * stations(c[k]);
  }
  return count;
}

/// Two unit vectors completing the unit `u` to a right-handed orthonormal basis.
std::pair<Eigen::Vector3d, Eigen::Vector3d> Perpendiculars(const Eigen::Vector3d& u) {
  const Eigen::Vector3d helper = std::abs(u.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = u.cross(helper).normalized();
  return {e1, u.cross(e1)};
}

struct Sampler {
  double spacing;
  std::size_t shape_index;
  std::vector<SurfacePoint> points;

  void Add(const Eigen::Vector3d& position, const Eigen::Vector3d& normal, double radius) {
    points.push_back({position, normal, radius, shape_index});
  }

  /// A ring of points around `centre` in the plane normal to `u`, at distance `rho`; their
  /// normals are `axial` · u + `radial` · (the radial direction), radius `radius`.
  void Ring(const Eigen::Vector3d& centre, const Eigen::Vector3d& u, double rho, double axial,
            double radial, double radius) {
    const auto [e1, e2] = Perpendiculars(u);
    const std::size_t n = AroundCount(rho, spacing);
    for (std::size_t k = 0; k < n; ++k) {
      const double theta = 2.0 * kPi * static_cast<double>(k) / static_cast<double>(n);
      const Eigen::Vector3d out = std::cos(theta) * e1 + std::sin(theta) * e2;
      Add(centre + rho * out, axial * u + radial * out, radius);
    }
  }

  /// The sphere cap about pole direction `u` (unit) from polar angle `from` to `to` [rad],
  /// both included unless `include_to` is false; the pole (angle 0) is one point.
  void Cap(const Eigen::Vector3d& centre, const Eigen::Vector3d& u, double r, double from, double to,
           bool include_to) {
    const std::size_t m = Intervals(r * (to - from), spacing);
    for (std::size_t k = 0; k <= m; ++k) {
      if (k == m && !include_to) break;
      const double phi = from + (to - from) * static_cast<double>(k) / static_cast<double>(m);
      const double rho = r * std::sin(phi);
      if (rho <= 1e-12 * r) {
        const Eigen::Vector3d normal = std::cos(phi) > 0.0 ? u : Eigen::Vector3d(-u);
        Add(centre + r * normal, normal, r);
        continue;
      }
      Ring(centre + r * std::cos(phi) * u, u, rho, std::cos(phi), std::sin(phi), r);
    }
  }

  /// The side of the cylinder or capsule a -> b, radius r: stations along the axis (both
  /// ends included), a ring at each.
  void Side(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double r) {
    const Eigen::Vector3d u = (b - a).normalized();
    const std::size_t m = Intervals((b - a).norm(), spacing);
    for (std::size_t k = 0; k <= m; ++k) {
      Ring(a + (b - a) * (static_cast<double>(k) / static_cast<double>(m)), u, r, 0.0, 1.0, r);
    }
  }

  /// A flat disc of radius r about `centre`, normal `u`: its centre and rings inside the rim.
  void Disc(const Eigen::Vector3d& centre, const Eigen::Vector3d& u, double r) {
    Add(centre, u, kFlat);
    const std::size_t m = Intervals(r, spacing);
    for (std::size_t k = 1; k < m; ++k) {
      Ring(centre, u, r * static_cast<double>(k) / static_cast<double>(m), 1.0, 0.0, kFlat);
    }
  }

  /// `m` cell midpoints over [-c, c] (none when c = 0: a face without a flat part).
  std::vector<double> Midpoints(double c) const {
    std::vector<double> values;
    if (c <= 0.0) return values;
    const std::size_t m = Intervals(2.0 * c, spacing);
    for (std::size_t k = 0; k < m; ++k) values.push_back(-c + 2.0 * c * (static_cast<double>(k) + 0.5) / static_cast<double>(m));
    return values;
  }
  /// Stations over [-c, c], both ends included (one, at 0, when c = 0).
  std::vector<double> Stations(double c) const {
    if (c <= 0.0) return {0.0};
    std::vector<double> values;
    const std::size_t m = Intervals(2.0 * c, spacing);
    for (std::size_t k = 0; k <= m; ++k) values.push_back(-c + 2.0 * c * static_cast<double>(k) / static_cast<double>(m));
    return values;
  }

  /// The rounded box: flat faces (kFlat), quarter-cylinder edges and sphere-octant corners
  /// of radius e, inside the extents `size`, in the box frame `pose`.
  void Box(const Eigen::Isometry3d& pose, const Eigen::Vector3d& size, double e) {
    const Eigen::Vector3d h = size / 2.0;
    const Eigen::Vector3d c = (h.array() - e).max(0.0).matrix();
    const Eigen::Matrix3d rotation = pose.linear();
    const auto add_local = [&](const Eigen::Vector3d& p, const Eigen::Vector3d& n, double radius) {
      Add(pose * p, rotation * n, radius);
    };
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3;
      const int j = (k + 2) % 3;
      for (const double sign : {-1.0, 1.0}) {
        // Face normal to axis k.
        for (const double x : Midpoints(c[i])) {
          for (const double y : Midpoints(c[j])) {
            Eigen::Vector3d p;
            p[k] = sign * h[k];
            p[i] = x;
            p[j] = y;
            add_local(p, sign * Eigen::Vector3d::Unit(k), kFlat);
          }
        }
      }
      // Edges along axis k, at the four (±i, ±j) corners of the cross-section.
      const std::size_t n_arc = Intervals(0.5 * kPi * e, spacing);
      for (const double si : {-1.0, 1.0}) {
        for (const double sj : {-1.0, 1.0}) {
          for (std::size_t a = 0; a < n_arc; ++a) {
            const double alpha = 0.5 * kPi * (static_cast<double>(a) + 0.5) / static_cast<double>(n_arc);
            Eigen::Vector3d n = Eigen::Vector3d::Zero();
            n[i] = si * std::cos(alpha);
            n[j] = sj * std::sin(alpha);
            for (const double z : Stations(c[k])) {
              Eigen::Vector3d p;
              p[k] = z;
              p[i] = si * c[i];
              p[j] = sj * c[j];
              add_local(p + e * n, n, e);
            }
          }
        }
      }
    }
    for (const double sx : {-1.0, 1.0}) {
      for (const double sy : {-1.0, 1.0}) {
        for (const double sz : {-1.0, 1.0}) {
          const Eigen::Vector3d n = Eigen::Vector3d(sx, sy, sz) / std::sqrt(3.0);
          add_local(Eigen::Vector3d(sx * c.x(), sy * c.y(), sz * c.z()) + e * n, n, e);
        }
      }
    }
  }
};

}  // namespace

double EstimateShapePoints(const SurfaceShape& shape, double spacing_m) {
  CheckSpacing(spacing_m);
  const double r = shape.radius_m;
  const Eigen::Vector3d axis = shape.b_m - shape.a_m;
  const bool finite = std::isfinite(r) && shape.a_m.allFinite() && shape.b_m.allFinite() && shape.size_m.allFinite() &&
                      std::isfinite(shape.edge_radius_m);
  if (!finite && shape.type != SurfaceShapeType::kPoint) return std::numeric_limits<double>::infinity();
  double count = 1.0;
  switch (shape.type) {
    case SurfaceShapeType::kSphere: count = CapCount(r, spacing_m, kPi, true); break;
    case SurfaceShapeType::kCapsule:
      count = axis.norm() <= 1e-12 ? CapCount(r, spacing_m, kPi, true)
                                   : SideCount(axis.norm(), r, spacing_m) + 2.0 * CapCount(r, spacing_m, 0.5 * kPi, false);
      break;
    case SurfaceShapeType::kCylinder: count = SideCount(axis.norm(), r, spacing_m) + 2.0 * DiscCount(r, spacing_m); break;
    case SurfaceShapeType::kBox: count = BoxCount(shape.size_m, shape.edge_radius_m, spacing_m); break;
    case SurfaceShapeType::kPoint: count = 1.0; break;
  }
  return std::isnan(count) ? std::numeric_limits<double>::infinity() : std::ceil(count);
}

std::vector<SurfacePoint> SampleShape(const SurfaceShape& shape, double spacing_m, std::size_t shape_index) {
  const double estimate = EstimateShapePoints(shape, spacing_m);
  if (!(estimate <= static_cast<double>(kMaxSurfacePoints))) {
    throw std::invalid_argument((shape.origin.empty() ? std::string(ToString(shape.type)) : shape.origin) + ": a " +
                                ToString(shape.type) + " sampled at a spacing of " + Num(spacing_m) + " m gives about " +
                                Num(estimate) + " points, more than the " + std::to_string(kMaxSurfacePoints) +
                                " a surface may have: choose a coarser spacing or a smaller shape");
  }
  Sampler sampler{spacing_m, shape_index, {}};
  sampler.points.reserve(static_cast<std::size_t>(estimate));
  const double r = shape.radius_m;
  const Eigen::Vector3d axis = shape.b_m - shape.a_m;
  const bool degenerate = axis.norm() <= 1e-12;
  switch (shape.type) {
    case SurfaceShapeType::kSphere:
      sampler.Cap(shape.a_m, Eigen::Vector3d::UnitZ(), r, 0.0, kPi, true);
      break;
    case SurfaceShapeType::kCapsule:
      if (degenerate) {
        sampler.Cap(shape.a_m, Eigen::Vector3d::UnitZ(), r, 0.0, kPi, true);
        break;
      }
      sampler.Side(shape.a_m, shape.b_m, r);
      sampler.Cap(shape.b_m, axis.normalized(), r, 0.0, 0.5 * kPi, false);
      sampler.Cap(shape.a_m, -axis.normalized(), r, 0.0, 0.5 * kPi, false);
      break;
    case SurfaceShapeType::kCylinder:
      sampler.Side(shape.a_m, shape.b_m, r);
      sampler.Disc(shape.b_m, axis.normalized(), r);
      sampler.Disc(shape.a_m, -axis.normalized(), r);
      break;
    case SurfaceShapeType::kBox:
      sampler.Box(shape.pose, shape.size_m, shape.edge_radius_m);
      break;
    case SurfaceShapeType::kPoint:
      sampler.Add(shape.a_m, Eigen::Vector3d::Zero(), shape.radius_m);
      break;
  }
  return std::move(sampler.points);
}

namespace {

/// "[0.0001, 1000] m": the range of a shape's radius or length.
std::string ShapeRange() {
  std::ostringstream out;  // a stream, not "[" + Num(...): GCC 12 warns (-Wrestrict) on that
  out << "[" << kMinRadius_m << ", " << kMaxLengthM << "] m";
  return out.str();
}

/// A radius of curvature (sphere, cylinder, capsule, a box's edges) or a shape's length, in
/// [kMinRadius_m, kMaxLengthM]: below the floor an edge cuts and the model's blunt contact does
/// not describe it (physical_floors.hpp); a denormal radius once read as safe.
void CheckDimension(double value, const std::string& where, const std::string& field) {
  if (!(value >= kMinRadius_m && value <= kMaxLengthM)) {
    throw std::invalid_argument(where + ": " + field + " = " + Num(value) + " m is not allowed (a " +
                                (field.find("radius") != std::string::npos ? "radius" : "length") + " in " +
                                ShapeRange() + "; below " + Num(kMinRadius_m) +
                                " m an edge cuts, which the model does not describe)");
  }
}

void CheckCoordinates(const Eigen::Vector3d& v, const std::string& where, const std::string& field) {
  for (int i = 0; i < 3; ++i) {
    if (!(std::abs(v[i]) <= kMaxLengthM)) {
      throw std::invalid_argument(where + ": " + field + " component " + std::to_string(i) + " = " +
                                  Num(v[i]) + " m is not allowed (a finite length within ±1000 m)");
    }
  }
}

Eigen::Isometry3d ToEigen(const urdf::Pose& pose) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
                     .normalized()
                     .toRotationMatrix();
  out.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  return out;
}

/// The shapes of one link's <collision> elements; capsules (a cylinder with a sphere of its
/// radius on each end centre) merged. `mesh` is set when one is a mesh (returned shapes are
/// then not used).
std::vector<SurfaceShape> UrdfShapes(const urdf::Link& link, const SurfaceOptions& options,
                                     const std::string& source, std::string& mesh) {
  std::vector<SurfaceShape> raw;
  std::size_t index = 0;
  for (const urdf::CollisionSharedPtr& collision : link.collision_array) {
    ++index;
    if (!collision || !collision->geometry) continue;
    const std::string where =
        source + ": link '" + link.name + "' <collision> " + std::to_string(index);
    const Eigen::Isometry3d pose = ToEigen(collision->origin);
    CheckCoordinates(pose.translation(), where, "<origin xyz>");
    if (!pose.linear().allFinite()) throw std::invalid_argument(where + ": <origin rpy> is not finite");
    SurfaceShape shape;
    shape.origin = "URDF <collision> " + std::to_string(index) + " of link '" + link.name + "'";
    switch (collision->geometry->type) {
      case urdf::Geometry::SPHERE: {
        const auto& sphere = static_cast<const urdf::Sphere&>(*collision->geometry);
        CheckDimension(sphere.radius, where, "<sphere radius>");
        shape.type = SurfaceShapeType::kSphere;
        shape.radius_m = sphere.radius;
        shape.a_m = pose.translation();
        break;
      }
      case urdf::Geometry::CYLINDER: {
        const auto& cylinder = static_cast<const urdf::Cylinder&>(*collision->geometry);
        CheckDimension(cylinder.radius, where, "<cylinder radius>");
        CheckDimension(cylinder.length, where, "<cylinder length>");
        shape.type = SurfaceShapeType::kCylinder;
        shape.radius_m = cylinder.radius;
        const Eigen::Vector3d half = pose.linear() * Eigen::Vector3d(0.0, 0.0, 0.5 * cylinder.length);
        shape.a_m = pose.translation() - half;
        shape.b_m = pose.translation() + half;
        break;
      }
      case urdf::Geometry::BOX: {
        const auto& box = static_cast<const urdf::Box&>(*collision->geometry);
        const Eigen::Vector3d size(box.dim.x, box.dim.y, box.dim.z);
        for (int i = 0; i < 3; ++i) CheckDimension(size[i], where, std::string("<box size> ") + "xyz"[i]);
        if (!options.box_edge_radius_m) {
          throw std::invalid_argument(where + ": a <box> needs an edge radius (URDF boxes have sharp edges; "
                                              "give the housing's edge radius, box_edge_radius_m / --box-edge-radius)");
        }
        const double e = *options.box_edge_radius_m;
        if (!(e >= kMinRadius_m && e <= 0.5 * size.minCoeff())) {
          throw std::invalid_argument(where + ": box edge radius = " + Num(e) + " m is not allowed (in [" +
                                      Num(kMinRadius_m) + " m, half the box's smallest extent, " +
                                      Num(0.5 * size.minCoeff()) + " m])");
        }
        shape.type = SurfaceShapeType::kBox;
        shape.pose = pose;
        shape.size_m = size;
        shape.edge_radius_m = e;
        break;
      }
      case urdf::Geometry::MESH:
        if (mesh.empty()) mesh = static_cast<const urdf::Mesh&>(*collision->geometry).filename;
        continue;
    }
    raw.push_back(std::move(shape));
  }
  // Capsules: a cylinder and two unused spheres of its radius on its end centres.
  std::vector<bool> used(raw.size(), false);
  const auto find_sphere = [&](const Eigen::Vector3d& centre, double r) -> std::size_t {
    for (std::size_t j = 0; j < raw.size(); ++j) {
      if (used[j] || raw[j].type != SurfaceShapeType::kSphere) continue;
      if ((raw[j].a_m - centre).norm() <= kCapsuleToleranceM && std::abs(raw[j].radius_m - r) <= kCapsuleToleranceM) {
        return j;
      }
    }
    return raw.size();
  };
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i].type != SurfaceShapeType::kCylinder) continue;
    const std::size_t at_a = find_sphere(raw[i].a_m, raw[i].radius_m);
    if (at_a == raw.size()) continue;
    used[at_a] = true;
    const std::size_t at_b = find_sphere(raw[i].b_m, raw[i].radius_m);
    if (at_b == raw.size()) {
      used[at_a] = false;
      continue;
    }
    used[at_b] = true;
    raw[i].type = SurfaceShapeType::kCapsule;
    raw[i].origin += " (a capsule, with its end spheres, <collision> " +
                     raw[at_a].origin.substr(std::string("URDF <collision> ").size()).substr(0, raw[at_a].origin.find(' ', 17) - 17) +
                     " and " +
                     raw[at_b].origin.substr(std::string("URDF <collision> ").size()).substr(0, raw[at_b].origin.find(' ', 17) - 17) + ")";
  }
  std::vector<SurfaceShape> shapes;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (!used[i]) shapes.push_back(std::move(raw[i]));
  }
  return shapes;
}

// ---- surface files -----------------------------------------------------------------------

[[noreturn]] void FileError(const std::string& source, const toml::source_region& region, const std::string& text) {
  throw std::invalid_argument(covopt::internal::Where(source, region) + ": " + text);
}

Eigen::Vector3d ReadPoint(const toml::table& table, std::string_view key, const std::string& source,
                          const std::string& what) {
  const toml::node* node = table.get(key);
  if (node == nullptr) FileError(source, table.source(), what + ": missing " + std::string(key) + " (x, y, z in m)");
  const toml::array* array = node->as_array();
  if (array == nullptr || array->size() != 3) {
    FileError(source, node->source(), what + ": " + std::string(key) + " must be an array of 3 numbers [m]");
  }
  Eigen::Vector3d v;
  for (std::size_t i = 0; i < 3; ++i) {
    const toml::node& item = *array->get(i);
    const std::optional<double> value = item.value<double>();
    if (!value || !(item.is_floating_point() || item.is_integer())) {
      FileError(source, item.source(), what + ": " + std::string(key) + " component " + std::to_string(i) + " is " +
                                           std::string(covopt::internal::TypeName(item)) + ", not a number [m]");
    }
    if (!(std::abs(*value) <= kMaxLengthM)) {
      FileError(source, item.source(), what + ": " + std::string(key) + " component " + std::to_string(i) + " = " +
                                           Num(*value) + " m is not allowed (a finite length within ±1000 m)");
    }
    v[static_cast<int>(i)] = *value;
  }
  return v;
}

double ReadRadius(const toml::table& table, const std::string& source, const std::string& what, bool flat_allowed) {
  const toml::node* node = table.get("radius_m");
  if (node == nullptr) FileError(source, table.source(), what + ": missing radius_m [m]");
  if (flat_allowed && node->is_string() && node->value<std::string>() == "flat") return kFlat;
  const std::optional<double> value = node->value<double>();
  if (!value || !(node->is_floating_point() || node->is_integer())) {
    FileError(source, node->source(), what + ": radius_m is " + std::string(covopt::internal::TypeName(*node)) +
                                          ", not a number [m]" + (flat_allowed ? " or \"flat\"" : ""));
  }
  if (!(*value >= kMinRadius_m && *value <= kMaxLengthM)) {
    FileError(source, node->source(), what + ": radius_m = " + Num(*value) + " m is not allowed (a radius in " +
                                          ShapeRange() + (flat_allowed ? ", or \"flat\"" : "") + "; below " +
                                          Num(kMinRadius_m) + " m an edge cuts, which the model does not describe)");
  }
  return *value;
}

template <std::size_t N>
void RefuseUnknownKeys(const toml::table& table, const std::array<std::string_view, N>& known,
                       const std::string& source, const std::string& what) {
  if (const toml::key* key = covopt::internal::FirstUnknownKey(table, known)) {
    std::string allowed;
    for (const std::string_view k : known) allowed += (allowed.empty() ? "" : ", ") + std::string(k);
    FileError(source, key->source(), what + ": unknown key '" + std::string(key->str()) + "' (allowed: " + allowed + ")");
  }
}

const toml::array* ArrayOfTables(const toml::table& table, std::string_view key, const std::string& source,
                                 const std::string& what) {
  const toml::node* node = table.get(key);
  if (node == nullptr) return nullptr;
  const toml::array* array = node->as_array();
  if (array == nullptr) FileError(source, node->source(), what + ": " + std::string(key) + " must be an array of tables");
  for (const toml::node& item : *array) {
    if (!item.is_table()) {
      FileError(source, item.source(), what + ": each of " + std::string(key) + " must be a table, not " +
                                           std::string(covopt::internal::TypeName(item)));
    }
  }
  return array;
}

/// "a sphere of radius 0.1 m", "a capsule of radius 0.05 m and length 0.3 m", "a box of
/// 0.1 x 0.2 x 0.3 m".
std::string Describe(const SurfaceShape& shape) {
  std::ostringstream out;
  out << "a " << ToString(shape.type);
  switch (shape.type) {
    case SurfaceShapeType::kBox:
      out << " of " << shape.size_m.x() << " x " << shape.size_m.y() << " x " << shape.size_m.z() << " m";
      break;
    case SurfaceShapeType::kCylinder:
    case SurfaceShapeType::kCapsule:
      out << " of radius " << shape.radius_m << " m and length " << (shape.b_m - shape.a_m).norm() << " m";
      break;
    default: out << " of radius " << shape.radius_m << " m";
  }
  return out.str();
}

/// The estimate of every shape of `links` at `spacing` [points].
double EstimateLinksPoints(const std::vector<LinkSurface>& links, double spacing) {
  double total = 0.0;
  for (const LinkSurface& link : links) {
    for (const SurfaceShape& shape : link.shapes) total += EstimateShapePoints(shape, spacing);
  }
  return total;
}

/// Refuses shapes whose estimate at `spacing` exceeds kMaxSurfacePoints, naming the shape that
/// gives the most, the estimate, the cap and the spacing that would do.
void CheckSurfaceSize(const std::vector<LinkSurface>& links, double spacing) {
  const double total = EstimateLinksPoints(links, spacing);
  const double cap = static_cast<double>(kMaxSurfacePoints);
  if (total <= cap) return;
  const SurfaceShape* largest = nullptr;
  double largest_count = -1.0;
  for (const LinkSurface& link : links) {
    for (const SurfaceShape& shape : link.shapes) {
      if (const double count = EstimateShapePoints(shape, spacing); count > largest_count) {
        largest = &shape;
        largest_count = count;
      }
    }
  }
  // The smallest spacing in whole millimetres that fits (bisection: fewer points the coarser).
  std::ostringstream message;
  message << "the surface sampled at a spacing of " << spacing << " m would have about " << total
          << " points, more than the " << kMaxSurfacePoints << " allowed (the most from " << largest->origin << ", "
          << Describe(*largest) << ": about " << largest_count << "); give ";
  if (EstimateLinksPoints(links, kMaxSurfaceSpacingM) <= cap) {
    double lo = spacing, hi = kMaxSurfaceSpacingM;  // lo does not fit, hi does
    while (hi - lo > 1e-4) {
      const double mid = 0.5 * (lo + hi);
      (EstimateLinksPoints(links, mid) <= cap ? hi : lo) = mid;
    }
    double coarser = std::min(kMaxSurfaceSpacingM, std::ceil(hi * 1e3) / 1e3);
    // The count steps with the rings' rounding: make sure the rounded spacing fits too.
    while (coarser < kMaxSurfaceSpacingM && EstimateLinksPoints(links, coarser) > cap) {
      coarser = std::min(kMaxSurfaceSpacingM, coarser + 1e-3);
    }
    message << "a spacing of at least " << coarser << " m (--surface-spacing, surface_spacing) or smaller shapes";
  } else {
    message << "smaller shapes (even the largest spacing, " << kMaxSurfaceSpacingM << " m, gives about "
            << EstimateLinksPoints(links, kMaxSurfaceSpacingM) << " points)";
  }
  throw std::invalid_argument(message.str());
}

/// The segments and points of a [[link]], [[tool]] or [[payload]] table into `surface`.
void ReadShapes(const toml::table& table, const std::string& source_name, const std::string& what,
                const std::string& empty_hint, LinkSurface& surface) {
  if (const toml::array* segments = ArrayOfTables(table, "segments", source_name, what)) {
    for (const toml::node& item : *segments) {
      const toml::table& segment = *item.as_table();
      RefuseUnknownKeys(segment, std::array<std::string_view, 3>{"from_m", "to_m", "radius_m"}, source_name,
                        what + " segment");
      SurfaceShape shape;
      shape.type = SurfaceShapeType::kCapsule;
      shape.a_m = ReadPoint(segment, "from_m", source_name, what + " segment");
      shape.b_m = ReadPoint(segment, "to_m", source_name, what + " segment");
      shape.radius_m = ReadRadius(segment, source_name, what + " segment", false);
      shape.origin = covopt::internal::Where(source_name, segment.source());
      surface.shapes.push_back(std::move(shape));
    }
  }
  if (const toml::array* points = ArrayOfTables(table, "points", source_name, what)) {
    for (const toml::node& item : *points) {
      const toml::table& point = *item.as_table();
      RefuseUnknownKeys(point, std::array<std::string_view, 2>{"at_m", "radius_m"}, source_name, what + " point");
      SurfaceShape shape;
      shape.type = SurfaceShapeType::kPoint;
      shape.a_m = ReadPoint(point, "at_m", source_name, what + " point");
      shape.radius_m = ReadRadius(point, source_name, what + " point", true);
      shape.origin = covopt::internal::Where(source_name, point.source());
      surface.shapes.push_back(std::move(shape));
    }
  }
  if (surface.shapes.empty()) {
    FileError(source_name, table.source(), what + ": give segments or points (" + empty_hint + ")");
  }
}

}  // namespace

SurfaceFileShapes ParseSurfaceFile(const std::string& toml_text, const std::string& source_name) {
  toml::table root;
  try {
    root = toml::parse(toml_text, source_name);
  } catch (const toml::parse_error& e) {
    std::string what(e.description());
    std::replace(what.begin(), what.end(), '\n', ' ');
    throw std::invalid_argument(covopt::internal::Where(source_name, e.source()) + ": not a TOML surface file: " + what);
  }
  RefuseUnknownKeys(root, std::array<std::string_view, 3>{"link", "tool", "payload"}, source_name, "surface file");
  SurfaceFileShapes out;
  out.source = source_name;
  // [[tool]] and [[payload]]: shapes in the tip link's frame (the flange), each table adding its own.
  for (const char* name : {"tool", "payload"}) {
    const toml::array* tables = ArrayOfTables(root, name, source_name, "surface file");
    if (tables == nullptr) continue;
    LinkSurface& carried = std::string(name) == "tool" ? out.tool : out.payload;
    carried.link = name;
    for (const toml::node& node : *tables) {
      const toml::table& table = *node.as_table();
      RefuseUnknownKeys(table, std::array<std::string_view, 2>{"segments", "points"}, source_name,
                        "[[" + std::string(name) + "]]");
      ReadShapes(table, source_name, std::string("[[") + name + "]]", "or leave the table out", carried);
    }
  }
  const toml::array* links = ArrayOfTables(root, "link", source_name, "surface file");
  if ((links == nullptr || links->empty()) && out.tool.shapes.empty() && out.payload.shapes.empty()) {
    throw std::invalid_argument(source_name + ": a surface file needs at least one [[link]], [[tool]] or [[payload]] table");
  }
  if (links == nullptr) return out;
  std::set<std::string> seen;
  for (const toml::node& node : *links) {
    const toml::table& link = *node.as_table();
    RefuseUnknownKeys(link, std::array<std::string_view, 3>{"name", "segments", "points"}, source_name, "[[link]]");
    const std::optional<std::string> name = link["name"].value<std::string>();
    if (!name || name->empty()) FileError(source_name, link.source(), "[[link]]: name must be the URDF link's name (a string)");
    const std::string shown = covopt::internal::EscapeControlCharacters(*name);  // one line, whole
    if (!seen.insert(*name).second) FileError(source_name, link.source(), "[[link]] '" + shown + "' is given twice");
    LinkSurface surface;
    surface.link = *name;
    ReadShapes(link, source_name, "link '" + shown + "'", "a link with no surface: leave it out", surface);
    out.links.push_back(std::move(surface));
  }
  return out;
}

SurfaceFileShapes ReadSurfaceFile(const std::filesystem::path& path) {
  return ParseSurfaceFile(internal::ReadBoundedFile(path, kMaxSurfaceFileBytes, "surface file"), path.string());
}

RobotSurface SurfaceFromUrdfString(const std::string& urdf_text, const KinematicChain& chain,
                                   const SurfaceOptions& options, const std::string& source_name) {
  CheckSpacing(options.spacing_m);
  if (!options.surface_file) return SurfaceFromUrdfString(urdf_text, chain, options, source_name, nullptr);
  const SurfaceFileShapes file = ReadSurfaceFile(*options.surface_file);
  return SurfaceFromUrdfString(urdf_text, chain, options, source_name, &file);
}

RobotSurface SurfaceFromUrdfString(const std::string& urdf_text, const KinematicChain& chain,
                                   const SurfaceOptions& options, const std::string& source_name,
                                   const SurfaceFileShapes* file) {
  CheckSpacing(options.spacing_m);
  const urdf::ModelInterfaceSharedPtr model = internal::ParseUrdf(urdf_text, source_name);
  const internal::ModelReleaser release{model.get()};

  std::vector<std::string> chain_links;
  for (const ChainJoint& joint : chain.joints()) chain_links.push_back(joint.child_link);
  std::map<std::string, const LinkSurface*> from_file;
  if (file) {
    for (const LinkSurface& link : file->links) {
      if (std::find(chain_links.begin(), chain_links.end(), link.link) == chain_links.end()) {
        std::string names;
        for (const std::string& name : chain_links) names += (names.empty() ? "" : ", ") + name;
        throw std::invalid_argument(file->source + ": link '" + covopt::internal::EscapeControlCharacters(link.link) + "' is not a moving link of the chain " +
                                    chain.base_link() + " -> " + chain.tip_link() + " (its links: " + names + ")");
      }
      from_file[link.link] = &link;
    }
  }

  RobotSurface surface;
  surface.spacing_m = options.spacing_m;
  for (const std::string& name : chain_links) {
    LinkSurface link;
    link.link = name;
    if (const auto it = from_file.find(name); it != from_file.end()) {
      link.shapes = it->second->shapes;
    } else {
      const urdf::LinkConstSharedPtr urdf_link = model->getLink(name);
      if (!urdf_link) {
        throw std::invalid_argument(source_name + ": link '" + covopt::internal::EscapeControlCharacters(name) +
                                    "' is not in the URDF");
      }
      std::string mesh;
      link.shapes = UrdfShapes(*urdf_link, options, source_name, mesh);
      if (!mesh.empty()) {
        throw std::invalid_argument(source_name + ": link '" + name + "' has mesh collision geometry ('" + mesh +
                                    "'), which covopt does not read: give a surface file with its segments "
                                    "or points (robot/README.md, \"Surface files\")");
      }
    }
    if (link.shapes.empty()) {
      surface.warnings.push_back("link '" + name + "' has no collision geometry: it has no surface points and is "
                                 "never checked");
      continue;
    }
    surface.links.push_back(std::move(link));
  }
  // The tool and the payload of the surface file: carried by the tip link.
  for (const LinkSurface* carried : {file ? &file->tool : nullptr, file ? &file->payload : nullptr}) {
    if (!carried || carried->shapes.empty()) continue;
    surface.links.push_back(LinkSurface{carried->link, chain.tip_link(), carried->shapes, {}});
  }
  // The size, from the shapes, before any point is made.
  CheckSurfaceSize(surface.links, options.spacing_m);
  for (LinkSurface& link : surface.links) {
    for (std::size_t i = 0; i < link.shapes.size(); ++i) {
      std::vector<SurfacePoint> points = SampleShape(link.shapes[i], options.spacing_m, i);
      link.points.insert(link.points.end(), points.begin(), points.end());
    }
  }
  return surface;
}

void AddTipSurface(RobotSurface& surface, const KinematicChain& chain, const std::string& name,
                   const std::vector<SurfaceShape>& shapes) {
  if (shapes.empty()) return;
  std::vector<LinkSurface> links = surface.links;  // the size with the new shapes, before any point is made
  auto it = std::find_if(links.begin(), links.end(), [&](const LinkSurface& l) { return l.link == name; });
  if (it == links.end()) it = links.insert(links.end(), LinkSurface{name, chain.tip_link(), {}, {}});
  const std::size_t first = it->shapes.size();
  it->shapes.insert(it->shapes.end(), shapes.begin(), shapes.end());
  CheckSurfaceSize(links, surface.spacing_m);
  for (std::size_t i = first; i < it->shapes.size(); ++i) {
    std::vector<SurfacePoint> points = SampleShape(it->shapes[i], surface.spacing_m, i);
    it->points.insert(it->points.end(), points.begin(), points.end());
  }
  surface.links = std::move(links);
}

RobotSurface SurfaceFromUrdfFile(const std::filesystem::path& path, const KinematicChain& chain,
                                 const SurfaceOptions& options) {
  return SurfaceFromUrdfString(internal::ReadBoundedFile(path, kMaxUrdfBytes, "URDF file"), chain, options,
                               path.string());
}

}  // namespace covopt::robot
