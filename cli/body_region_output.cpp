#include "body_region_output.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/core/quantity.hpp"
#include "covopt/core/verdict.hpp"
#include "covopt/report/verdict_text.hpp"
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

/// The verdict block of one judgement (simulate; optimize's recommendation): each criterion of
/// its verdict as the library words it (report::CriterionText: the standard's and the derated
/// limit with every EXCEEDED), and what was not evaluated.
void PrintJudgement(std::ostream& out, const BodyRegionJudgement& v, std::string_view indent) {
  for (const Criterion& c : v.verdict.criteria) {
    fmt::print(out, "{}{}\n", indent, report::CriterionText(c, v.verdict.safety_factor));
  }
  if (!v.pressure_ratio) {
    fmt::print(out, "{}{:<17} not evaluated (no --contact-area); limit {}\n", indent, "pressure",
               NPerCm2(v.limits.pressure_Pa));
  }
  if (v.crush_check == optim::CrushCheck::kDoesNotCrush) fmt::print(out, "{}{:<17} does-not-crush\n", indent, "crush");
}

std::string VerdictWord(const BodyRegionJudgement& v) { return report::VerdictSummary(v.verdict); }

}  // namespace body_text
}  // namespace covopt::cli
