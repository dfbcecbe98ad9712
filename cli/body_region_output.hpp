#pragma once
/// @file body_region_output.hpp
/// The words and verdict blocks the --body-region forms of `simulate`, `speed-limit` and
/// `optimize` print (docs/model.md §13): forces, pressures and lengths as the tables show them,
/// the robot's surface, the braking and the contact, one judgement's block. Shared by those
/// commands' files; no command's own code.

#include <optional>
#include <ostream>
#include <string>
#include <string_view>

#include "covopt/core/body_contact.hpp"
#include "covopt/optim/body_region_check.hpp"
#include "body_region_options.hpp"
#include "simulation_plan.hpp"

namespace covopt::cli::body_text {

using optim::BodyRegionJudgement;

/// "1234 N" (4 significant digits).
std::string Newtons(double n);
/// A pressure in N/cm² (4 significant digits).
std::string NPerCm2(double pa);
/// A length in mm (3 significant digits).
std::string Mm(double m);
/// "5.1 kg", or "fixed" for an infinite mass.
std::string Mass(double kg);

/// "radius 15 mm; covering 15 mm, 27.6 MPa, ν 0.25 (material)" or "flat; bare".
std::string RobotSurface(const BodyContactScene& s, const std::optional<std::string>& material);

/// "100 m/s² after 5 ms, while the robot still moves forward (time path)".
std::string BrakingText(const BodyContactScene& s);

/// "transient contact; bare robot's contact area 1 cm²".
std::string ContactText(const BodyRegionPlan& regions);

/// The covering's catalog material, when the plan has a covering from the catalog.
std::optional<std::string> MaterialName(const SimulationPlan& plan);

/// The verdict block of one judgement (simulate; optimize's recommendation): its criteria as
/// report::CriterionText words them, and what was not evaluated.
void PrintJudgement(std::ostream& out, const optim::BodyRegionJudgement& v, std::string_view indent);

/// The verdict's summary (report::VerdictSummary): "SAFE (governing force, ratio 0.812, margin 18.8 %, ...)".
std::string VerdictWord(const optim::BodyRegionJudgement& v);

}  // namespace covopt::cli::body_text
