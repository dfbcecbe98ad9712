#pragma once
/// @file simulation_text.hpp
/// The readable report of one simulated contact (`covopt simulate`'s text; simulation_json.hpp
/// is its JSON): scene, peaks, verdicts, method and solver, scope, warnings.

#include <ostream>

#include <covopt/report/simulation_json.hpp>

namespace covopt::report {

/// The readable report: scene, peaks, verdicts, method and solver, scope, warnings.
void PrintTable(std::ostream& out, const SimulationReport& report);

}  // namespace covopt::report
