#pragma once
/// @file work_precision_text.hpp
/// The readable tables of the work-precision studies (`covopt workprecision`'s text;
/// work_precision_report.hpp holds their JSON, CSV and charts).

#include <ostream>

#include <covopt/core/scene.hpp>
#include <covopt/core/work_precision.hpp>
#include <covopt/optim/design_work_precision.hpp>

namespace covopt::report {

/// The study of the impact oracles on `scene`: one row per method and tolerance, the cheapest
/// run reaching each target error, and the series not keeping their tolerance.
void PrintWorkPrecision(std::ostream& out, const WorkPrecisionResult& study, const Scene& scene);

/// The optimiser-level study (--design): the continuous optimum found on each oracle.
void PrintDesignWorkPrecision(std::ostream& out, const optim::DesignWorkPrecisionResult& study, const Scene& scene);

}  // namespace covopt::report
