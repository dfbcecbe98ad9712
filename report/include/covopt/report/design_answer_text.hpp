#pragma once
/// @file design_answer_text.hpp
/// The default answer's part of `covopt optimize`'s report (optim/design_answer.hpp): the
/// range the recommendation was checked over and its worst margin, the candidates its stated
/// uncertainty changed, and the nearest changes when no material works.

#include <ostream>

#include "covopt/optim/design.hpp"

namespace covopt::report {

/// Prints the range line (the range checked, at which thickness, the worst margin and where), a
/// line per candidate among the first `rows` whose range changed it, and the "Nearest changes"
/// block. Nothing when the result carries none of them.
void PrintDesignAnswer(std::ostream& out, const optim::DesignResult& result, int rows);

}  // namespace covopt::report
