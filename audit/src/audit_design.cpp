// The per-link design of `covopt audit --design`: per link the thinnest catalog covering safe at
// full speed against the demand the audit's pass collected, then checked again by a second audit.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "audit_internal.hpp"
#include "robust_internal.hpp"

namespace covopt::audit::detail {
namespace {

/// The per-link design: the thinnest thickness per material with E* >= the link's demand for
/// every radius and region it meets, rounded up to the step.
struct DesignTry {
  std::optional<double> thickness_m;
  std::string why_not;
};

DesignTry DesignMaterial(const AuditSetup& setup, const AuditDesignOptions& d, const RegionLimits& regions,
                         const LinkPlan& plan, const std::vector<double>& demand, const CandidateMaterial& material) {
  DesignTry out;
  if (material.crush_behaviour == materials::CrushBehaviour::kUnknown && setup.rule.refuses_unknown_strength()) {
    out.why_not = material.name + ": compressive strength unknown (refused by the rule)";
    return out;
  }
  const std::size_t n_regions = regions.size();
  // The (radius, region) pairs the link meets, the most demanding first.
  std::vector<std::size_t> pairs;
  for (std::size_t k = 0; k < demand.size(); ++k) {
    if (demand[k] > 0.0) pairs.push_back(k);
  }
  std::sort(pairs.begin(), pairs.end(), [&](std::size_t a, std::size_t b) { return demand[a] > demand[b]; });
  std::size_t last_failed = 0;  // checked first next time (the pair that binds stays the same)
  auto admissible = [&](double b) {
    AuditCovering covering{optim::CoveringOf(material, b, CoveringLaw::kAuto), material};
    auto ok = [&](std::size_t k) {
      const EnergyLimit limit = regions.Limit(covering, plan.radii[k / n_regions], k % n_regions);
      return limit.ceiling || limit.energy_J >= demand[k];
    };
    if (!pairs.empty() && !ok(pairs[last_failed])) return false;
    for (std::size_t j = 0; j < pairs.size(); ++j) {
      if (j == last_failed) continue;
      if (!ok(pairs[j])) {
        last_failed = j;
        return false;
      }
    }
    return true;
  };
  DesignSpace space;  // only its thickness range is read
  space.min_thickness_m = d.min_thickness_m;
  space.max_thickness_m = d.max_thickness_m;
  std::optional<double> thickness =
      internal::ThinnestAdmissibleThickness(space, d.thickness_scan_points, d.thickness_resolution_m, admissible);
  if (!thickness) {
    out.why_not = material.name + ": not safe at any thickness in " + Millimetres(d.min_thickness_m) + " .. " +
                  Millimetres(d.max_thickness_m);
    return out;
  }
  if (d.thickness_step_m > 0.0) {
    std::optional<double> beyond_max;
    const std::optional<double> stock = internal::FirstAdmissibleStock(
        *thickness, d.thickness_step_m, d.max_thickness_m, [](double b) { return b; }, admissible, beyond_max);
    if (stock) thickness = *stock;  // else the exact thinnest (no stock thickness within the range)
  }
  out.thickness_m = thickness;
  return out;
}

/// Sets every designed link's re-checked governing ratio and message from a second audit of
/// `recheck` (every designed link at its covering).
void Recheck(const AuditSetup& setup, const AuditSetup& recheck, const robot::JointTrajectory& trajectory,
             const std::vector<std::size_t>& designed, AuditResult& result) {
  if (designed.empty()) return;
  AuditOptions again;
  again.keep_ratio_over_time = false;
  const AuditResult checked = Audit(recheck, trajectory, again);
  const double sf = setup.rule.safety_factor;
  for (std::size_t l : designed) {
    AuditLinkDesign& ld = result.link_designs[l];
    ld.governing_ratio = 0.0;
    for (std::size_t r = 0; r < checked.regions.size(); ++r) {
      ld.governing_ratio = std::max(ld.governing_ratio, checked.cell(l, r).governing_ratio);
    }
    const bool safe = sf * ld.governing_ratio <= 1.0;
    ld.message = ld.material->name + " at " + Millimetres(*ld.thickness_m) + ": " +
                 (safe ? "safe at full speed" : "NOT safe at full speed when checked again") +
                 " (governing ratio " + FormatSignificant(ld.governing_ratio, 4) + ")";
    if (!safe) {
      result.warnings.push_back("link '" + result.links[l] + "': the designed covering failed its re-check");
    }
  }
}

}  // namespace

void DesignLinks(const AuditSetup& setup, const robot::JointTrajectory& trajectory, const AuditOptions& options,
                 const RegionLimits& regions, const std::vector<LinkPlan>& plans, const Pass& pass,
                 AuditResult& result) {
  // The per-link design, then a second audit with every designed link at its covering.
  const AuditDesignOptions& d = options.design;
  if (setup.braking_m_per_s2 > 0.0) {
    result.warnings.push_back(
        "braking: the per-link design is the unbraked robot's (conservative: braking only takes energy out); its "
        "re-check is braked");
  }
  AuditSetup recheck = setup;
  std::vector<std::size_t> designed;
  for (std::size_t l = 0; l < plans.size(); ++l) {
    AuditLinkDesign ld;
    ld.link = l;
    const std::vector<double>& demand = pass.demand_J[l];
    if (std::none_of(demand.begin(), demand.end(), [](double e) { return e > 0.0; })) {
      ld.message = "the link never moves: no covering needed";
      result.link_designs.push_back(std::move(ld));
      continue;
    }
    LinkPlan plan;
    plan.chain_index = plans[l].chain_index;
    plan.surface = plans[l].surface;
    try {
      PlanRadii(setup, *plan.surface, /*covered=*/true, plan);
    } catch (const std::invalid_argument& e) {
      ld.message = std::string("no design: ") + e.what();
      result.link_designs.push_back(std::move(ld));
      continue;
    }
    // The demand was accumulated on the audited covering's radii; map it onto the covered ones.
    std::vector<double> covered_demand(plan.radii.size() * regions.size(), 0.0);
    for (std::size_t p = 0; p < plan.point_radius.size(); ++p) {
      const std::size_t from = plans[l].point_radius[p], to = plan.point_radius[p];
      for (std::size_t r = 0; r < regions.size(); ++r) {
        double& e = covered_demand[to * regions.size() + r];
        e = std::max(e, demand[from * regions.size() + r]);
      }
    }
    std::vector<std::string> why_not;
    for (const CandidateMaterial& material : d.materials) {
      const DesignTry t = DesignMaterial(setup, d, regions, plan, covered_demand, material);
      if (!t.thickness_m) {
        why_not.push_back(t.why_not);
        continue;
      }
      if (!ld.thickness_m || *t.thickness_m < *ld.thickness_m) {  // ties: catalog order
        ld.thickness_m = t.thickness_m;
        ld.material = material;
      }
    }
    if (!ld.material) {
      ld.message = "no material in " + Millimetres(d.min_thickness_m) + " .. " + Millimetres(d.max_thickness_m) +
                   " makes the link safe at full speed";
      for (const std::string& w : why_not) ld.message += "; " + w;
    } else {
      recheck.link_coverings[result.links[l]] =
          AuditCovering{optim::CoveringOf(*ld.material, *ld.thickness_m, CoveringLaw::kAuto), ld.material};
      designed.push_back(l);
    }
    result.link_designs.push_back(std::move(ld));
  }
  Recheck(setup, recheck, trajectory, designed, result);
}

}  // namespace covopt::audit::detail
