// The report's inputs as tables a reader knows (html_sections.hpp): every input leaf of the
// result's JSON, grouped robot | covering | human | criteria | solver | other, with its quantity,
// its value in the unit the command line uses, the unit, and where it came from (the JSON's
// "input_sources": a flag, a scene file, the catalog, a default). The SI value stays in the
// cell's data-key/data-value, exactly as --json printed it.
#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <vector>

#include "html_sections.hpp"

namespace covopt::report::internal::html {

namespace {

/// The top-level keys of each kind's result that hold its inputs.
std::vector<std::string_view> InputKeys(ReportKind kind) {
  switch (kind) {
    case ReportKind::kSimulate: return {"scene", "robot_model", "uncertain_inputs", "safety_factor", "limits"};
    case ReportKind::kOptimize:
      return {"scene", "robot_model", "speed_m_per_s", "thickness_m", "safety_factor", "limits", "design_space",
              "uncertain_inputs", "max_probability", "samples", "seed"};
    case ReportKind::kSpeedLimit:
      return {"solve_for", "scene", "robot_model", "safety_factor", "limits", "search_limit", "uncertain_inputs"};
    case ReportKind::kTrajectory:
      return {"scene", "safety_factor", "limits", "search_limit", "regions", "joint_names", "sample_count"};
    case ReportKind::kRetime:
      return {"robot", "coverings", "contact_area_m2", "reaction_delay_s", "braking_m_per_s2", "safety_factor",
              "sample_count", "surface", "regions", "joint_names", "joint_speed_limits_rad_per_s", "joint_acceleration_limits_rad_per_s2",
              "max_speed_scale", "tolerance"};
    case ReportKind::kAudit:
      return {"robot", "coverings", "contact_area_m2", "reaction_delay_s", "braking_m_per_s2", "safety_factor",
              "sample_count", "surface", "regions"};
    case ReportKind::kMeasure: return {"scene", "safety_factor", "device"};
  }
  return {};
}

/// A leaf of the inputs: its dotted path, its quantity in words, its value and unit.
struct Leaf {
  std::string path;
  std::string quantity;
  const Json* value;
  Unit unit;
};

/// The name an array element goes by: its "name", "link", "field" or "region", else its number.
std::string ElementName(const Json& element, std::size_t index) {
  for (const char* key : {"name", "link", "field", "region"}) {
    if (const Json* v = Find(element, key); v && v->is_string()) return v->get<std::string>();
  }
  return "#" + std::to_string(index + 1);
}

std::string Words(std::string_view key) {
  std::string text(WithoutUnit(key));
  std::replace(text.begin(), text.end(), '_', ' ');
  return text;
}

void Flatten(const Json& value, const std::string& path, const std::string& quantity, const Unit& inherited,
             std::vector<Leaf>& out) {
  const auto join = [&](const std::string& word) { return quantity.empty() ? word : quantity + " " + word; };
  if (value.is_object() && !value.empty()) {
    const Json* unit_name = Find(value, "unit");
    for (const auto& [key, child] : value.items()) {
      Unit unit = UnitOfKey(key);
      if (unit.si.empty() && unit_name && unit_name->is_string() &&
          (key == "low" || key == "high" || key == "mean" || key == "standard_deviation")) {
        unit = UnitOfName(unit_name->get<std::string>());
      }
      if (unit.si.empty() && (child.is_array() || child.is_object())) unit = inherited;
      Flatten(child, path + "." + key, key == "scene" ? quantity : join(Words(key)), unit, out);
    }
  } else if (value.is_array() && !value.empty()) {
    for (std::size_t i = 0; i < value.size(); ++i) {
      Flatten(value[i], path + "." + std::to_string(i), join(ElementName(value[i], i)), inherited, out);
    }
  } else {
    out.push_back({path, quantity, &value, inherited});
  }
}

constexpr std::array<std::string_view, 6> kGroups = {"robot", "covering", "human", "criteria", "solver", "other"};
constexpr std::array<std::string_view, 6> kGroupTitles = {"Robot", "Covering", "Human (target)", "Criteria",
                                                          "Solver and model settings", "Other"};

/// The group of a leaf, by the words of its path and quantity.
std::size_t GroupOf(const Leaf& leaf) {
  std::string text = leaf.path + " " + leaf.quantity;
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  const auto any = [&](std::initializer_list<std::string_view> words) {
    return std::any_of(words.begin(), words.end(), [&](std::string_view w) { return text.find(w) != std::string::npos; });
  };
  if (any({"limits", "limit_", "safety_factor", "max_probability", "criterion"})) return 3;
  if (any({"solve_for", "search_limit", "samples", "seed", "solver", "model.", "tolerance"})) return 4;
  if (any({"covering", "design_space", "material", "thickness_m"}) && !any({"scalp"})) return 1;
  if (any({"head", "scalp", "skull", "neck", "torso", "region", "body", "contact_area", "human"})) return 2;
  if (any({"robot", "joint", "speed", "payload", "surface", "sample_count", "reaction_delay", "braking", "tool"})) {
    return 0;
  }
  return 5;
}

void WriteLeaf(std::string& out, const Leaf& leaf, const Json* sources) {
  const Json& v = *leaf.value;
  const std::string text = ScalarText(v);
  out += "<tr>";
  Cell(out, leaf.quantity.empty() ? leaf.path : leaf.quantity);
  out += "<td class=\"num\" data-key=\"";
  Escape(out, leaf.path);
  out += "\" data-value=\"";
  Escape(out, text);
  out += "\">";
  if (v.is_number()) Escape(out, Significant(v.get<double>() * (leaf.unit.display.empty() ? 1.0 : leaf.unit.factor)));
  else Escape(out, v.is_null() ? "none" : v.is_primitive() ? text : v.dump());
  out += "</td>";
  std::string unit = "-";
  if (v.is_string()) unit = "text";
  else if (v.is_number() && !leaf.unit.display.empty()) unit = leaf.unit.display;
  else if (v.is_number() && !leaf.unit.si.empty()) unit = leaf.unit.si;
  Cell(out, unit, "unit");
  const Json* source = sources ? Find(*sources, leaf.path) : nullptr;
  Cell(out, source && source->is_string() ? source->get<std::string>() : "—", "source");
  out += "</tr>\n";
}

}  // namespace

void WriteInputs(std::string& out, const Json& j, ReportKind kind) {
  std::vector<Leaf> leaves;
  for (const std::string_view key : InputKeys(kind)) {
    if (const Json* v = Find(j, key)) Flatten(*v, std::string(key), key == "scene" ? "" : Words(key), UnitOfKey(key), leaves);
  }
  const Json* sources = Find(j, "input_sources");
  // An input the result records a source for is an input, wherever its value sits (simulate's
  // safety factor and limits live in its verdict objects: laceration.limit_Pa).
  if (sources && sources->is_object()) {
    for (const auto& [path, source] : sources->items()) {
      const bool listed = std::any_of(leaves.begin(), leaves.end(), [&](const Leaf& l) { return l.path == path; });
      const std::size_t dot = path.rfind('.');
      const std::string key = dot == std::string::npos ? path : path.substr(dot + 1);
      const Json* value = &j;
      for (std::size_t from = 0; value && from <= path.size();) {
        const std::size_t to = std::min(path.find('.', from), path.size());
        value = Find(*value, path.substr(from, to - from));
        from = to + 1;
      }
      if (!listed && value && !value->is_structured()) {
        std::string quantity = path.substr(0, dot == std::string::npos ? 0 : dot) + " " + Words(key);
        std::replace(quantity.begin(), quantity.end(), '.', ' ');
        leaves.push_back({path, quantity, value, UnitOfKey(key)});
      }
    }
  }
  out += "<p>Values in the units the command line uses; each cell keeps the SI value of the JSON. Source: where the "
         "value came from (a flag, a scene file, the catalog, a default); — where the result does not say. A mass "
         "or radius of \"fixed\" or \"flat\" is infinite.</p>\n";
  if (leaves.empty()) out += "<p>The result records no inputs.</p>\n";
  out += "<div class=\"input-groups\">\n";
  for (std::size_t g = 0; g < kGroups.size(); ++g) {
    std::vector<const Leaf*> rows;
    for (const Leaf& leaf : leaves) {
      if (GroupOf(leaf) == g) rows.push_back(&leaf);
    }
    if (rows.empty()) continue;
    out += "<div><h3>";
    Escape(out, kGroupTitles[g]);
    out += "</h3>\n";
    OpenTable(out, {{"quantity", 40}, {"value", 18}, {"unit", 12}, {"source", 30}},
              "inputs\" data-group=\"" + std::string(kGroups[g]));
    for (const Leaf* leaf : rows) WriteLeaf(out, *leaf, sources);
    out += "</tbody></table></div>\n";
  }
  out += "</div>\n";
}

}  // namespace covopt::report::internal::html
