#include "covopt/report/design_csv.hpp"

#include <cmath>

#include <fmt/format.h>

#include "covopt/report/csv.hpp"

namespace covopt::report {

std::string DesignCandidatesCsv(const std::vector<optim::CandidateOutcome>& candidates, const optim::DesignRule& rule) {
  std::string csv =
      "rank,material,family,youngs_modulus_Pa,poisson_ratio,poisson_assumed,crush_behaviour,compressive_strength_Pa,"
      "admissible,thickness_m,min_safe_thickness_m,laceration_ratio,contusion_ratio,compression_ratio,crush_ratio,"
      "governing_criterion,governing_ratio,margin,max_compressive_stress_Pa,fully_compressed\n";
  const auto quoted = [](const std::string& text) { return CsvField(text); };
  const auto number = [](double v) { return std::isfinite(v) ? fmt::format("{}", v) : std::string(); };
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const optim::CandidateOutcome& c = candidates[i];
    const optim::GoverningRatio g = c.score.governing(rule);
    const bool crushes = c.material.crush_behaviour == materials::CrushBehaviour::kCrushes;
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", i + 1, quoted(c.material.name),
                       quoted(c.material.family), number(c.material.youngs_modulus_Pa),
                       number(c.material.poisson_ratio), c.material.poisson_assumed,
                       materials::ToString(c.material.crush_behaviour),
                       crushes ? number(c.material.compressive_strength_Pa) : "", c.safe,
                       number(c.score.design.thickness_m),
                       c.min_safe_thickness_m ? number(*c.min_safe_thickness_m) : "",
                       number(c.score.laceration_ratio), number(c.score.contusion_ratio),
                       number(c.score.compression_ratio),
                       c.score.crush_check == optim::CrushCheck::kChecked ? number(c.score.crush_ratio) : "",
                       optim::ToString(g.criterion), number(g.ratio), number(c.margin),
                       number(c.score.peaks.max_compressive_stress_Pa), c.score.peaks.fully_compressed);
  }
  return csv;
}

}  // namespace covopt::report
