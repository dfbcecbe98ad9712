#include "sweep_axis_option.hpp"

#include "covopt/scene_file/sweep_axis.hpp"
#include "errors.hpp"

namespace covopt::cli {

SweepAxisArgument ParseSweepAxis(std::string_view text, std::string_view flag) {
  return AsInputError([&] { return scene_file::ParseSweepAxis(text, flag); });
}

void CheckGridSize(const SweepAxisArgument& x, const SweepAxisArgument* y) {
  AsInputError([&] { scene_file::CheckGridSize(x, y); });
}

}  // namespace covopt::cli
