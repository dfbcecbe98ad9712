#pragma once
/// @file sweep_axis_text.hpp
/// One swept quantity as a user typed it, NAME=SPEC (`covopt sweep --x/--y`, the value lists of
/// `speed-limit --robot-mass` and `--speed`): its scene field, its name, its items and the values
/// they expand to. The reader is covopt::scene_file::ParseSweepAxis
/// (covopt/scene_file/sweep_axis.hpp); the sweep's CSV and charts lay it out (covopt/report/).

#include <cstddef>
#include <string>
#include <vector>

#include "covopt/core/scene_fields.hpp"

namespace covopt {

/// One item of an axis spec: a range LO..HI of `count` values, or a single value.
struct SweepAxisPart {
  double low = 0.0;        ///< SI; the value itself for a single value
  double high = 0.0;       ///< SI; equals `low` for a single value
  std::size_t count = 1;   ///< values the item gives (1 for a single value)
  bool log = false;        ///< a :log range
  bool range = false;      ///< LO..HI rather than a single value
};

/// One swept quantity, as typed.
struct TypedSweepAxis {
  const SceneField* field = nullptr;  ///< the scene field it sets
  std::string name;                   ///< the field's name: "covering-modulus"
  /// SI, in the order typed (each range expanded in place); kFixed/kFlat where listed as
  /// 'fixed'/'flat'. Charts draw them sorted; the CSV keeps this order.
  std::vector<double> values;
  /// Drawn on a log axis: some range is :log and every finite value is above 0.
  bool log = false;
  std::vector<SweepAxisPart> parts;  ///< the items of the spec, in order
  std::string spec;                  ///< as typed after '='
};

}  // namespace covopt
