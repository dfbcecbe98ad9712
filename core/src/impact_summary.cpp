// The pieces every result's summary shares, and the summary of one head impact (simulate).
#include <cmath>
#include <string>

#include "covopt/core/impact_result.hpp"
#include "covopt/core/number_format.hpp"
#include "covopt/core/result_summary.hpp"
#include "covopt/core/scene.hpp"

namespace covopt {

std::string HeadTarget(HeadArea area) { return "head (" + std::string(ToString(area)) + ")"; }

std::string LawWord(bool covered, CoveringLaw law) { return covered ? std::string(ToString(law)) : "bare"; }

std::string ValidityWords(bool covered, const CoveringValidity& validity) {
  if (!covered) return "";
  return validity.within ? "within" : validity.note;
}

CoveringSummary SummarizeCovering(double thickness_m, std::string_view material, CoveringLaw law,
                                  const CoveringValidity& validity) {
  if (!(thickness_m > 0.0)) return {};
  return CoveringSummary{.present = true,
                         .material = std::string(material),
                         .thickness_m = thickness_m,
                         .law = LawWord(true, law),
                         .validity = ValidityWords(true, validity),
                         .validity_ratio = validity.ratio};
}

ResultSummary SummarizeImpact(const Scene& scene, const ImpactResult& result, const Verdict& verdict,
                              std::string_view material) {
  const bool covered = scene.covering.thickness_m > 0.0;
  const CoveringLaw law = result.peaks.covering_law;
  ResultSummary s;
  s.command = "simulate";
  s.AddVerdict(HeadTarget(scene.head.area), verdict, LawWord(covered, law), ValidityWords(covered, result.validity));
  s.Finish();
  s.governing_case = "one impact of the robot at " + FormatSignificant(scene.robot.speed_m_per_s, 4) + " m/s";
  s.covering = SummarizeCovering(scene.covering.thickness_m, material, law, result.validity);
  s.robot = RobotSummary{.model_file = "",
                         .motion = "",
                         .joints = {},
                         .reflected_mass_kg = scene.robot.mass_kg,
                         .payload_kg = 0.0,
                         .speed_m_per_s = scene.robot.speed_m_per_s};
  return s;
}

}  // namespace covopt
