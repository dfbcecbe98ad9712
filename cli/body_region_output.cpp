#include "body_region_output.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/core/quantity.hpp"
#include "covopt/report/body_contact_json.hpp"
#include "covopt/report/csv.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "report_option.hpp"

namespace covopt::cli {
namespace body_text {

using optim::BodyRegionJudgement;

std::string Newtons(double n) { return fmt::format("{:.4g} N", n); }
std::string NPerCm2(double pa) { return fmt::format("{:.4g} N/cm²", pa * 1e-4); }
std::string Mm(double m) { return fmt::format("{:.3g} mm", m * 1e3); }
std::string Mass(double kg) { return std::isinf(kg) ? std::string("fixed") : fmt::format("{:.4g} kg", kg); }
std::string Percent(double fraction) { return fmt::format("{:.1f} %", 100.0 * fraction); }

/// "radius 15 mm; covering 15 mm, 27.6 MPa, ν 0.25 (material)" or "flat; bare".
std::string RobotSurface(const BodyContactScene& s, const std::optional<std::string>& material) {
  std::string text = std::isinf(s.robot_radius_m) ? std::string("flat robot") : "robot radius " + Mm(s.robot_radius_m);
  if (s.has_covering()) {
    text += fmt::format("; covering {}, {}, ν {:g}{}", Mm(s.covering.thickness_m),
                        FormatQuantity(s.covering.youngs_modulus_Pa, QuantityKind::kModulus), s.covering.poisson_ratio,
                        material ? " (" + *material + ")" : std::string());
  } else {
    text += "; bare (no covering)";
  }
  return text;
}

/// "100 m/s² after 5 ms, while the robot still moves forward (time path)".
std::string BrakingText(const BodyContactScene& s) {
  return fmt::format("{} after {}, while the robot still moves forward (the time path answers)",
                     FormatQuantity(s.braking_m_per_s2, QuantityKind::kAcceleration),
                     FormatQuantity(s.reaction_delay_s, QuantityKind::kTime));
}

std::string ContactText(const BodyRegionPlan& regions) {
  return fmt::format("{} contact; bare robot's contact area {}", ToString(regions.contact),
                     regions.contact_area_m2 > 0.0 ? FormatQuantity(regions.contact_area_m2, QuantityKind::kArea)
                                                   : std::string("not given"));
}

std::optional<std::string> MaterialName(const SimulationPlan& plan) {
  if (plan.covering_material && plan.scene.covering.thickness_m > 0.0) return plan.covering_material->name;
  return std::nullopt;
}

/// "ok" or "EXCEEDED" for a ratio under the safety factor.
std::string_view Mark(double ratio, double sf) { return sf * ratio <= 1.0 ? "ok" : "EXCEEDED"; }

/// The verdict block of one judgement (simulate; optimize's recommendation).
void PrintJudgement(std::ostream& out, const BodyRegionJudgement& v, double sf, std::string_view indent) {
  const BodyContactResult& c = v.contact;
  fmt::print(out, "{}{:<12} {:<12} limit {:<12} ratio {:.3f}  {}\n", indent, "force", Newtons(c.peak_force_N),
             Newtons(v.limits.force_N), v.force_ratio, Mark(v.force_ratio, sf));
  if (v.pressure_ratio && c.peak_pressure_Pa) {
    fmt::print(out, "{}{:<12} {:<12} limit {:<12} ratio {:.3f}  {}\n", indent, "pressure", NPerCm2(*c.peak_pressure_Pa),
               NPerCm2(v.limits.pressure_Pa), *v.pressure_ratio, Mark(*v.pressure_ratio, sf));
  } else {
    fmt::print(out, "{}{:<12} not evaluated (no --contact-area); limit {}\n", indent, "pressure",
               NPerCm2(v.limits.pressure_Pa));
  }
  if (c.covering_deflection_m > 0.0 || c.fully_compressed) {
    fmt::print(out, "{}{:<12} {} of the travel{}  ratio {:.3f}  {}\n", indent, "compression", Percent(v.compression_ratio),
               c.fully_compressed ? " (fully compressed)" : "", v.compression_ratio,
               c.fully_compressed ? std::string_view("EXCEEDED") : Mark(v.compression_ratio, sf));
  }
  if (v.crush_check == optim::CrushCheck::kChecked) {
    fmt::print(out, "{}{:<12} ratio {:.3f} of the compressive strength  {}\n", indent, "crush", v.crush_ratio,
               Mark(v.crush_ratio, sf));
  } else if (v.crush_check != optim::CrushCheck::kNoMaterial) {
    fmt::print(out, "{}{:<12} {}\n", indent, "crush", optim::ToString(v.crush_check));
  }
}

std::string VerdictWord(const BodyRegionJudgement& v) {
  return fmt::format("{}: governed by {} (ratio {:.3f}, margin {})", v.admissible ? "safe" : "NOT SAFE",
                     optim::ToString(v.governing), v.governing_ratio, Percent(v.margin));
}

}  // namespace body_text
}  // namespace covopt::cli
