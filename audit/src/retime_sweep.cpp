// Cycle time against covering thickness (docs/model.md, "Re-timing"): Retime at every covering
// of the sweep, the joint limits and the path prepared once.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <covopt/optim/covering_design.hpp>

#include "retime_internal.hpp"
#include "validation_internal.hpp"

namespace covopt::audit {
using namespace detail;
namespace {

using optim::internal::Number;
using optim::internal::Require;

/// `design`'s covering at `thickness_m`: a catalog material's law at that thickness, or the
/// modulus with the thickness replaced.
AuditCovering CoveringAt(const CycleTimeDesign& design, double thickness_m) {
  AuditCovering covering = design.covering;
  if (covering.material && thickness_m > 0.0) {
    covering.covering = optim::CoveringOf(*covering.material, thickness_m, CoveringLaw::kAuto);
  }
  covering.covering.thickness_m = thickness_m;
  return covering;
}

/// One point: Retime at `setup`, its failures kept (a refused covering is a point that could
/// not be judged, with the refusal as its message).
CycleTimePoint PointOf(const AuditSetup& setup, const robot::JointTrajectory& trajectory, const RetimeOptions& options,
                       const RetimeInputs& in, std::size_t design, double thickness_m) {
  CycleTimePoint p;
  p.design = design;
  p.thickness_m = thickness_m;
  p.cycle_time_s = kInf;
  p.uniform_cycle_time_s = kInf;
  try {
    const RetimeResult r = RetimeWith(setup, trajectory, options, in);
    p.status = r.status;
    if (r.status == RetimeStatus::kSafe || r.status == RetimeStatus::kAtRest) p.cycle_time_s = r.cycle_time_s;
    p.uniform_cycle_time_s = r.uniform_cycle_time_s;
    p.safe_speed_scale = r.before.safe_speed_scale;
    p.message = r.message;
  } catch (const std::invalid_argument& e) {
    p.status = RetimeStatus::kEvaluationFailed;
    p.message = std::string("refused: ") + e.what();
  }
  return p;
}

/// The per-link design's point: the audit's design gives each link its covering.
CycleTimePoint DesignPoint(const AuditSetup& setup, const robot::JointTrajectory& trajectory,
                           const RetimeOptions& options, const RetimeInputs& in, std::size_t d,
                           const AuditDesignOptions& design) {
  AuditOptions audit_options;
  audit_options.keep_ratio_over_time = false;
  audit_options.design = design;
  AuditSetup designed = setup;
  double thickest = 0.0;
  std::size_t undesigned = 0;
  try {
    const AuditResult audited = Audit(setup, trajectory, audit_options);
    for (const AuditLinkDesign& ld : audited.link_designs) {
      if (!ld.material || !ld.thickness_m) {
        ++undesigned;
        continue;
      }
      designed.link_coverings[audited.links[ld.link]] =
          AuditCovering{optim::CoveringOf(*ld.material, *ld.thickness_m, CoveringLaw::kAuto), ld.material};
      thickest = std::max(thickest, *ld.thickness_m);
    }
  } catch (const std::invalid_argument& e) {
    CycleTimePoint p;
    p.design = d;
    p.status = RetimeStatus::kEvaluationFailed;
    p.cycle_time_s = kInf;
    p.uniform_cycle_time_s = kInf;
    p.message = std::string("refused: ") + e.what();
    return p;
  }
  CycleTimePoint p = PointOf(designed, trajectory, options, in, d, thickest);
  if (undesigned > 0) {
    p.message += "; " + std::to_string(undesigned) +
                 " link(s) without a designed covering (never moving, or none in range) keep the setup's covering";
  }
  return p;
}

}  // namespace

std::vector<CycleTimePoint> CycleTimeAgainstThickness(const AuditSetup& setup,
                                                      const robot::JointTrajectory& trajectory,
                                                      const RetimeOptions& options,
                                                      const std::vector<CycleTimeDesign>& designs,
                                                      const std::vector<double>& thicknesses_m) {
  Require(!designs.empty(), "designs: none given (a covering to sweep, or the per-link design)");
  const bool any_fixed = std::any_of(designs.begin(), designs.end(),
                                     [](const CycleTimeDesign& d) { return !d.design.has_value(); });
  Require(!any_fixed || !thicknesses_m.empty(), "thicknesses_m: none given for the coverings to sweep");
  for (std::size_t k = 0; k < thicknesses_m.size(); ++k) {
    const double b = thicknesses_m[k];
    Require(std::isfinite(b) && b >= 0.0 && b <= 1.0,
            "thicknesses_m[" + std::to_string(k) + "] must be in [0, 1] m (0: bare) (got " + Number(b) + ")");
  }
  for (std::size_t d = 0; d < designs.size(); ++d) {
    Require(!designs[d].design || !designs[d].design->materials.empty(),
            "designs[" + std::to_string(d) + "] ('" + designs[d].name +
                "').design.materials: empty; the per-link design needs catalog materials to choose from");
  }
  const RetimeInputs in = PrepareRetime(setup.chain, trajectory, options);
  std::vector<CycleTimePoint> points;
  for (std::size_t d = 0; d < designs.size(); ++d) {
    if (designs[d].design) {
      points.push_back(DesignPoint(setup, trajectory, options, in, d, *designs[d].design));
      continue;
    }
    for (double b : thicknesses_m) {
      AuditSetup at = setup;
      at.covering = CoveringAt(designs[d], b);
      at.link_coverings.clear();
      CycleTimePoint p = PointOf(at, trajectory, options, in, d, b);
      if (!setup.link_coverings.empty()) {
        p.message += "; every link wears this covering (the setup's " + std::to_string(setup.link_coverings.size()) +
                     " per-link covering(s) replaced)";
      }
      points.push_back(std::move(p));
    }
  }
  return points;
}

}  // namespace covopt::audit
