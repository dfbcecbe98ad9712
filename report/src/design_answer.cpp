// The default answer's text and JSON (optim/design_answer.hpp): the range checked, the
// candidates it changed, and the nearest changes.
#include <algorithm>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/report/design_answer_text.hpp"
#include "design_answer_json.hpp"
#include "verdict_object.hpp"

namespace covopt::report {
namespace {

using nlohmann::ordered_json;

std::string Mm(double metres) { return fmt::format("{:.2f} mm", metres * 1e3); }

std::string ChangeText(const optim::NearestChange& c, std::string_view unit_value) {
  return c.reachable ? fmt::format("{} ({})", unit_value, c.note) : c.note;
}

ordered_json ChangeJson(const optim::NearestChange& c) {
  return {{"reachable", c.reachable}, {"value", c.reachable ? ordered_json(c.value) : ordered_json(nullptr)},
          {"note", c.note}};
}

ordered_json RangeJson(const optim::CurveScaleRange& r) {
  auto bounds = [](const std::optional<materials::Bounds>& b) {
    return b ? ordered_json::array({b->low, b->high}) : ordered_json(nullptr);
  };
  return {{"stated", r.stated},
          {"scale_low", r.low},
          {"scale_high", r.high},
          {"stress_at_25_band_Pa", bounds(r.stress_at_25_band_Pa)},
          {"stress_at_25_Pa", r.stress_at_25_band_Pa ? ordered_json(r.stress_at_25_Pa) : ordered_json(nullptr)},
          {"rate_factor", bounds(r.rate_factor)},
          {"description", r.Describe()}};
}

}  // namespace

void PrintDesignAnswer(std::ostream& out, const optim::DesignResult& result, int rows) {
  if (result.material_range) {
    const optim::MaterialRangeCheck& c = *result.material_range;
    fmt::print(out, "  {} {} at {}: worst margin {} ({} at curve scale {:.3g}){}\n",
               c.range.stated ? "robust over" : "checked with", c.range.Describe(), Mm(c.thickness_m),
               FormatPercent(c.worst_margin()), c.worst().governing_name(), c.worst_scale(),
               c.scales.size() > 2 ? fmt::format(", {} scales judged", c.scales.size()) : std::string());
  }
  const std::size_t shown = std::min({result.range_notes.size(), result.candidates.size(),
                                      static_cast<std::size_t>(std::max(rows, 0))});
  for (std::size_t i = 0; i < shown; ++i) {
    if (!result.range_notes[i].empty()) {
      fmt::print(out, "  over its range, {}: {}\n", result.candidates[i].material.name, result.range_notes[i]);
    }
  }
  if (!result.nearest_changes) return;
  const optim::NearestChanges& n = *result.nearest_changes;
  fmt::print(out, "\nNearest changes (for {}, the material nearest to admissible: worst ratio {:.3f} at {} over {}; "
                  "each found by bisection on the same verdict)\n",
             n.material, n.worst_ratio_at_thickness, Mm(n.at_thickness_m), n.range.Describe());
  fmt::print(out, "  slower     {}\n", ChangeText(n.speed, fmt::format("at most {:.4g} m/s", n.speed.value)));
  fmt::print(out, "  thicker    {}\n", ChangeText(n.thickness, Mm(n.thickness.value)));
  fmt::print(out, "  larger     {}\n", ChangeText(n.radius, "robot radius " + Mm(n.radius.value)));
}

namespace internal {

void AddDesignAnswerJson(ordered_json& j, const optim::DesignResult& result) {
  if (result.material_range) {
    const optim::MaterialRangeCheck& c = *result.material_range;
    ordered_json verdicts = ordered_json::array();
    for (std::size_t i = 0; i < c.scales.size(); ++i) {
      verdicts.push_back({{"scale", c.scales[i]}, {"verdict", VerdictObject(c.verdicts[i])}});
    }
    j["material_range"] = {{"thickness_m", c.thickness_m},     {"range", RangeJson(c.range)},
                           {"admissible", c.admissible()},     {"worst_scale", c.worst_scale()},
                           {"worst_margin", c.worst_margin()}, {"worst_criterion", c.worst().governing_name()},
                           {"verdicts", verdicts}};
  } else {
    j["material_range"] = nullptr;
  }
  if (result.nearest_changes) {
    const optim::NearestChanges& n = *result.nearest_changes;
    j["nearest_changes"] = {{"material", n.material},
                            {"at_thickness_m", n.at_thickness_m},
                            {"worst_ratio_at_thickness", n.worst_ratio_at_thickness},
                            {"range", RangeJson(n.range)},
                            {"speed_m_per_s", ChangeJson(n.speed)},
                            {"thickness_m", ChangeJson(n.thickness)},
                            {"robot_radius_m", ChangeJson(n.radius)},
                            {"summary", n.Describe()}};
  } else {
    j["nearest_changes"] = nullptr;
  }
  ordered_json& candidates = j["candidates"];
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    candidates[i]["range_note"] = i < result.range_notes.size() ? result.range_notes[i] : std::string();
  }
}

}  // namespace internal
}  // namespace covopt::report
