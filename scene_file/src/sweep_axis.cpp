#include "covopt/scene_file/sweep_axis.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "covopt/core/quantity.hpp"
#include "covopt/core/sweep.hpp"
#include "covopt/internal/text.hpp"
#include "covopt/scene_file/range.hpp"

namespace covopt::scene_file {
namespace {

using internal::TrimBlanks;

constexpr std::size_t kDefaultCount = 50;
constexpr std::size_t kMaxAxisValues = covopt::kMaxSweepAxisValues;

std::string AxisNames() {
  std::string names;
  for (const SceneField& field : SceneFields()) {
    if (!names.empty()) names += ", ";
    names += field.name;
  }
  return names;
}

/// Reads a range item's ":lin|:log" and ":N" into `part`; returns the range's own text (before
/// the first ':'). `fail` throws the message naming the input and the spec.
std::string_view ReadRangeOptions(std::string_view item, SweepAxisPart& part,
                                  const std::function<void(const std::string&)>& fail) {
  std::size_t colon = item.find(':');
  const std::string_view range_text = TrimBlanks(item.substr(0, colon));
  bool count_given = false, spacing_given = false;
  while (colon != std::string_view::npos) {
    const std::size_t next = item.find(':', colon + 1);
    const std::string_view option = TrimBlanks(item.substr(
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
      fail(fmt::format("after the range, expected ':lin', ':log' or a count ':N', not ':{}'", option));
    }
    if (count_given) fail("give the count :N once per range");
    count_given = true;
    if (n < 2 || n > kMaxAxisValues) fail(fmt::format("the count after ':' must be in 2..{}", kMaxAxisValues));
    part.count = n;
  }
  return range_text;
}

/// The reader of one NAME=SPEC: its axis so far and how it fails.
class AxisReader {
 public:
  AxisReader(std::string_view text, std::string_view name) : text_(text), name_(name) {}

  [[noreturn]] void Fail(const std::string& problem) const {
    throw std::invalid_argument(fmt::format("{}: {} (got '{}')", name_, problem, text_));
  }

  /// A value's own message names the item; in a list, also say where it is.
  template <class Parse>
  auto InSpec(const Parse& parse) const {
    try {
      return parse();
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(fmt::format("{} in '{}'", e.what(), text_));
    }
  }

  /// A range LO..HI[:lin|:log][:N], appended to the values.
  void AddRange(std::string_view item, TypedSweepAxis& axis) const {
    SweepAxisPart part;
    part.range = true;
    part.count = kDefaultCount;
    const std::string_view range_text =
        ReadRangeOptions(item, part, [this](const std::string& problem) { Fail(problem); });
    const materials::Range range =
        InSpec([&] { return ParseQuantityRange(range_text, axis.field->spec, name_); });
    if (!range.min || !range.max) Fail("a sweep range needs both ends, LO..HI");
    const double lo = *range.min, hi = *range.max;
    if (!std::isfinite(lo) || !std::isfinite(hi)) {
      Fail("a range needs finite ends; list 'fixed' or 'flat' as a value instead, e.g. "
           "robot-mass=5kg..50kg:10,fixed");
    }
    if (!(lo < hi)) Fail("the range's low end must be below its high end");
    if (part.log && !(lo > 0.0)) Fail("a :log range needs a low end above 0");
    if (axis.values.size() + part.count > kMaxAxisValues) Fail(fmt::format("more than {} values", kMaxAxisValues));
    part.low = lo;
    part.high = hi;
    const std::size_t first = axis.values.size();
    for (std::size_t i = 0; i < part.count; ++i) {
      const double k = static_cast<double>(i), n = static_cast<double>(part.count - 1);
      axis.values.push_back(part.log ? std::pow(10.0, std::log10(lo) + (std::log10(hi) - std::log10(lo)) * k / n)
                                     : lo + (hi - lo) * k / n);
    }
    axis.values[first] = lo;
    axis.values.back() = hi;
    axis.parts.push_back(part);
  }

  /// A single value, appended.
  void AddValue(std::string_view item, TypedSweepAxis& axis) const {
    if (axis.values.size() + 1 > kMaxAxisValues) Fail(fmt::format("more than {} values", kMaxAxisValues));
    const double value = InSpec([&] { return ParseQuantity(item, axis.field->spec, name_); });
    axis.values.push_back(value);
    axis.parts.push_back(SweepAxisPart{value, value, 1, false, false});
  }

 private:
  std::string_view text_;
  std::string_view name_;
};

}  // namespace

TypedSweepAxis ParseSweepAxis(std::string_view text, std::string_view name) {
  const AxisReader reader(text, name);
  const std::size_t eq = text.find('=');
  if (eq == std::string_view::npos) {
    reader.Fail("expected NAME=LO..HI[:lin|:log][:N] or NAME=V1,V2,... (items may mix ranges and "
                "values), e.g. covering-thickness=0..50mm:101");
  }
  const std::string_view field_name = TrimBlanks(text.substr(0, eq));
  const std::string_view spec = TrimBlanks(text.substr(eq + 1));
  TypedSweepAxis axis;
  axis.field = FindSceneField(field_name);
  if (axis.field == nullptr) {
    reader.Fail(fmt::format("unknown quantity '{}'; the quantities are {}", field_name, AxisNames()));
  }
  axis.name = std::string(axis.field->name);
  axis.spec = std::string(spec);
  if (spec.empty()) reader.Fail(fmt::format("no values after '{}='", field_name));
  // A comma list whose items are ranges or single values; one range alone is the old form.
  std::string_view rest = spec;
  while (true) {
    const std::size_t comma = rest.find(',');
    const std::string_view item = TrimBlanks(rest.substr(0, comma));
    if (item.empty()) reader.Fail("empty value in the list");
    if (item.find("..") != std::string_view::npos) {
      reader.AddRange(item, axis);
    } else {
      reader.AddValue(item, axis);
    }
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  // A log axis when a range asked for it and every finite value can sit on it.
  const bool any_log = std::any_of(axis.parts.begin(), axis.parts.end(), [](const SweepAxisPart& p) { return p.log; });
  const bool all_positive = std::all_of(axis.values.begin(), axis.values.end(),
                                        [](double v) { return !std::isfinite(v) || v > 0.0; });
  axis.log = any_log && all_positive;
  return axis;
}

void CheckGridSize(const TypedSweepAxis& x, const TypedSweepAxis* y) {
  covopt::CheckSweepSize(x.values.size(), y ? std::optional(y->values.size()) : std::nullopt);
}

}  // namespace covopt::scene_file
