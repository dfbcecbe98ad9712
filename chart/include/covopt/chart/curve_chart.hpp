#pragma once
/// @file curve_chart.hpp
/// The chart of a catalog material's compressive curve (`covopt materials show NAME --plot`),
/// drawn by gnuplot like every chart of covopt (charts.hpp).

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "covopt/core/body_contact.hpp"
#include "covopt/core/compressive_curve.hpp"
#include "covopt/materials/material.hpp"
#include "covopt/optim/body_region_check.hpp"
#include "covopt/report/simulation_json.hpp"
#include "covopt/chart/charts.hpp"

namespace covopt::chart {

/// `materials show --plot`: the curve's stress σ [kPa] over strain [%] (its points marked,
/// piecewise linear from the origin), W(ε) = ∫σ dε [kJ/m³] on the right axis, the rigid stop
/// at the last point, σ(25 %) marked, and a grade band's range at 25 % where the entry has one.
/// 1000 x 650.
/// @throws std::invalid_argument when the material has no compressive curve.
GnuplotChart CompressiveCurveChart(const materials::Material& material);

/// A result's working point on its foam covering's curve: the covering's nominal strain at the
/// peak [-] (its stress is the curve's there).
struct WorkingPoint {
  std::string label;  ///< "chest (sternum)"; "" for a result of one contact
  double strain = 0.0;
};

/// A foam covering's compressive curve, nominal stress σ [kPa] over nominal strain [%], with the
/// result's working points marked (ε at the peak and σ(ε)), the rigid stop past the last point
/// dashed; `covering` names the covering in the title. 1000 x 600.
/// @throws std::invalid_argument without points.
GnuplotChart FoamWorkingPointChart(const CompressiveCurve& curve, const std::string& covering,
                                   std::span<const WorkingPoint> points);

/// The working-point chart of a head simulation whose covering is a foam (the foam law judged
/// it: ImpactModel::is_foam); empty otherwise.
std::optional<GnuplotChart> FoamWorkingPointChartOf(const report::SimulationReport& report);

/// The working-point chart of body contacts (one per judged region, in order) whose covering is
/// a foam (BodyContactModel::foam); empty otherwise, or without judgements.
std::optional<GnuplotChart> FoamWorkingPointChartOf(const BodyContactScene& scene,
                                                    std::span<const optim::BodyRegionJudgement> judged,
                                                    const std::optional<std::string>& material);

}  // namespace covopt::chart
