#pragma once
/// @file optimize_resolve.hpp
/// `covopt optimize`'s flags read into the library's request (part of the optimize command;
/// optimize.cpp prints what the library answers).

#include <string>
#include <vector>

#include "covopt/optim/design.hpp"
#include "covopt/scene_file/range.hpp"
#include "optimize.hpp"
#include "report_option.hpp"

namespace covopt::cli {

/// What optimize's flags resolve to.
struct Resolved {
  optim::DesignRequest request;
  /// Scene inputs given as ranges LO..HI: the robust design (docs/model.md §11).
  std::vector<SceneRange> ranges;
  std::vector<std::string> warnings;  ///< about the input (the library adds its own)
  ResultInputs inputs;                ///< what the inputs add to the report: the scene file's [report]
  int runners_up = 8;
};

/// Reads the scene (file, flags, ranges, --urdf), the design flags (criterion, space, limits,
/// safety factor, ν, step, --thickness), the solver's and the candidates (the catalog, --family,
/// --material), each checked with the flag's name.
/// @throws InputError naming the flag, the value and what is allowed.
Resolved ResolveOptimize(const OptimizeOptions& o);

}  // namespace covopt::cli
