// The tool's and the payload's shape specs (tool_surface.hpp).
#include "covopt/audit/tool_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <covopt/core/number_format.hpp>
#include <covopt/core/physical_floors.hpp>
#include <covopt/core/quantity.hpp>

namespace covopt::audit {
namespace {

/// A length as typed: metres, or with its unit. Bare numbers are not checked for plausibility
/// here: every value has its own range below.
constexpr QuantitySpec kToolLength{QuantityKind::kLength, false, false, 0.0, std::numeric_limits<double>::infinity(),
                                   {"mm", "cm"}, "tool length"};

struct Spec {
  std::string where;  ///< "--tool-surface 'box:...'"
  std::map<std::string, std::string> values;

  [[noreturn]] void Fail(const std::string& key, const std::string& problem) const {
    throw std::invalid_argument(where + ": " + key + ": " + problem);
  }
  std::vector<double> Numbers(const std::string& key, std::size_t count) const {
    const auto it = values.find(key);
    if (it == values.end()) Fail(key, "missing");
    std::vector<double> out;
    std::string text = it->second;
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = text.find(',', start);
      const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      try {
        out.push_back(ParseQuantity(item, kToolLength, key));
      } catch (const std::invalid_argument& e) {
        Fail(key, std::string(e.what()));
      }
      if (!std::isfinite(out.back())) Fail(key, "not a finite length (got '" + item + "')");
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (out.size() != count) {
      Fail(key, count == 1 ? "expected one length (got '" + text + "')"
                           : "expected " + std::to_string(count) + " lengths x,y,z (got '" + text + "')");
    }
    return out;
  }
  Eigen::Vector3d Point(const std::string& key) const {
    const std::vector<double> v = Numbers(key, 3);
    for (const double x : v) {
      if (std::abs(x) > kMaxToolCoordinate_m) {
        Fail(key, "each coordinate must be within ±" + FormatSignificant(kMaxToolCoordinate_m) +
                      " m of the flange (got " + FormatSignificant(x) + " m)");
      }
    }
    return {v[0], v[1], v[2]};
  }
  /// Roll, pitch, yaw [rad] about the flange's fixed x, y, z (as a URDF origin's rpy).
  Eigen::Matrix3d Rotation(const std::string& key) const {
    const std::string& text = values.at(key);
    std::array<double, 3> a{};
    std::size_t start = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t comma = text.find(',', start);
      if ((k < 2) != (comma != std::string::npos)) Fail(key, "expected three angles r,p,y in rad (got '" + text + "')");
      const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      std::size_t used = 0;
      try {
        a[k] = std::stod(item, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != item.size() || !(std::abs(a[k]) <= 7.0)) {
        Fail(key, "each angle must be a number of radians within ±7 rad (got '" + item + "')");
      }
      start = comma + 1;
    }
    return (Eigen::AngleAxisd(a[2], Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(a[1], Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(a[0], Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
  }
  double Length(const std::string& key, double min_m, double max_m) const {
    const double x = Numbers(key, 1).front();
    if (!(x >= min_m && x <= max_m)) {
      Fail(key, "must be in [" + FormatSignificant(min_m * 1e3) + " mm, " + FormatSignificant(max_m * 1e3) +
                    " mm] (got " + FormatSignificant(x * 1e3) + " mm)");
    }
    return x;
  }
};

}  // namespace

robot::SurfaceShape ParseTipShape(std::string_view spec_text, std::string_view field) {
  const std::string text(spec_text);
  Spec spec{std::string(field) + " '" + text + "'", {}};
  const std::size_t colon = text.find(':');
  const std::string type = text.substr(0, colon);
  const std::map<std::string, std::vector<std::string>> keys{
      {"capsule", {"from", "to", "radius"}}, {"sphere", {"center", "radius"}}, {"box", {"center", "size", "edge", "rpy"}}};
  const auto kind = keys.find(type);
  if (kind == keys.end()) {
    throw std::invalid_argument(spec.where + ": shape: expected capsule:, sphere: or box: (e.g. "
                                "'sphere:center=0,0,0.1;radius=30mm'; got '" + type + "')");
  }
  const std::vector<std::string>& allowed = kind->second;
  std::string rest = colon == std::string::npos ? std::string() : text.substr(colon + 1);
  std::size_t start = 0;
  while (start <= rest.size() && !rest.empty()) {
    const std::size_t semi = rest.find(';', start);
    const std::string item = rest.substr(start, semi == std::string::npos ? std::string::npos : semi - start);
    const std::size_t eq = item.find('=');
    const std::string key = item.substr(0, eq);
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end() || eq == std::string::npos) {
      std::string names;
      for (const std::string& k : allowed) names += (names.empty() ? "" : ", ") + k;
      spec.Fail(key.empty() ? "key" : key, "a " + type + " takes " + names + " as key=value separated by ';'");
    }
    if (!spec.values.emplace(key, item.substr(eq + 1)).second) spec.Fail(key, "given twice");
    if (semi == std::string::npos) break;
    start = semi + 1;
  }
  robot::SurfaceShape shape;
  shape.origin = spec.where;
  if (type == "capsule" || type == "sphere") {
    shape.type = type == "capsule" ? robot::SurfaceShapeType::kCapsule : robot::SurfaceShapeType::kSphere;
    shape.a_m = spec.Point(type == "capsule" ? "from" : "center");
    if (type == "capsule") {
      shape.b_m = spec.Point("to");
      if ((shape.b_m - shape.a_m).norm() < kMinRadius_m) spec.Fail("to", "coincides with from: give a sphere instead");
    }
    shape.radius_m = spec.Length("radius", kMinRadius_m, kMaxToolRadius_m);
    return shape;
  }
  shape.type = robot::SurfaceShapeType::kBox;
  shape.pose = Eigen::Isometry3d::Identity();
  shape.pose.translation() = spec.Point("center");
  const std::vector<double> size = spec.Numbers("size", 3);
  for (const double x : size) {
    if (!(x >= 2.0 * kMinRadius_m && x <= kMaxToolExtent_m)) {
      spec.Fail("size", "each extent must be in [0.2 mm, " + FormatSignificant(kMaxToolExtent_m * 1e3) + " mm] (got " +
                            FormatSignificant(x * 1e3) + " mm)");
    }
  }
  shape.size_m = {size[0], size[1], size[2]};
  shape.edge_radius_m = spec.Length("edge", kMinRadius_m, 0.5 * shape.size_m.minCoeff());
  if (spec.values.count("rpy")) shape.pose.linear() = spec.Rotation("rpy");
  return shape;
}

}  // namespace covopt::audit
