#include "sweep_axis_option.hpp"

#include <algorithm>
#include <charconv>
#include <functional>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "catalog_options.hpp"
#include "covopt/core/sweep.hpp"
#include "errors.hpp"

namespace covopt::cli {
namespace {

constexpr std::size_t kDefaultCount = 50;
constexpr std::size_t kMaxAxisValues = covopt::kMaxSweepAxisValues;

std::string_view Trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

/// The flag without its dashes: "--robot-mass" -> "robot-mass".
std::string_view AxisName(const SceneField& field) {
  std::string_view flag = field.flag;
  while (!flag.empty() && flag.front() == '-') flag.remove_prefix(1);
  return flag;
}

std::string AxisNames() {
  std::string names;
  for (const SceneField& field : SceneFields()) {
    if (!names.empty()) names += ", ";
    names += AxisName(field);
  }
  return names;
}

const SceneField* FindField(std::string_view name) {
  for (const SceneField& field : SceneFields()) {
    if (AxisName(field) == name || field.dotted_name() == name) return &field;
  }
  return nullptr;
}

/// Reads a range item's ":lin|:log" and ":N" into `part`; returns the range's own text (before
/// the first ':'). `fail` throws the message naming the flag and the spec.
std::string_view ReadRangeOptions(std::string_view item, SweepAxisPart& part,
                                  const std::function<void(const std::string&)>& fail) {
  std::size_t colon = item.find(':');
  const std::string_view range_text = Trim(item.substr(0, colon));
  bool count_given = false, spacing_given = false;
  while (colon != std::string_view::npos) {
    const std::size_t next = item.find(':', colon + 1);
    const std::string_view option = Trim(item.substr(
        colon + 1, next == std::string_view::npos ? std::string_view::npos : next - colon - 1));
    colon = next;
    if (option == "lin" || option == "log") {
      if (spacing_given) fail("give the spacing (lin or log) once per range");
      spacing_given = true;
      part.log = option == "log";
      continue;
    }
    std::size_t n = 0;
    const auto [end, ec] = std::from_chars(option.data(), option.data() + option.size(), n);
    if (ec != std::errc() || end != option.data() + option.size() || option.empty()) {
      fail(fmt::format("after the range, expected ':lin', ':log' or a count ':N', not ':{}'",
                       option));
    }
    if (count_given) fail("give the count :N once per range");
    count_given = true;
    if (n < 2 || n > kMaxAxisValues) {
      fail(fmt::format("the count after ':' must be in 2..{}", kMaxAxisValues));
    }
    part.count = n;
  }
  return range_text;
}

}  // namespace

SweepAxisArgument ParseSweepAxis(std::string_view text, std::string_view flag) {
  const auto fail = [&](const std::string& problem) -> void {
    throw InputError(fmt::format("{}: {} (got '{}')", flag, problem, text));
  };
  const std::size_t eq = text.find('=');
  if (eq == std::string_view::npos) {
    fail("expected NAME=LO..HI[:lin|:log][:N] or NAME=V1,V2,... (items may mix ranges and "
         "values), e.g. covering-thickness=0..50mm:101");
  }
  const std::string_view name = Trim(text.substr(0, eq));
  const std::string_view spec = Trim(text.substr(eq + 1));
  SweepAxisArgument axis;
  const SceneField* field = FindField(name);
  if (field == nullptr) {
    fail(fmt::format("unknown quantity '{}'; the quantities are {}", name, AxisNames()));
  }
  axis.field = field;
  axis.name = std::string(AxisName(*field));
  axis.spec = std::string(spec);
  const QuantitySpec& quantity = axis.field->spec;
  if (spec.empty()) fail(fmt::format("no values after '{}='", name));

  // A value's own message names the item; in a list, also say where it is.
  const auto in_spec = [&](const auto& parse) {
    try {
      return parse();
    } catch (const std::invalid_argument& e) {
      throw InputError(fmt::format("{} in '{}'", e.what(), text));
    }
  };

  // A range LO..HI[:lin|:log][:N], appended to the values.
  const auto add_range = [&](std::string_view item) {
    SweepAxisPart part;
    part.range = true;
    part.count = kDefaultCount;
    const std::string_view range_text = ReadRangeOptions(item, part, fail);
    const materials::Range range = in_spec([&] { return ParseRange(range_text, quantity, flag); });
    if (!range.min || !range.max) fail("a sweep range needs both ends, LO..HI");
    const double lo = *range.min, hi = *range.max;
    if (!std::isfinite(lo) || !std::isfinite(hi)) {
      fail("a range needs finite ends; list 'fixed' or 'flat' as a value instead, e.g. "
           "robot-mass=5kg..50kg:10,fixed");
    }
    if (!(lo < hi)) fail("the range's low end must be below its high end");
    if (part.log && !(lo > 0.0)) fail("a :log range needs a low end above 0");
    if (axis.values.size() + part.count > kMaxAxisValues) {
      fail(fmt::format("more than {} values", kMaxAxisValues));
    }
    part.low = lo;
    part.high = hi;
    const std::size_t first = axis.values.size();
    for (std::size_t i = 0; i < part.count; ++i) {
      const double k = static_cast<double>(i), n = static_cast<double>(part.count - 1);
      axis.values.push_back(
          part.log ? std::pow(10.0, std::log10(lo) + (std::log10(hi) - std::log10(lo)) * k / n)
                   : lo + (hi - lo) * k / n);
    }
    axis.values[first] = lo;
    axis.values.back() = hi;
    axis.parts.push_back(part);
  };

  // A comma list whose items are ranges or single values; one range alone is the old form.
  std::string_view rest = spec;
  while (true) {
    const std::size_t comma = rest.find(',');
    const std::string_view item = Trim(rest.substr(0, comma));
    if (item.empty()) fail("empty value in the list");
    if (item.find("..") != std::string_view::npos) {
      add_range(item);
    } else {
      if (axis.values.size() + 1 > kMaxAxisValues) {
        fail(fmt::format("more than {} values", kMaxAxisValues));
      }
      const double value = in_spec([&] { return ParseQuantity(item, quantity, flag); });
      axis.values.push_back(value);
      axis.parts.push_back(SweepAxisPart{value, value, 1, false, false});
    }
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  // A log axis when a range asked for it and every finite value can sit on it.
  const bool any_log = std::any_of(axis.parts.begin(), axis.parts.end(),
                                   [](const SweepAxisPart& p) { return p.log; });
  const bool all_positive = std::all_of(axis.values.begin(), axis.values.end(),
                                        [](double v) { return !std::isfinite(v) || v > 0.0; });
  axis.log = any_log && all_positive;
  return axis;
}

void CheckGridSize(const SweepAxisArgument& x, const SweepAxisArgument* y) {
  try {
    covopt::CheckSweepSize(x.values.size(), y ? std::optional(y->values.size()) : std::nullopt);
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
}

}  // namespace covopt::cli
