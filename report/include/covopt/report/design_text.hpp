#pragma once
/// @file design_text.hpp
/// The readable report of a covering design (`covopt optimize`'s text; design_json.hpp is its
/// JSON): the deterministic design (optim::Design), the robust one over a box of uncertain
/// inputs and the one meeting a probability target, each with its candidate table, solver
/// lines, scope and warnings.

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <covopt/optim/design.hpp>
#include <covopt/optim/robust_design.hpp>

namespace covopt::report {

/// One scene input given as a range, as the user wrote it.
struct InputRange {
  std::string name;    ///< the field's name, "head-mass"
  std::string text;    ///< as written, "3.7kg..5.8kg"
  std::string source;  ///< where: "--head-mass" or "scene.toml:4:8: head.mass"
};

/// What the design's text reads beside the result: the request (its scene, limits, safety
/// factor, space, step, fixed thickness), the ranges, the input's warnings and the rows of
/// the candidate table.
struct DesignText {
  const optim::DesignRequest& request;
  std::vector<InputRange> ranges;
  const std::vector<std::string>& warnings;
  int runners_up = 8;
};

/// The report of a deterministic design: scene, limits, criterion, message, recommendation,
/// bare robot, continuous optimum, candidates, solver, oracle, scope and warnings.
void PrintDesign(std::ostream& out, const DesignText& r, const optim::DesignResult& result);

/// The report of FindRobustThinnestCovering, with the recommendation's probability when sampled.
void PrintRobustDesign(std::ostream& out, const DesignText& r, const optim::UncertaintyBox& box,
                       const optim::RobustDesignOptions& options, const optim::RobustThinnestCovering& result,
                       const std::optional<optim::InjuryProbability>& probability);

/// The report of FindProbabilityDesign (optimize --max-injury-probability).
void PrintProbabilityDesign(std::ostream& out, const DesignText& r, const optim::UncertaintyBox& box,
                            const optim::ProbabilityDesignOptions& options, const optim::ProbabilityDesign& result);

}  // namespace covopt::report
