#pragma once
/// @file curve_chart.hpp
/// The chart of a catalog material's compressive curve (`covopt materials show NAME --plot`),
/// drawn by gnuplot like every chart of covopt (charts.hpp).

#include "covopt/materials/material.hpp"
#include "covopt/chart/charts.hpp"

namespace covopt::chart {

/// `materials show --plot`: the curve's stress σ [kPa] over strain [%] (its points marked,
/// piecewise linear from the origin), W(ε) = ∫σ dε [kJ/m³] on the right axis, the rigid stop
/// at the last point, σ(25 %) marked, and a grade band's range at 25 % where the entry has one.
/// 1000 x 650.
/// @throws std::invalid_argument when the material has no compressive curve.
GnuplotChart CompressiveCurveChart(const materials::Material& material);

}  // namespace covopt::chart
