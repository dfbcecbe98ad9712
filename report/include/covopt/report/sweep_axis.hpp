#pragma once
/// @file sweep_axis.hpp
/// One swept quantity of `covopt sweep` as the CSV and the charts lay it out
/// (sweep_csv.hpp, sweep_charts.hpp): its scene field, its name and its values as typed.

#include <cstddef>
#include <string>
#include <vector>

#include "covopt/core/scene_fields.hpp"

namespace covopt::report {

/// One item of an axis spec: a range LO..HI of `count` values, or a single value.
struct SweepAxisPart {
  double low = 0.0;        ///< SI; the value itself for a single value
  double high = 0.0;       ///< SI; equals `low` for a single value
  std::size_t count = 1;   ///< values the item gives (1 for a single value)
  bool log = false;        ///< a :log range
  bool range = false;      ///< LO..HI rather than a single value
};

/// One swept quantity.
struct SweepAxisArgument {
  const covopt::SceneField* field = nullptr;  ///< the scene field it sets
  std::string name;                   ///< the flag without dashes: "covering-modulus"
  /// SI, in the order typed (each range expanded in place); kFixed/kFlat where listed as
  /// 'fixed'/'flat'. Charts draw them sorted; the CSV keeps this order.
  std::vector<double> values;
  /// Drawn on a log axis: some range is :log and every finite value is above 0.
  bool log = false;
  std::vector<SweepAxisPart> parts;  ///< the items of the spec, in order
  std::string spec;                  ///< as typed after '='
};

/// An axis with at most this many values is drawn as a family of lines.
inline constexpr std::size_t kMaxFamilies = 8;
}  // namespace covopt::report
