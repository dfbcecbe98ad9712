#pragma once
/// @file robust_text.hpp
/// The readable text of the robust results (docs/model.md §11): worst cases over a box of
/// uncertain inputs, sampled injury probabilities, a braking robot's time-path use and the
/// elasticity table. The JSON of the same results is robust_json.hpp's.

#include <ostream>
#include <span>
#include <string>
#include <string_view>

#include <covopt/optim/robust_design.hpp>

namespace covopt::report {

/// "head-mass 5.8 kg, scalp-thickness 5 mm": input values [SI] for people.
std::string DescribeValues(const optim::UncertaintyBox& box, std::span<const double> values);

/// The worst case as text: "worst case: head-mass 5.8 kg, scalp-thickness 2 mm (found by
/// corner; 1 234 evaluations, 3.1 ms)" and a line with the ratios and what binds.
void PrintWorstCase(std::ostream& out, const optim::UncertaintyBox& box, const optim::WorstCase& worst,
                    std::string_view indent = "");

/// The probability table: laceration, contusion, either, fully compressed, inadmissible, each
/// with its count and Wilson 95 % interval.
void PrintInjuryProbability(std::ostream& out, const optim::InjuryProbability& probability,
                            std::string_view indent = "");

/// For a box with a braking robot (optim::UncertaintyBox::brakes()): how its impacts were
/// judged ("Braking robot: 1 234 time-path runs; 5 678 impacts screened by the unbraked exact
/// path's bound, 90 with the brake after the peak"), and a warning for failed runs. Nothing
/// otherwise.
void PrintTimePathUse(std::ostream& out, const optim::UncertaintyBox& box, const optim::TimePathUse& use,
                      std::string_view indent = "");

/// The elasticity table (tornado order).
void PrintElasticities(std::ostream& out, const optim::ElasticityTable& table);

}  // namespace covopt::report
