// The inputs of `covopt retime` and covopt.retime() (retime_inputs.hpp).
#include "covopt/audit/retime_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <covopt/core/number_format.hpp>
#include <covopt/optim/covering_design.hpp>
#include <covopt/optim/design.hpp>
#include <covopt/scene_file/sweep_axis.hpp>

namespace covopt::audit {

Eigen::VectorXd JointLimitVector(std::span<const double> values, std::size_t joint_count, std::string_view field,
                                 double max, bool allow_infinite) {
  for (std::size_t j = 0; j < values.size(); ++j) {
    const double v = values[j];
    if (v > 0.0 && (v <= max || (allow_infinite && std::isinf(v)))) continue;
    throw std::invalid_argument(std::string(field) + ": " + (values.size() > 1 ? "joint " + std::to_string(j + 1) + ": " : "") +
                                "expected a limit > 0 and <= " + FormatSignificant(max, 3) +
                                (allow_infinite ? " or inf (none)" : "") + " (got " + FormatSignificant(v, 6) + ")");
  }
  if (values.size() == 1) return Eigen::VectorXd::Constant(static_cast<Eigen::Index>(joint_count), values.front());
  if (values.size() != joint_count) {
    throw std::invalid_argument(std::string(field) + ": expected one value for every joint or one per joint (" +
                                std::to_string(joint_count) + "), got " + std::to_string(values.size()));
  }
  Eigen::VectorXd limits(static_cast<Eigen::Index>(joint_count));
  for (std::size_t j = 0; j < joint_count; ++j) limits[static_cast<Eigen::Index>(j)] = values[j];
  return limits;
}

std::vector<double> ThicknessGrid(std::string_view spec, std::string_view field) {
  const TypedSweepAxis axis = scene_file::ParseSweepAxis("covering-thickness=" + std::string(spec), field);
  std::vector<double> grid = axis.values;
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  if (grid.size() < 2) {
    throw std::invalid_argument(std::string(field) + ": a cycle-time sweep needs at least 2 thicknesses (got '" +
                                std::string(spec) + "')");
  }
  return grid;
}

std::vector<CycleTimeDesign> CycleTimeDesigns(const AssembledAudit& assembled, const materials::Catalog& catalog,
                                              std::span<const std::string> material_names, bool per_link_design,
                                              std::string_view materials_field) {
  std::vector<CycleTimeDesign> designs;
  for (const std::string& name : material_names) {
    optim::CandidateMaterial material;
    try {
      material = optim::SelectCandidates(catalog, std::vector<std::string>{name}).front();
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string(materials_field) + ": " + e.what());
    }
    AuditCovering covering{optim::CoveringOf(material, 0.0, CoveringLaw::kAuto), material};
    designs.push_back(CycleTimeDesign{.name = material.name, .covering = std::move(covering), .design = std::nullopt});
  }
  if (material_names.empty()) {
    const AuditCovering& all = assembled.setup.covering;
    const std::string name = all.material ? all.material->name
                                          : "covering E = " + FormatSignificant(all.covering.youngs_modulus_Pa / 1e6, 4) +
                                                " MPa, ν " + FormatSignificant(all.covering.poisson_ratio, 3);
    designs.push_back(CycleTimeDesign{.name = name, .covering = all, .design = std::nullopt});
  }
  if (per_link_design) {
    designs.push_back(CycleTimeDesign{
        .name = "per-link design", .covering = assembled.setup.covering, .design = assembled.options.design});
  }
  return designs;
}

}  // namespace covopt::audit
