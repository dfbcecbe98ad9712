#pragma once
/// @file speed_limit_text.hpp
/// The readable speed-limit table (`covopt speed-limit`'s text; speed_limit_json.hpp is its
/// JSON and CSV): the limit per row, what limits it and the ratios there; and the limit over
/// a box of uncertain inputs, with where it is set.

#include <ostream>
#include <span>
#include <string>

#include <covopt/optim/robust_search.hpp>
#include <covopt/optim/speed_limit_table.hpp>
#include <covopt/report/body_contact_json.hpp>

namespace covopt::report {

/// The table: per row its mass (or speed), the max safe speed (or mass), the limiting
/// criterion and the laceration, contusion and compression ratios at the limit; with a
/// material column when `several_materials`.
void PrintSpeedLimitRows(std::ostream& out, optim::SpeedLimitQuantity quantity, bool several_materials,
                         std::span<const optim::SpeedLimitRow> rows);

/// One row over a box: "robot 10 kg: max safe speed 1.2 m/s for every value in the box
/// (found), limited by contusion" and "  set at: head-mass 5.8 kg (found by corner, 12
/// evaluations)", each line ending in a newline.
std::string RobustSpeedLimitRowText(const optim::UncertaintyBox& box, optim::SpeedLimitQuantity quantity,
                                    const optim::RobustSpeedLimitRow& row);

/// The body-region table's rows (speed-limit --body-region): a block per material and robot
/// mass, each row a region and area with its force and pressure limits, the bare and covered
/// max safe speeds, what binds and the covering's gain.
void PrintBodyRegionSpeedLimitRows(std::ostream& out, std::span<const BodyRegionTableRow> rows);

}  // namespace covopt::report
