#include "covopt/report/robust_text.hpp"

#include <utility>

#include <fmt/format.h>

#include "covopt/core/quantity.hpp"
#include "covopt/core/scene_fields.hpp"

namespace covopt::report {

std::string DescribeValues(const optim::UncertaintyBox& box, std::span<const double> values) {
  std::string text;
  for (std::size_t i = 0; i < box.size() && i < values.size(); ++i) {
    if (!text.empty()) text += ", ";
    text += fmt::format("{} {}", box.inputs()[i].field, FormatQuantity(values[i], box.field(i).spec.kind));
  }
  return text;
}

void PrintWorstCase(std::ostream& out, const optim::UncertaintyBox& box, const optim::WorstCase& worst,
                    std::string_view indent) {
  out << fmt::format("{}worst case: {} (found by {}, {} evaluations)\n", indent, DescribeValues(box, worst.values),
                     worst.found_by, worst.evaluations);
  const CoveringSpec& covering = worst.scene.covering;
  const bool foam = covering.compressive_curve && covering.law != CoveringLaw::kHertz;
  out << fmt::format("{}  laceration ratio {:.4f}, contusion ratio {:.4f}, fracture ratio {:.4f}{}{}; governing "
                     "ratio {:.4f} ({} binds): {}\n",
                     indent, worst.laceration_ratio, worst.contusion_ratio, worst.fracture_ratio,
                     covering.thickness_m > 0.0
                         ? fmt::format(", compression {:.1f} % of the {}", 100.0 * worst.compression_ratio,
                                       foam ? "foam's measured curve (foam law)" : "covering")
                         : std::string(),
                     worst.crush_ratio > 0.0 ? fmt::format(", crush ratio {:.4f}", worst.crush_ratio) : std::string(),
                     worst.governing_ratio,
                     optim::ToString(worst.binding, foam ? CoveringLaw::kFoam : CoveringLaw::kHertz),
                     worst.admissible ? "admissible for every value in the box" : "NOT admissible for the whole box");
  if (worst.corner_governing_ratio) {
    out << fmt::format("{}  the corners alone give {:.4f}{}\n", indent, *worst.corner_governing_ratio,
                       *worst.corner_governing_ratio < worst.governing_ratio * (1.0 - 1e-9)
                           ? " (the worst case is inside the box, not at a corner)"
                           : "");
  }
}

void PrintInjuryProbability(std::ostream& out, const optim::InjuryProbability& p, std::string_view indent) {
  out << fmt::format("{}probability over {} samples (seed {}), Wilson 95 % intervals:\n", indent, p.any.samples, p.seed);
  const std::pair<const char*, const optim::ProbabilityEstimate*> rows[] = {
      {"laceration", &p.laceration},           {"contusion", &p.contusion}, {"fracture", &p.fracture},
      {"any injury", &p.any},                  {"fully compressed", &p.fully_compressed},
      {"crushed", &p.crushed},                 {"inadmissible", &p.inadmissible}};
  for (const auto& [name, e] : rows) {
    out << fmt::format("{}  {:<17} {:>10.6f}  [{:.6f}, {:.6f}]  ({} of {})\n", indent, name, e->probability,
                       e->ci95_low, e->ci95_high, e->count, e->samples);
  }
}

void PrintTimePathUse(std::ostream& out, const optim::UncertaintyBox& box, const optim::TimePathUse& use,
                      std::string_view indent) {
  if (!box.brakes()) return;
  out << fmt::format("{}Braking robot: {} time-path runs; {} impacts screened by the unbraked exact path's bound, {} "
                     "with the brake after the unbraked peak (exact path) (docs/model.md §11)\n",
                     indent, use.runs, use.screened, use.brake_after_peak);
  if (use.failed > 0) {
    out << fmt::format("{}Warning: {} time-path runs failed, each judged inadmissible (never safe); the first: {}\n",
                       indent, use.failed, use.first_failure);
  }
}

void PrintElasticities(std::ostream& out, const optim::ElasticityTable& table) {
  out << fmt::format("Sensitivities (elasticities d ln r / d ln x) at r_L {:.4f}, r_C {:.4f}{}:\n",
                     table.laceration_ratio, table.contusion_ratio,
                     table.compression_ratio ? fmt::format(", r_delta {:.4f}", *table.compression_ratio) : "");
  out << fmt::format("  {:<20} {:>12} {:>11} {:>10} {:>12}  {}\n", "input", "value", "laceration", "contusion",
                     "compression", "method");
  for (const optim::InputElasticity& r : table.rows) {
    const covopt::SceneField* field = FindSceneField(r.field);
    out << fmt::format("  {:<20} {:>12} {:>+11.4f} {:>+10.4f} {:>12}  {}{}\n", r.field,
                       field ? FormatQuantity(r.value, field->spec.kind) : fmt::format("{:g}", r.value), r.laceration,
                       r.contusion, r.compression ? fmt::format("{:+.4f}", *r.compression) : "-",
                       optim::ToString(r.method), r.reliable ? "" : " (steps disagree: a kink nearby)");
  }
}

}  // namespace covopt::report
