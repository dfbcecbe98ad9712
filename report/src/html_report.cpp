// The report for the risk-assessment file (html_report.hpp): one self-contained HTML5 document
// rendered from a command's --json object and its charts' SVG.
#include "covopt/report/html_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include <covopt/materials/body_regions.hpp>
#include <covopt/materials/catalog.hpp>

#include "html_svg.hpp"

namespace covopt::report {

std::string_view ToString(ReportKind kind) noexcept {
  switch (kind) {
    case ReportKind::kSimulate: return "simulate";
    case ReportKind::kOptimize: return "optimize";
    case ReportKind::kSpeedLimit: return "speed-limit";
    case ReportKind::kTrajectory: return "robot --trajectory";
    case ReportKind::kAudit: return "audit";
  }
  return "unknown";
}

namespace {

using Json = nlohmann::ordered_json;

// ---------------------------------------------------------------------------------------------
// Text

/// Appends `text` HTML-escaped (safe in element content and in quoted attribute values).
void Escape(std::string& out, std::string_view text) {
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
}

/// The JSON text of a scalar as the JSON holds it: a string's own characters, a number's
/// shortest round-trip text (nlohmann's, as --json prints it), true/false/null.
std::string ScalarText(const Json& value) {
  if (value.is_string()) return value.get<std::string>();
  return value.dump();
}

/// `value` with about `significant` digits, for reading (the exact JSON text is kept beside it):
/// plain decimals from 1e-3 to 1e7 (trailing zeros dropped), an exponent beyond.
std::string Significant(double value, int significant = 4) {
  if (!std::isfinite(value)) return value > 0 ? "∞" : (value < 0 ? "−∞" : "NaN");
  char buffer[64];
  const double magnitude = std::fabs(value);
  if (value == 0.0 || (magnitude >= 1e-3 && magnitude < 1e7)) {
    const int exponent = value == 0.0 ? 0 : static_cast<int>(std::floor(std::log10(magnitude)));
    const int decimals = std::max(0, significant - 1 - exponent);
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    std::string text = buffer;
    if (text.find('.') != std::string::npos) {
      while (text.back() == '0') text.pop_back();
      if (text.back() == '.') text.pop_back();
    }
    return text == "-0" ? "0" : text;
  }
  std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
  return buffer;
}

std::string Percent(double fraction) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.1f %%", 100.0 * fraction);
  return buffer;
}

bool EndsWith(std::string_view text, std::string_view tail) {
  return text.size() >= tail.size() && text.substr(text.size() - tail.size()) == tail;
}

// ---------------------------------------------------------------------------------------------
// Units: the SI unit in a JSON key's suffix, and the display unit the CLI uses for it.

struct Unit {
  std::string si;       ///< "m", "Pa", ...; empty when the key carries none
  std::string display;  ///< "mm", "MPa", "J/cm²", "N/cm²", "cm²"; empty when SI is shown as is
  double factor = 1.0;  ///< display value = SI value × factor
};

Unit UnitOfKey(std::string_view key) {
  struct Suffix {
    std::string_view tail;
    Unit unit;
  };
  static const Suffix kSuffixes[] = {
      {"_N_s_per_m", {"N·s/m", "", 1.0}},
      {"_N_per_m", {"N/m", "", 1.0}},
      {"_m_per_s2", {"m/s²", "", 1.0}},
      {"_m_per_s", {"m/s", "", 1.0}},
      {"_s_per_m", {"s/m", "", 1.0}},
      {"_J_per_m2", {"J/m²", "J/cm²", 1e-4}},
      {"_kg_per_m3", {"kg/m³", "", 1.0}},
      {"_m2", {"m²", "cm²", 1e4}},
      {"_kg", {"kg", "", 1.0}},
      {"_Pa", {"Pa", "MPa", 1e-6}},
      {"_m", {"m", "mm", 1e3}},
      {"_s", {"s", "", 1.0}},
      {"_N", {"N", "", 1.0}},
      {"_J", {"J", "", 1.0}},
  };
  for (const Suffix& s : kSuffixes) {
    if (EndsWith(key, s.tail)) {
      Unit unit = s.unit;
      // ISO/TS 15066's pressures read in N/cm², as the standard and the CLI give them.
      if (unit.si == "Pa" && key.find("pressure") != std::string_view::npos) unit = {"Pa", "N/cm²", 1e-4};
      return unit;
    }
  }
  return {};
}

/// The unit of a value named by the CLI's quantity ("kg", "m", "Pa", ...), as in uncertain_inputs.
Unit UnitOfName(std::string_view si) {
  if (si == "m") return {"m", "mm", 1e3};
  if (si == "Pa") return {"Pa", "MPa", 1e-6};
  if (si.empty() || si == "-" || si == "1") return {};
  return {std::string(si), "", 1.0};
}

/// "1.526 kN"-style reading of a value in its display unit, or in SI.
std::string Reading(double value, const Unit& unit) {
  if (!unit.display.empty()) return Significant(value * unit.factor) + " " + unit.display;
  if (!unit.si.empty()) return Significant(value) + " " + unit.si;
  return Significant(value);
}

// ---------------------------------------------------------------------------------------------
// JSON access

const Json* Find(const Json& object, std::string_view key) {
  if (!object.is_object()) return nullptr;
  const auto it = object.find(std::string(key));
  return it == object.end() ? nullptr : &*it;
}

const Json* FindPath(const Json& object, std::initializer_list<std::string_view> keys) {
  const Json* at = &object;
  for (const std::string_view key : keys) {
    at = Find(*at, key);
    if (!at) return nullptr;
  }
  return at;
}

std::string StringAt(const Json& object, std::string_view key, std::string fallback = "") {
  const Json* v = Find(object, key);
  return v && v->is_string() ? v->get<std::string>() : fallback;
}

std::optional<double> NumberAt(const Json& object, std::string_view key) {
  const Json* v = Find(object, key);
  if (v && v->is_number()) return v->get<double>();
  return std::nullopt;
}

bool TrueAt(const Json& object, std::string_view key) {
  const Json* v = Find(object, key);
  return v && v->is_boolean() && v->get<bool>();
}

// ---------------------------------------------------------------------------------------------
// What a report says: the verdict, its rows, the criteria and the models it rests on.

/// One verdict line: value against limit, ratio and margin.
struct VerdictRow {
  std::string subject;    ///< what is judged: "head: laceration", "chest (sternum): force"
  std::string criterion;  ///< the criterion, with its source in short
  std::string value;      ///< value, limit and derated limit as read (display units)
  std::string limit;
  std::string derated;
  Json ratio;             ///< a number, or null where the row has none (a yes/no criterion)
  double safety_factor = 1.0;
  std::optional<bool> safe;
  std::string note;
};

/// One criterion and where its limit comes from.
struct Criterion {
  std::string name;
  std::string limit;
  std::string source;
};

enum class Model { kHead, kBody, kSpeedLimit, kTrajectory, kAudit, kRobust };

struct Governing {
  std::string criterion;  ///< "contusion", "chest (sternum): force", ...
  Json ratio;             ///< the JSON's number, or null when the kind has none
};

struct Assessment {
  bool safe = false;
  std::string headline;          ///< one sentence: what was found
  std::string safe_means;        ///< what SAFE means for this kind, when it needs saying
  Governing governing;
  double safety_factor = 1.0;
  std::vector<VerdictRow> rows;  ///< every verdict
  std::string rows_note;         ///< what the rows are (e.g. "the recommended design")
  std::vector<Criterion> criteria;
  std::set<Model> models;
  std::vector<std::string> input_keys;  ///< top-level keys shown as inputs
};

constexpr std::string_view kPark =
    "Park et al., Designing Optimally Safe Robot Surface Properties for Minimizing the Stress "
    "Characteristics of Human-Robot Collisions, ICRA 2011";
constexpr std::string_view kCompressionSource =
    "covopt's criterion (docs/model.md §6): at the peak the covering is not fully compressed, i.e. "
    "it uses at most 1/SF of its own travel (80 % of its thickness, the paper's convention)";
constexpr std::string_view kFractureSource = "published skull and facial fracture forces (docs/model.md §7.1)";
constexpr std::string_view kCrushSource =
    "the material's compressive strength at yield or 10 % strain, from its datasheet (docs/model.md §12; "
    "see Materials below)";
constexpr std::string_view kIso = "ISO/TS 15066:2016 Annex A, Table A.2";

/// Table A.2's area number of `area` in `region` (built-in table), or 0 when unknown.
int AreaNumber(std::string_view region, std::string_view area) {
  try {
    const materials::BodyRegion& r = materials::BodyRegionTable::BuiltIn().Region(region);
    for (const materials::BodyArea& a : r.areas) {
      if (a.name == area) return a.number;
    }
  } catch (const std::exception&) {
  }
  return 0;
}

std::string RegionLabel(const std::string& region, const std::string& area) {
  if (area.empty()) return region;
  return region + " (" + area + ")";
}

std::string RegionSource(const std::string& region, const std::string& area) {
  std::string source = std::string(kIso) + ", region " + region;
  if (!area.empty()) {
    source += ", area " + area;
    const int number = AreaNumber(region, area);
    if (number > 0) source += " (body area no. " + std::to_string(number) + " of Tables A.1/A.2)";
  }
  return source;
}

void AddHeadCriteria(Assessment& a, const Json& limits_holder, bool with_compression = true, bool with_crush = true) {
  const std::optional<double> lac = NumberAt(limits_holder, "laceration_Pa");
  const std::optional<double> con = NumberAt(limits_holder, "contusion_J_per_m2");
  a.criteria.push_back({"head: laceration (peak tensile stress of the skin)",
                        lac ? Reading(*lac, {"Pa", "MPa", 1e-6}) : "1 MPa", std::string(kPark)});
  a.criteria.push_back({"head: contusion (peak energy density)",
                        con ? Reading(*con, {"J/m²", "J/cm²", 1e-4}) : "2.52 J/cm²", std::string(kPark)});
  a.criteria.push_back({"head: fracture (peak force on the struck bone)",
                        "the struck area's lowest published fracture force (forehead 3114 N)",
                        std::string(kFractureSource)});
  if (with_compression) {
    a.criteria.push_back({"full compression of the covering", "compression ratio ≤ 1/SF", std::string(kCompressionSource)});
  }
  if (with_crush) a.criteria.push_back({"crushing of the covering", "compressive stress ≤ strength / SF", std::string(kCrushSource)});
  a.models.insert(Model::kHead);
}

/// A head verdict object of SimulationJson ({value_*, limit_*, ratio, safe, derated_limit_*}).
VerdictRow HeadVerdictRow(const std::string& subject, const std::string& criterion, const Json& v, const Unit& unit) {
  VerdictRow row;
  row.subject = subject;
  row.criterion = criterion;
  for (const auto& [key, value] : v.items()) {
    if (!value.is_number()) continue;
    if (key.rfind("value_", 0) == 0) row.value = Reading(value.get<double>(), unit);
    if (key.rfind("limit_", 0) == 0) row.limit = Reading(value.get<double>(), unit);
    if (key.rfind("derated_limit_", 0) == 0) row.derated = Reading(value.get<double>(), unit);
  }
  row.ratio = v.contains("ratio") ? v["ratio"] : Json(nullptr);
  row.safety_factor = NumberAt(v, "safety_factor").value_or(1.0);
  if (v.contains("safe") && v["safe"].is_boolean()) row.safe = v["safe"].get<bool>();
  return row;
}

/// Ratio-only rows of a design ({laceration_ratio, contusion_ratio, compression_ratio, crush_ratio}).
void AddRatioRows(Assessment& a, const std::string& prefix, const Json& d, double sf, const Json* limits) {
  const auto add = [&](std::string_view key, std::string criterion, std::string value, std::string limit) {
    const Json* r = Find(d, key);
    if (!r) return;
    VerdictRow row;
    row.subject = prefix + criterion;
    row.criterion = criterion == "laceration" || criterion == "contusion" ? "skin injury, Park et al. 2011"
                    : criterion == "fracture"                             ? std::string(kFractureSource)
                    : criterion == "full compression"                     ? "covopt (docs/model.md §6)"
                                                                          : "material strength (docs/model.md §12)";
    row.value = std::move(value);
    row.limit = std::move(limit);
    row.ratio = *r;
    row.safety_factor = sf;
    if (r->is_number()) row.safe = sf * r->get<double>() <= 1.0;
    if (r->is_null() && key == "crush_ratio") row.note = "not checked: " + StringAt(d, "crush_check", "no strength known");
    a.rows.push_back(std::move(row));
  };
  const Unit mpa{"Pa", "MPa", 1e-6};
  const auto value_of = [&](std::string_view key, const Unit& unit) {
    const std::optional<double> v = NumberAt(d, key);
    return v ? Reading(*v, unit) : std::string();
  };
  const auto limit_of = [&](std::string_view key, const Unit& unit) {
    const std::optional<double> v = limits ? NumberAt(*limits, key) : std::nullopt;
    return v ? Reading(*v, unit) : std::string();
  };
  add("laceration_ratio", "laceration", value_of("max_tensile_stress_Pa", mpa), limit_of("laceration_Pa", mpa));
  add("contusion_ratio", "contusion", value_of("max_energy_density_J_per_m2", {"J/m²", "J/cm²", 1e-4}),
      limit_of("contusion_J_per_m2", {"J/m²", "J/cm²", 1e-4}));
  add("fracture_ratio", "fracture", "", "the struck area's lowest published fracture force");
  add("compression_ratio", "full compression", "", "the covering's travel");
  std::string strength;
  if (const std::optional<double> s = NumberAt(d, "compressive_strength_Pa")) strength = Reading(*s, mpa);
  add("crush_ratio", "crush", value_of("max_compressive_stress_Pa", mpa), strength);
}

/// The rows of one body-region verdict object (BodyRegionVerdict JSON).
void AddRegionRows(Assessment& a, const Json& r, const std::string& prefix = "") {
  const std::string region = StringAt(r, "region");
  const std::string area = StringAt(r, "area");
  const std::string label = prefix + RegionLabel(region, area);
  const double sf = NumberAt(r, "safety_factor").value_or(1.0);
  const std::string iso = std::string(kIso);
  if (const Json* f = Find(r, "force")) {
    VerdictRow row;
    row.subject = label + ": force";
    row.criterion = iso;
    if (auto v = NumberAt(*f, "value_N")) row.value = Reading(*v, {"N", "", 1});
    if (auto v = NumberAt(*f, "limit_N")) {
      row.limit = Reading(*v, {"N", "", 1});
      row.derated = Reading(*v / sf, {"N", "", 1});
    }
    row.ratio = f->contains("ratio") ? (*f)["ratio"] : Json(nullptr);
    row.safety_factor = sf;
    if (row.ratio.is_number()) row.safe = sf * row.ratio.get<double>() <= 1.0;
    a.rows.push_back(std::move(row));
  }
  if (const Json* p = Find(r, "pressure")) {
    VerdictRow row;
    row.subject = label + ": pressure";
    row.criterion = iso + " (Hertz peak pressure)";
    const Unit ncm2{"Pa", "N/cm²", 1e-4};
    if (auto v = NumberAt(*p, "value_Pa")) row.value = Reading(*v, ncm2);
    if (auto v = NumberAt(*p, "limit_Pa")) {
      row.limit = Reading(*v, ncm2);
      row.derated = Reading(*v / sf, ncm2);
    }
    row.ratio = p->contains("ratio") ? (*p)["ratio"] : Json(nullptr);
    row.safety_factor = sf;
    if (row.ratio.is_number()) row.safe = sf * row.ratio.get<double>() <= 1.0;
    if (!TrueAt(*p, "evaluated")) row.note = "pressure not evaluated (no contact area)";
    a.rows.push_back(std::move(row));
  }
  if (const Json* c = Find(r, "compression_ratio"); c && c->is_number() && c->get<double>() > 0.0) {
    VerdictRow row;
    row.subject = label + ": full compression";
    row.criterion = "covopt (docs/model.md §6, §13.4)";
    row.limit = "the covering's travel";
    row.ratio = *c;
    row.safety_factor = sf;
    row.safe = sf * c->get<double>() <= 1.0 && !TrueAt(r, "fully_compressed");
    a.rows.push_back(std::move(row));
  }
  if (const Json* c = Find(r, "crush")) {
    VerdictRow row;
    row.subject = label + ": crush";
    row.criterion = "material strength (docs/model.md §12)";
    row.ratio = c->contains("ratio") ? (*c)["ratio"] : Json(nullptr);
    row.safety_factor = sf;
    if (row.ratio.is_number()) row.safe = sf * row.ratio.get<double>() <= 1.0;
    else row.note = "not checked: " + StringAt(*c, "check");
    a.rows.push_back(std::move(row));
  }
  if (!region.empty() && region != "head") {
    std::string limit;
    const Json* f = FindPath(r, {"force", "limit_N"});
    const Json* p = FindPath(r, {"pressure", "limit_Pa"});
    if (f && f->is_number()) limit += Reading(f->get<double>(), {"N", "", 1});
    if (p && p->is_number()) limit += (limit.empty() ? "" : ", ") + Reading(p->get<double>(), {"Pa", "N/cm²", 1e-4});
    std::string source = RegionSource(region, area);
    if (const std::string scope = StringAt(r, "scope"); !scope.empty()) source += " — " + scope;
    a.criteria.push_back({RegionLabel(region, area) + ": force and pressure (" + StringAt(r, "contact", "transient") + ")",
                          limit, source});
  }
}

std::string ObjectLabel(const Json& o) { return StringAt(o, "material", "the design"); }

/// Governing = the largest numeric ratio over `rows` (the first on a tie).
Governing MaxRow(const std::vector<VerdictRow>& rows) {
  Governing g{"", Json(nullptr)};
  double best = -1.0;
  for (const VerdictRow& row : rows) {
    if (row.ratio.is_number() && row.ratio.get<double>() > best) {
      best = row.ratio.get<double>();
      g = {row.subject, row.ratio};
    }
  }
  return g;
}

// --- simulate ---------------------------------------------------------------------------------

void AssessHeadSimulation(Assessment& a, const Json& j, const std::string& prefix) {
  a.rows.push_back(HeadVerdictRow(prefix + "laceration", "skin injury, Park et al. 2011", j.at("laceration"),
                                  {"Pa", "MPa", 1e-6}));
  a.rows.push_back(HeadVerdictRow(prefix + "contusion", "skin injury, Park et al. 2011", j.at("contusion"),
                                  {"J/m²", "J/cm²", 1e-4}));
  if (const Json* fracture = Find(j, "fracture"); fracture && fracture->is_object()) {
    VerdictRow row = HeadVerdictRow(prefix + "fracture", std::string(kFractureSource), *fracture, {"N", "N", 1.0});
    row.note = StringAt(*fracture, "area") + ": " + StringAt(*fracture, "source");
    a.rows.push_back(std::move(row));
  }
  if (const Json* crush = Find(j, "crush"); crush && crush->is_object()) {
    a.rows.push_back(HeadVerdictRow(prefix + "crush", "material strength (docs/model.md §12)", *crush, {"Pa", "MPa", 1e-6}));
  }
  VerdictRow full;  // shown, not judged: simulate's verdict is the injuries and crushing (its scope)
  full.subject = prefix + "full compression";
  full.criterion = "not part of this verdict (see its scope); docs/model.md §6";
  full.value = TrueAt(j, "fully_compressed") ? "fully compressed" : "not fully compressed";
  full.ratio = nullptr;
  full.note = "phase at the peak: " + StringAt(j, "phase_at_max_name");
  a.rows.push_back(std::move(full));
  a.safety_factor = NumberAt(j.at("laceration"), "safety_factor").value_or(1.0);
  const Json* crush = Find(j, "crush");
  AddHeadCriteria(a, Json{{"laceration_Pa", j["laceration"].value("limit_Pa", 1e6)},
                          {"contusion_J_per_m2", j["contusion"].value("limit_J_per_m2", 25200.0)}},
                  false, crush && crush->is_object());
}

/// The worst case over a box of uncertain inputs ({governing_ratio, binding, admissible, ...}).
void AddWorstCase(Assessment& a, const Json& w, double sf, const std::string& subject) {
  VerdictRow row;
  row.subject = subject;
  row.criterion = "worst case over the ranges (docs/model.md §11): " + StringAt(w, "binding");
  std::string at;
  if (const Json* in = Find(w, "inputs")) {
    for (const auto& [k, v] : in->items()) {
      at += (at.empty() ? "" : ", ") + k + " " + ScalarText(v) + " " + StringAt(w.value("units", Json::object()), k);
    }
  }
  row.value = at.empty() ? "" : "at " + at;
  row.ratio = w.contains("governing_ratio") ? w["governing_ratio"] : Json(nullptr);
  row.safety_factor = sf;
  if (w.contains("admissible") && w["admissible"].is_boolean()) row.safe = w["admissible"].get<bool>();
  a.rows.push_back(std::move(row));
  a.models.insert(Model::kRobust);
}

void AddProbability(Assessment& a, const Json& p, std::optional<double> max_probability) {
  VerdictRow row;
  row.subject = "injury probability: P(inadmissible)";
  row.criterion = "Monte Carlo over the ranges, Wilson 95 % interval (docs/model.md §11)";
  const std::optional<double> inadmissible = NumberAt(p, "inadmissible");
  if (inadmissible) row.value = Significant(*inadmissible);
  if (const Json* ci = FindPath(p, {"ci95", "inadmissible"}); ci && ci->is_array() && ci->size() == 2) {
    row.value += " [" + Significant((*ci)[0].get<double>()) + ", " + Significant((*ci)[1].get<double>()) + "]";
  }
  row.value += " (" + ScalarText(p.value("samples", Json(nullptr))) + " samples, seed " + ScalarText(p.value("seed", Json(nullptr))) + ")";
  if (max_probability) {
    row.limit = Significant(*max_probability);
    if (inadmissible) row.ratio = Json(*inadmissible / *max_probability);
  } else {
    row.ratio = nullptr;
    row.note = "an estimate: no probability target was given";
  }
  a.rows.push_back(std::move(row));
  a.models.insert(Model::kRobust);
}

void AssessSimulate(Assessment& a, const Json& j) {
  if (const Json* regions = Find(j, "regions"); regions && regions->is_array()) {
    // --body-region: each region under ISO/TS 15066, the head under Park et al.
    if (!Find(j, "safe") || !j["safe"].is_boolean()) throw std::invalid_argument("the result has no verdict (\"safe\")");
    a.safety_factor = NumberAt(j, "safety_factor").value_or(1.0);
    for (const Json& r : *regions) AddRegionRows(a, r);
    a.models.insert(Model::kBody);
    if (const Json* head = Find(j, "head"); head && head->is_object()) AssessHeadSimulation(a, *head, "head: ");
    a.safe = j["safe"].get<bool>();
    a.governing = MaxRow(a.rows);
    a.headline = a.safe ? "every region named is within its limits" : "a region named exceeds its limits";
    a.input_keys = {"scene", "safety_factor"};
    return;
  }
  if (!Find(j, "safe") || !j["safe"].is_boolean() || !Find(j, "laceration") || !Find(j, "contusion")) {
    throw std::invalid_argument("the result has no verdict (\"safe\", \"laceration\", \"contusion\")");
  }
  if (const Json* status = FindPath(j, {"solver", "status"}); status && status->is_string() && *status != "success") {
    throw std::invalid_argument("the simulation failed (solver status '" + status->get<std::string>() + "')");
  }
  AssessHeadSimulation(a, j, "");
  a.safe = j["safe"].get<bool>();
  a.headline = a.safe ? "the impact causes neither laceration nor contusion, and the covering holds"
                      : "the impact injures, or the covering bottoms out or crushes";
  if (const Json* w = Find(j, "worst_case"); w && w->is_object()) {
    AddWorstCase(a, *w, a.safety_factor, "worst case over the ranges");
    a.safe = a.safe && TrueAt(*w, "admissible");
    a.headline = a.safe ? "the nominal impact and the worst case over the ranges are admissible"
                        : "the nominal impact or the worst case over the ranges is not admissible";
    a.safe_means = "With ranges of inputs, SAFE means the nominal impact and the worst case over the whole box are "
                   "admissible.";
  }
  if (const Json* p = Find(j, "injury_probability"); p && p->is_object()) AddProbability(a, *p, std::nullopt);
  a.governing = MaxRow(a.rows);
  a.input_keys = {"scene", "uncertain_inputs"};
}

// --- optimize ---------------------------------------------------------------------------------

void AssessOptimize(Assessment& a, const Json& j) {
  const Json* rec = Find(j, "recommendation");
  if (!rec) throw std::invalid_argument("the result has no verdict (\"recommendation\")");
  a.safety_factor = NumberAt(j, "safety_factor").value_or(NumberAt(j.value("criterion", Json::object()), "safety_factor").value_or(1.0));
  if (rec->is_object() && Find(*rec, "regions")) {
    // --body-region design
    for (const Json& r : (*rec)["regions"]) AddRegionRows(a, r, ObjectLabel(*rec) + ", ");
    a.models.insert(Model::kBody);
    if (const Json* head = Find(*rec, "head"); head && head->is_object()) {
      AddRatioRows(a, "head: ", *head, a.safety_factor, nullptr);
      AddHeadCriteria(a, Json::object());
    }
    a.safe = TrueAt(*rec, "admissible");
    a.governing = {StringAt(*rec, "governing_where"), rec->value("governing_ratio", Json(nullptr))};
    a.headline = StringAt(j, "message");
    a.rows_note = "The recommended covering, " + ObjectLabel(*rec) + " at " +
                  Reading(rec->value("thickness_m", 0.0), {"m", "mm", 1e3}) + ", on every region named.";
    a.input_keys = {"speed_m_per_s", "scene", "safety_factor"};
    return;
  }
  if (!rec->is_object()) {
    // Nothing recommended: no covering found (UNSAFE), or none needed.
    const std::string verdict = StringAt(j, "verdict");
    const Json* bare = Find(j, "bare_robot");
    a.safe = verdict == "bare-robot-safe" || (bare && verdict.empty() && TrueAt(*bare, "safe"));
    a.headline = a.safe ? "no covering is needed: the bare robot is safe"
                        : "NO COVERING FOUND: " + StringAt(j, "summary", StringAt(j, "message"));
    if (bare && bare->is_object()) {
      if (Find(*bare, "regions")) {
        for (const Json& r : (*bare)["regions"]) AddRegionRows(a, r, "bare robot, ");
        a.models.insert(Model::kBody);
      } else {
        AddRatioRows(a, "bare robot: ", *bare, a.safety_factor, Find(j, "limits"));
        if (const Json* g = Find(*bare, "governing_ratio")) {
          a.rows.back().note = "bare robot's governing ratio " + ScalarText(*g);
        }
      }
      a.rows_note = "No design is recommended; the rows are the bare robot's.";
    }
    a.governing = MaxRow(a.rows);
    if (const Json* limits = Find(j, "limits")) AddHeadCriteria(a, *limits);
    else if (!Find(j, "problem")) AddHeadCriteria(a, Json::object());
  } else {
    const std::string problem = StringAt(j, "problem");
    const Json* limits = Find(j, "limits");
    AddRatioRows(a, ObjectLabel(*rec) + ": ", *rec, a.safety_factor, limits);
    if (limits) AddHeadCriteria(a, *limits);
    a.rows_note = "The recommended covering, " + ObjectLabel(*rec) + " at " +
                  Reading(rec->value("thickness_m", 0.0), {"m", "mm", 1e3}) + ".";
    if (const Json* w = Find(*rec, "worst_case"); w && w->is_object()) {
      AddWorstCase(a, *w, a.safety_factor, ObjectLabel(*rec) + ": worst case over the ranges");
    }
    if (problem == "probability") {
      const std::optional<double> max_p = NumberAt(j, "max_probability");
      if (const Json* p = Find(*rec, "injury_probability")) AddProbability(a, *p, max_p);
      a.safe = StringAt(j, "verdict") == "covering-found";
      const VerdictRow& p_row = a.rows.back();
      a.governing = {"P(inadmissible) / max_probability", p_row.ratio};
      a.safe_means = "SAFE means the upper end of the Wilson 95 % interval of P(inadmissible) is at or below the "
                     "target max_probability (" + ScalarText(j.value("max_probability", Json(nullptr))) +
                     "); the governing ratio is P(inadmissible) / max_probability.";
    } else {
      a.safe = Find(*rec, "safe") ? TrueAt(*rec, "safe") : StringAt(j, "verdict") == "covering-found";
      a.governing = {StringAt(*rec, "governing_criterion"), rec->value("governing_ratio", Json(nullptr))};
      if (problem == "robust-thinnest") {
        a.safe_means = "SAFE means the recommended covering is admissible for every value in the box of uncertain inputs.";
      }
    }
    a.headline = StringAt(j, "summary");
  }
  a.input_keys = {"scene", "speed_m_per_s", "thickness_m", "safety_factor", "limits", "design_space",
                  "uncertain_inputs", "max_probability", "samples", "seed"};
}

// --- speed-limit ------------------------------------------------------------------------------

void AssessSpeedLimit(Assessment& a, const Json& j) {
  const Json* rows = Find(j, "rows");
  if (!rows || !rows->is_array() || rows->empty()) throw std::invalid_argument("the result has no verdict (no \"rows\")");
  a.safety_factor = NumberAt(j, "safety_factor").value_or(1.0);
  a.models.insert(Model::kSpeedLimit);
  bool all_found = true;
  double lowest = INFINITY;
  std::string lowest_where;
  std::string lowest_text;
  for (const Json& row : *rows) {
    const std::string status = StringAt(row, "covered_status", StringAt(row, "status"));
    if (status == "evaluation-failed") throw std::invalid_argument("the result has no verdict: a row's evaluation failed");
    if (status == "no-safe-value") all_found = false;
    const bool body = Find(row, "region") != nullptr;
    const std::string region = StringAt(row, "region");
    const std::string area = StringAt(row, "area");
    VerdictRow v;
    v.subject = (row.contains("material") && row["material"].is_string() ? row["material"].get<std::string>() + ", " : "");
    if (auto m = NumberAt(row, "robot_mass_kg")) v.subject += Significant(*m) + " kg";
    else if (row.contains("robot_mass_kg")) v.subject += "fixed robot";
    if (auto s = NumberAt(row, "speed_m_per_s")) v.subject += " at " + Significant(*s) + " m/s";
    if (body) v.subject += ", " + RegionLabel(region, area);
    v.safety_factor = a.safety_factor;
    std::optional<double> limit;
    std::string limit_key;
    for (const char* key : {"covered_max_speed_m_per_s", "max_safe_speed_m_per_s", "speed_limit_m_per_s", "max_safe_mass_kg"}) {
      if (auto x = NumberAt(row, key)) {
        limit = x;
        limit_key = key;
        break;
      }
    }
    const std::string by = StringAt(row, "covered_limited_by", StringAt(row, "limited_by"));
    v.value = limit ? (limit_key == "max_safe_mass_kg" ? "max safe mass " + Significant(*limit) + " kg"
                                                       : "max safe speed " + Significant(*limit) + " m/s")
                    : "no safe value";
    v.criterion = "limited by " + by + " (" + status + ")";
    if (body) {
      v.criterion += region == "head" ? "; skin injury, Park et al. 2011" : "; ISO/TS 15066:2016 Table A.2";
      if (auto bare = NumberAt(row, "bare_max_speed_m_per_s")) {
        v.note = "bare robot " + Significant(*bare) + " m/s (" + StringAt(row, "bare_limited_by") + ")";
        if (auto gain = NumberAt(row, "gain")) v.note += ", gain " + Significant(*gain, 3) + "×";
      }
      if (region != "head") {
        std::string lim;
        if (auto f = NumberAt(row, "force_limit_N")) lim += Reading(*f, {"N", "", 1});
        if (auto p = NumberAt(row, "pressure_limit_Pa")) lim += (lim.empty() ? "" : ", ") + Reading(*p, {"Pa", "N/cm²", 1e-4});
        a.criteria.push_back({RegionLabel(region, area) + ": force and pressure (" + StringAt(row, "contact", "transient") + ")",
                              lim, RegionSource(region, area)});
        a.models.insert(Model::kBody);
      } else {
        a.models.insert(Model::kHead);
      }
    }
    // The ratios of the impact at the limit: the largest is the binding criterion's (1 by construction).
    double row_max = -1.0;
    for (const char* key : {"laceration_ratio", "contusion_ratio", "compression_ratio", "crush_ratio"}) {
      if (const Json* r = Find(row, key); r && r->is_number() && r->get<double>() > row_max) {
        row_max = r->get<double>();
        v.ratio = *r;
      }
    }
    if (v.ratio.is_null()) v.ratio = nullptr;
    v.safe = status != "no-safe-value";
    if (limit && *limit < lowest) {
      lowest = *limit;
      lowest_where = v.subject + ": " + by;
      lowest_text = v.value;
    }
    a.rows.push_back(std::move(v));
  }
  a.safe = all_found;
  a.governing = MaxRow(a.rows);
  if (a.governing.ratio.is_null()) a.governing.criterion = lowest_where;
  if (!lowest_where.empty()) a.governing.criterion = lowest_where;
  a.headline = all_found ? "a safe limit exists for every row; the lowest: " + lowest_where + ", " + lowest_text
                         : "NO SAFE VALUE for at least one row: that robot is unsafe at any speed (or mass) searched";
  // Only the sentence of this verdict: a SAFE report never carries the other word.
  a.safe_means = std::string(all_found ? "SAFE here means every row has a max safe speed (or mass) above zero; the "
                                         "robot is safe only while it runs at or below its row's limit."
                                       : "UNSAFE here means some row has no max safe speed (or mass): no value "
                                         "searched is safe there.") +
                 " The ratios are those of the impact at the limit, so the largest is 1 at the binding criterion by "
                 "construction.";
  const Json* limits = Find(j, "limits");
  const bool any_head = std::any_of(rows->begin(), rows->end(), [](const Json& r) { return !r.contains("region"); });
  if (any_head) AddHeadCriteria(a, limits ? *limits : Json::object());
  if (Find(j, "uncertain_inputs")) a.models.insert(Model::kRobust);
  a.input_keys = {"solve_for", "scene", "safety_factor", "limits", "search_limit", "uncertain_inputs"};
}

// --- robot --trajectory -----------------------------------------------------------------------

bool StatusVerdict(const Json& j, std::string_view what) {
  const std::string status = StringAt(j, "status");
  if (status == "safe" || status == "at-rest") return true;
  if (status == "unsafe") return false;
  throw std::invalid_argument("the result has no verdict: " + std::string(what) + " status is '" + status + "'");
}

void AssessTrajectory(Assessment& a, const Json& j) {
  a.safe = StatusVerdict(j, "the trajectory's");
  a.models.insert(Model::kTrajectory);
  a.headline = StringAt(j, "message");
  const Json* samples = Find(j, "samples");
  a.safety_factor = NumberAt(j, "safety_factor").value_or(NumberAt(j, "criterion").value_or(1.0));
  if (const Json* c = Find(j, "criterion"); c && c->is_object()) {
    a.safety_factor = c->value("safety_factor", a.safety_factor);
  } else if (c && c->is_string()) {
    // The body-region trajectory records its factor only in the criterion's words ("safety factor 2 on each").
    const std::string text = c->get<std::string>();
    const std::size_t at = text.rfind("safety factor ");
    if (at != std::string::npos) a.safety_factor = std::strtod(text.c_str() + at + 14, nullptr);
    if (!(a.safety_factor >= 1.0)) a.safety_factor = 1.0;
  }
  Governing g{"", Json(nullptr)};
  double best = -1.0;
  const bool body = Find(j, "regions") != nullptr;
  if (samples && samples->is_array()) {
    for (const Json& s : *samples) {
      for (const char* key : {"laceration_ratio", "contusion_ratio", "compression_ratio", "crush_ratio", "worst_ratio"}) {
        const Json* r = Find(s, key);
        if (r && r->is_number() && r->get<double>() > best) {
          best = r->get<double>();
          std::string what = key == std::string_view("worst_ratio") ? StringAt(s, "binding") : std::string(key).substr(0, std::string(key).size() - 6);
          g = {what + " at t = " + ScalarText(s.value("time_s", Json(nullptr))) + " s", *r};
        }
      }
    }
  }
  a.governing = g;
  const auto sample_row = [&](const Json& s, const std::string& subject) {
    if (body) {
      VerdictRow v;
      v.subject = subject;
      v.criterion = "limited by " + StringAt(s, "binding", StringAt(s, "limited_by"));
      v.value = "speed " + Significant(s.value("speed_m_per_s", 0.0)) + " m/s, reflected mass " +
                Significant(s.value("reflected_mass_kg", 0.0)) + " kg";
      if (auto m = NumberAt(s, "max_safe_speed_m_per_s")) v.limit = "max safe speed " + Significant(*m) + " m/s";
      v.ratio = s.value("worst_ratio", Json(nullptr));
      v.safety_factor = a.safety_factor;
      if (s.contains("safe")) v.safe = TrueAt(s, "safe");
      a.rows.push_back(std::move(v));
    } else {
      AddRatioRows(a, subject + ": ", s, a.safety_factor, Find(j, "limits"));
    }
  };
  const Json* worst = Find(j, "worst_sample");
  if (worst && worst->is_number_integer() && samples && worst->get<std::size_t>() < samples->size()) {
    const Json& s = (*samples)[worst->get<std::size_t>()];
    sample_row(s, "worst sample (t = " + ScalarText(s.value("time_s", Json(nullptr))) + " s)");
  } else if (worst && worst->is_object()) {
    sample_row(*worst, "worst sample (t = " + ScalarText(worst->value("time_s", Json(nullptr))) + " s)");
  }
  VerdictRow scale;
  scale.subject = "the whole trajectory";
  scale.criterion = "safe speed scale (docs/model.md §9.3)";
  scale.value = "safe speed scale " + ScalarText(j.value("safe_speed_scale", Json(nullptr)));
  scale.limit = "≥ 1";
  scale.ratio = nullptr;
  scale.safe = a.safe;
  scale.note = ScalarText(j.value("unsafe_sample_count", Json(0))) + " unsafe of " +
               ScalarText(j.value("sample_count", Json(samples ? samples->size() : 0))) + " samples";
  a.rows.push_back(std::move(scale));
  a.rows_note = "The worst sample (the one that sets the safe speed scale) and the whole trajectory; every sample is "
                "in the appendix. The governing ratio is the largest ratio over every sample.";
  if (body) {
    a.models.insert(Model::kBody);
    for (const Json& r : j["regions"]) {
      const std::string region = StringAt(r, "region");
      const std::string area = StringAt(r, "area");
      a.criteria.push_back({RegionLabel(region, area) + " (" + StringAt(r, "contact", "transient") + ")",
                            StringAt(r, "scope"), RegionSource(region, area)});
    }
    if (const Json* head = Find(j, "head"); head && !head->is_null()) AddHeadCriteria(a, Json::object());
  } else {
    const Json* limits = Find(j, "limits");
    AddHeadCriteria(a, limits ? *limits : Json::object());
    a.models.insert(Model::kSpeedLimit);
  }
  a.input_keys = {"scene", "safety_factor", "limits", "search_limit", "regions", "joint_names", "sample_count"};
}

// --- audit ------------------------------------------------------------------------------------

void AssessAudit(Assessment& a, const Json& j) {
  a.safe = StatusVerdict(j, "the audit's");
  a.models.insert({Model::kAudit, Model::kBody, Model::kTrajectory, Model::kHead});
  a.headline = StringAt(j, "message");
  a.safety_factor = NumberAt(j, "safety_factor").value_or(1.0);
  const Json* cells = Find(j, "cells");
  // Per link, its worst cell; the governing ratio is the largest over every cell.
  std::vector<std::string> links;
  std::vector<const Json*> worst;
  if (cells && cells->is_array()) {
    for (const Json& c : *cells) {
      const std::string link = StringAt(c, "link");
      const auto it = std::find(links.begin(), links.end(), link);
      const Json* r = Find(c, "governing_ratio");
      if (it == links.end()) {
        links.push_back(link);
        worst.push_back(&c);
      } else {
        const Json*& w = worst[static_cast<std::size_t>(it - links.begin())];
        if (r && r->is_number() && r->get<double>() > w->value("governing_ratio", -1.0)) w = &c;
      }
    }
  }
  for (const Json* c : worst) {
    VerdictRow v;
    v.subject = StringAt(*c, "link") + " against " + StringAt(*c, "region");
    v.criterion = c->contains("binding") && (*c)["binding"].is_string() ? "limited by " + StringAt(*c, "binding") : "never moves";
    if (auto s = NumberAt(*c, "speed_m_per_s")) {
      v.value = "speed " + Significant(*s) + " m/s at t = " + ScalarText(c->value("time_s", Json(nullptr))) + " s";
    }
    if (auto m = NumberAt(*c, "max_safe_speed_m_per_s")) v.limit = "max safe speed " + Significant(*m) + " m/s";
    v.ratio = c->value("governing_ratio", Json(nullptr));
    v.safety_factor = a.safety_factor;
    if (v.ratio.is_number()) v.safe = a.safety_factor * v.ratio.get<double>() <= 1.0;
    a.rows.push_back(std::move(v));
  }
  a.rows_note = "Each link's worst cell (the region and moment of its largest ratio); every cell is in the appendix.";
  a.governing = MaxRow(a.rows);
  if (const Json* designs = Find(j, "link_designs"); designs && designs->is_array()) {
    for (const Json& d : *designs) {
      VerdictRow v;
      v.subject = StringAt(d, "link") + ": designed covering";
      v.criterion = "thinnest catalog covering safe at full speed";
      v.value = d.contains("material") && d["material"].is_string() ? d["material"].get<std::string>() : "-";
      if (auto t = NumberAt(d, "thickness_m")) v.value += " at " + Reading(*t, {"m", "mm", 1e3});
      v.ratio = d.value("governing_ratio", Json(nullptr));
      v.safety_factor = a.safety_factor;
      if (v.ratio.is_number()) v.safe = a.safety_factor * v.ratio.get<double>() <= 1.0;
      v.note = StringAt(d, "message");
      a.rows.push_back(std::move(v));
    }
  }
  if (const Json* regions = Find(j, "regions"); regions && regions->is_array()) {
    for (const Json& r : *regions) {
      if (!r.is_string()) continue;
      const std::string text = r.get<std::string>();
      const std::size_t open = text.find(" (");
      if (text.rfind("head", 0) == 0) continue;
      const std::string region = text.substr(0, open);
      const std::string area = open == std::string::npos ? "" : text.substr(open + 2, text.size() - open - 3);
      const materials::BodyRegionTable& table = materials::BodyRegionTable::BuiltIn();
      std::string limit;
      try {
        const materials::BodyLimits l = table.Limits(region, area, ContactType::kTransient);
        limit = Reading(l.force_N, {"N", "", 1}) + ", " + Reading(l.pressure_Pa, {"Pa", "N/cm²", 1e-4});
      } catch (const std::exception&) {
      }
      a.criteria.push_back({text + " (transient)", limit, RegionSource(region, area)});
    }
  }
  AddHeadCriteria(a, Json::object());
  a.input_keys = {"robot", "coverings", "contact_area_m2", "reaction_delay_s", "braking_m_per_s2", "safety_factor",
                  "sample_count", "surface", "regions"};
}

// ---------------------------------------------------------------------------------------------
// Models: their assumptions and validity limits, from docs/model.md.

struct ModelText {
  Model model;
  std::string_view title;
  std::vector<std::string_view> points;
};

const std::vector<ModelText>& ModelTexts() {
  static const std::vector<ModelText> kTexts = {
      {Model::kHead,
       "The head: Park et al.'s multi-layer Hertz model",
       {"Robot, covering, scalp and skull are elastic half-spaces in Hertz contact on one axis; the contact law has "
        "three phases (docs/model.md §2).",
        "The robot is its reflected mass along the impact direction; the head one rigid mass (4.5 kg by default), "
        "with no neck unless one is given (§7, §10.3).",
        "No dissipation and no fracture: energy is conserved unless damping, braking or a neck damper is given, and "
        "the skull stays elastic; above a published fracture force the real skull breaks first (§7).",
        "Hertz holds for non-sharp contact: radii larger than the contact radius. covopt warns when a phase leaves "
        "this domain (§7).",
        "The exponents are fitted constants from the paper's unpublished dummy tests; nothing shows they hold for "
        "coverings stiffer than the scalp (§7, §5).",
        "A layer is fully compressed at 80 % of its thickness: the paper's convention, not a material property "
        "(§6, §12.2).",
        "Moduli are quasi-static; an impact stiffens foams and elastomers, so the catalog's E is not conservative "
        "(§12.2).",
        "Not modelled: crushing itself, viscoelasticity and rate effects, hysteresis beyond optional Hunt–Crossley "
        "damping, compression set, ageing, temperature, the shape factor of bonded pads (§12.2).",
        "A SAFE head verdict means no skin injury in Park et al.'s model, not conformity with ISO/TS 15066, which "
        "permits no transient contact with the skull, forehead or face (§6)."}},
      {Model::kBody,
       "The body regions: ISO/TS 15066 Annex A with the covering in series",
       {"Each region is the standard's effective mass m_H and spring k_H (Table A.3); transient limits are twice the "
        "quasi-static force and pressure of Table A.2 (docs/model.md §13.1).",
        "The covering is a Hertz layer in series with the region's spring: covopt's extension, the standard has none. "
        "An integrator still validates the application by measurement (§13.2, §13.7).",
        "Table A.2's pressures are pain-onset values measured with a 1.4 cm × 1.4 cm probe; covopt compares them with "
        "the Hertz peak pressure at the contact's centre: conservative for contacts larger than the probe, an "
        "extrapolation for smaller ones (§13.8).",
        "The body is linear (constant k_H) and the contact conservative: no damping of tissue or foam (§13.8).",
        "The robot reacts at most as an ideal brake after a reaction delay; joint compliance, a ramping brake and a "
        "held stop are not modelled (§13.8, §13.10).",
        "The covering's Hertz law assumes a half-space and small strains; a contact radius larger than the "
        "covering's thickness or a foam on its plateau is outside it (§13.8, §12.2)."}},
      {Model::kSpeedLimit,
       "Speed limits",
       {"The max safe speed (or mass) is the largest value at which every counted criterion holds, every lower value "
        "being safe too (docs/model.md §9.1).",
        "The ratios shown with a limit are those of the impact at the limit: the binding criterion's is 1 (§9.1)."}},
      {Model::kTrajectory,
       "Trajectories: the robot behind the reflected mass",
       {"Each sample is an impact at the contact point's speed |J_v q̇| along its direction of motion, with the "
        "reflected mass along it, 1/(uᵀ J_v M⁻¹ J_vᵀ u) (docs/model.md §9.2, §9.3).",
        "Rigid links from the URDF; no motor rotor inertia (so the reflected mass is a lower bound in that respect); "
        "the joints are free during the impact (§9.2).",
        "Running the trajectory k times faster multiplies every speed by k: it is safe exactly when k ≤ the safe "
        "speed scale; a sample at rest does not limit it (§9.3)."}},
      {Model::kAudit,
       "The audit: the whole robot along its motion",
       {"Only the surface points given are judged: the collision geometry (or a surface file) sampled at a spacing; a "
        "cable, a tool without geometry or links after the tip are not (docs/model.md §14.6).",
        "Every point is judged against every region head-on along its velocity: the worst any contact of the program "
        "could be, not what a cell layout allows (§14.6).",
        "One covering per link, on the surface's radius (§14.6).",
        "The contact direction is the velocity: conservative for the speed, not necessarily for the mass (§14.6).",
        "Everything the body-region model and §7 leave out applies here too (§14.6)."}},
      {Model::kRobust,
       "Ranges of inputs",
       {"With ranges, the worst case is searched over the whole box (its corners, then a global search) (docs/model.md "
        "§11).",
        "Injury probabilities are Monte Carlo estimates over the ranges' distributions, with Wilson 95 % intervals; "
        "they are as good as the distributions given (§11)."}},
  };
  return kTexts;
}

// ---------------------------------------------------------------------------------------------
// HTML pieces

constexpr std::string_view kCss = R"css(
@page { size: A4; margin: 15mm 13mm 16mm 13mm; }
* { box-sizing: border-box; }
html { -webkit-print-color-adjust: exact; print-color-adjust: exact; }
body { font-family: "DejaVu Sans", "Liberation Sans", Arial, sans-serif; font-size: 10pt; line-height: 1.35;
       color: #111; background: #fff; margin: 0 auto; padding: 8mm; max-width: 210mm; }
h1 { font-size: 16pt; margin: 0 0 2mm 0; }
h2 { font-size: 13pt; margin: 7mm 0 2mm 0; border-bottom: 1px solid #888; break-after: avoid; page-break-after: avoid; }
h3 { font-size: 11pt; margin: 4mm 0 1mm 0; break-after: avoid; page-break-after: avoid; }
p, li { margin: 1mm 0; }
code { font-family: "DejaVu Sans Mono", monospace; font-size: 8.5pt; overflow-wrap: anywhere; }
.meta { color: #444; font-size: 9pt; }
.verdict { border: 4px solid; border-radius: 3mm; padding: 4mm 6mm; margin: 4mm 0; text-align: center;
           break-inside: avoid; page-break-inside: avoid; }
.verdict .word { font-size: 34pt; font-weight: 800; letter-spacing: 0.08em; line-height: 1.1; }
.verdict .headline { font-size: 12pt; font-weight: 600; margin-top: 2mm; }
.verdict .governing { font-size: 11pt; margin-top: 1mm; }
.verdict.safe { color: #0b5a23; background: #e3f4e8; border-color: #137333; }
.verdict.unsafe { color: #8c1410; background: #fde7e5; border-color: #b3261e; }
table { border-collapse: collapse; width: 100%; table-layout: fixed; font-size: 8.5pt; margin: 1mm 0 2mm 0; }
thead { display: table-header-group; }
tr { break-inside: avoid; page-break-inside: avoid; }
th, td { border: 1px solid #aaa; padding: 1px 3px; vertical-align: top; text-align: left; overflow-wrap: anywhere; }
th { background: #eee; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
td.ok { color: #0b5a23; font-weight: 700; white-space: nowrap; }
td.bad { color: #8c1410; font-weight: 700; white-space: nowrap; }
table.appendix { font-size: 7pt; margin: 0 0 1mm 0; }
h4.key { margin: 2mm 0 0.5mm 0; font-weight: 700; break-after: avoid; page-break-after: avoid; }
.key { font-family: "DejaVu Sans Mono", monospace; font-size: 7.5pt; }
figure.chart { margin: 3mm 0; break-inside: avoid; page-break-inside: avoid; text-align: center; }
figure.chart svg { width: 100%; max-width: 170mm; height: auto; max-height: 125mm; }
figure.chart figcaption { text-align: left; font-size: 9pt; }
.warnings li { color: #6b3d00; }
section.appendix-section { break-before: page; page-break-before: always; }
@media screen { body { box-shadow: 0 0 4mm #bbb; margin-top: 4mm; margin-bottom: 4mm; } }
@media print { body { padding: 0; max-width: none; } }
)css";

void OpenTable(std::string& out, std::initializer_list<std::pair<std::string_view, int>> columns, std::string_view cls = "") {
  out += "<table";
  if (!cls.empty()) out += " class=\"" + std::string(cls) + "\"";
  out += "><colgroup>";
  for (const auto& [name, width] : columns) out += "<col style=\"width:" + std::to_string(width) + "%\">";
  out += "</colgroup><thead><tr>";
  for (const auto& [name, width] : columns) {
    out += "<th>";
    Escape(out, name);
    out += "</th>";
  }
  out += "</tr></thead><tbody>\n";
}

void Cell(std::string& out, std::string_view text, std::string_view cls = "") {
  out += cls.empty() ? "<td>" : "<td class=\"" + std::string(cls) + "\">";
  Escape(out, text);
  out += "</td>";
}

/// A leaf of the inputs: its dotted path and value, with the unit its key (or its range) names.
struct Leaf {
  std::string path;
  const Json* value;
  Unit unit;
};

void Flatten(const Json& value, const std::string& path, const Unit& inherited, std::vector<Leaf>& out) {
  if (value.is_object() && !value.empty()) {
    const Json* unit_name = Find(value, "unit");
    for (const auto& [key, child] : value.items()) {
      Unit unit = UnitOfKey(key);
      if (unit.si.empty() && unit_name && unit_name->is_string() &&
          (key == "low" || key == "high" || key == "mean" || key == "standard_deviation")) {
        unit = UnitOfName(unit_name->get<std::string>());
      }
      if (unit.si.empty() && (child.is_array() || child.is_object())) unit = inherited;
      Flatten(child, path + "." + key, unit, out);
    }
  } else if (value.is_array() && !value.empty()) {
    for (std::size_t i = 0; i < value.size(); ++i) Flatten(value[i], path + "." + std::to_string(i), inherited, out);
  } else {
    out.push_back({path, &value, inherited});
  }
}

void WriteInputs(std::string& out, const Json& j, const std::vector<std::string>& keys) {
  std::vector<Leaf> leaves;
  for (const std::string& key : keys) {
    if (const Json* v = Find(j, key)) Flatten(*v, key, UnitOfKey(key), leaves);
  }
  out += "<p>Every input the result records, by its path in the JSON. Values are SI, exactly as the JSON gives them; "
         "the last column reads them in the unit the command line uses (mm, MPa, J/cm², N/cm², cm²) where it uses "
         "one. A mass or radius of \"fixed\" or \"flat\" is infinite.</p>\n";
  OpenTable(out, {{"input (JSON path)", 38}, {"value (SI, as in the JSON)", 24}, {"SI unit", 10}, {"reading", 28}});
  for (const Leaf& leaf : leaves) {
    out += "<tr><td class=\"key\">";
    Escape(out, leaf.path);
    out += "</td><td class=\"num\" data-key=\"";
    Escape(out, leaf.path);
    out += "\" data-value=\"";
    const std::string text = ScalarText(*leaf.value);
    Escape(out, text);
    out += "\">";
    Escape(out, leaf.value->is_string() || leaf.value->is_number() || leaf.value->is_boolean() ? text
                : leaf.value->is_null()                                                        ? "null"
                                                                                               : leaf.value->dump());
    out += "</td>";
    Cell(out, leaf.value->is_number() ? leaf.unit.si : "");
    Cell(out, leaf.value->is_number() && !leaf.unit.display.empty() ? Reading(leaf.value->get<double>(), leaf.unit) : "",
         "num");
    out += "</tr>\n";
  }
  if (leaves.empty()) out += "<tr><td colspan=\"4\">(the result records no inputs)</td></tr>\n";
  out += "</tbody></table>\n";
}

/// The margin 1 − SF × ratio, as a percentage of the derated limit.
std::string MarginText(const VerdictRow& row) {
  if (!row.ratio.is_number()) return "";
  return Percent(1.0 - row.safety_factor * row.ratio.get<double>());
}

void WriteVerdicts(std::string& out, const Assessment& a) {
  if (!a.rows_note.empty()) {
    out += "<p>";
    Escape(out, a.rows_note);
    out += "</p>\n";
  }
  OpenTable(out, {{"verdict", 16}, {"criterion", 17}, {"value", 12}, {"limit", 10}, {"derated limit", 9},
                  {"ratio", 7}, {"margin", 8}, {"verdict", 9}, {"note", 12}});
  for (const VerdictRow& row : a.rows) {
    out += "<tr>";
    Cell(out, row.subject);
    Cell(out, row.criterion);
    Cell(out, row.value, "num");
    Cell(out, row.limit, "num");
    Cell(out, row.derated, "num");
    out += "<td class=\"num\" data-ratio=\"";
    Escape(out, ScalarText(row.ratio));
    out += "\">";
    Escape(out, row.ratio.is_number() ? Significant(row.ratio.get<double>()) : "—");
    out += "</td>";
    Cell(out, MarginText(row), "num");
    if (row.safe) Cell(out, *row.safe ? "SAFE" : "UNSAFE", *row.safe ? "ok" : "bad");
    else Cell(out, "");
    Cell(out, row.note);
    out += "</tr>\n";
  }
  out += "</tbody></table>\n";
}

/// A material the result uses (not every candidate of a design), with the modulus the run used
/// when the JSON gives it beside the name [Pa].
struct UsedMaterial {
  std::string name;
  std::optional<double> youngs_modulus_Pa;
};

std::vector<UsedMaterial> MaterialsUsed(const Json& j) {
  std::vector<UsedMaterial> used;
  const auto add = [&](const Json* holder, std::optional<double> modulus) {
    const Json* v = holder ? Find(*holder, "material") : nullptr;
    if (!v || !v->is_string()) return;
    const std::string name = v->get<std::string>();
    if (std::none_of(used.begin(), used.end(), [&](const UsedMaterial& m) { return m.name == name; })) {
      used.push_back({name, modulus});
    }
  };
  const auto modulus_of = [](const Json* holder) {
    if (!holder) return std::optional<double>();
    if (auto e = NumberAt(*holder, "youngs_modulus_Pa")) return e;
    return NumberAt(*holder, "modulus_Pa");
  };
  const Json* covering = FindPath(j, {"scene", "covering"});
  add(covering, modulus_of(covering));
  if (const Json* rec = Find(j, "recommendation"); rec && rec->is_object()) add(rec, modulus_of(rec));
  for (const char* list : {"rows", "coverings", "link_designs"}) {
    if (const Json* rows = Find(j, list); rows && rows->is_array()) {
      for (const Json& row : *rows) add(&row, modulus_of(&row));
    }
  }
  return used;
}

void WriteMaterials(std::string& out, const Json& j) {
  const std::vector<UsedMaterial> used = MaterialsUsed(j);
  if (used.empty()) {
    out += "<p>No catalog material: the covering is given by its modulus (or there is none), so there is no datasheet "
           "to cite.</p>\n";
    return;
  }
  out += "<p>The datasheet values come from covopt's built-in catalog entry of each name (materials/data; "
         "<code>covopt materials show NAME</code>). If the run read a catalog of its own (<code>--catalog</code>, listed "
         "with its SHA-256 under Provenance), that file's entry is the one used.</p>\n";
  const materials::Catalog& catalog = materials::Catalog::BuiltIn();
  for (const UsedMaterial& u : used) {
    out += "<h3>";
    Escape(out, u.name);
    out += "</h3>\n";
    const materials::Material* m = catalog.Find(u.name);
    if (!m) {
      out += "<p>Not in the built-in catalog: its datasheet is the catalog file the run read.</p>\n";
      continue;
    }
    if (u.youngs_modulus_Pa && std::fabs(*u.youngs_modulus_Pa - m->youngs_modulus_Pa) > 1e-9 * m->youngs_modulus_Pa) {
      out += "<p><b>The run used E = ";
      Escape(out, Reading(*u.youngs_modulus_Pa, {"Pa", "MPa", 1e-6}));
      out += ", not the built-in entry's: its datasheet is the catalog file the run read (Provenance); the built-in "
             "entry of the same name follows for reference.</b></p>\n";
    }
    OpenTable(out, {{"field", 25}, {"value", 75}});
    const auto row = [&](std::string_view field, const std::string& value) {
      out += "<tr>";
      Cell(out, field);
      Cell(out, value.empty() ? "not given by the source" : value);
      out += "</tr>\n";
    };
    row("family", m->family);
    row("Young's modulus E", Reading(m->youngs_modulus_Pa, {"Pa", "MPa", 1e-6}) + " (" +
                                 std::string(materials::ToString(m->modulus_basis)) + ")");
    row("Poisson ratio ν", m->poisson_ratio ? Significant(*m->poisson_ratio) : "");
    row("density", m->density_kg_per_m3 ? Significant(*m->density_kg_per_m3) + " kg/m³" : "");
    row("source (datasheet)", m->source);
    row("note on E", m->note);
    row("crush behaviour", std::string(materials::ToString(m->crush_behaviour)));
    row("compressive strength", m->compressive_strength_Pa ? Reading(*m->compressive_strength_Pa, {"Pa", "MPa", 1e-6}) : "");
    row("strength method", m->strength_method);
    row("strength source", m->strength_source);
    out += "</tbody></table>\n";
  }
}

bool IsScalarArray(const Json& v) {
  return v.is_array() && std::all_of(v.begin(), v.end(), [](const Json& e) { return e.is_primitive(); });
}

/// A value that reads on one line: a scalar, an empty or scalar array, or a small object of
/// such (at most 4 scalars).
bool IsInline(const Json& v) {
  if (v.is_primitive() || v.empty() || IsScalarArray(v)) return true;
  return v.is_object() && v.size() <= 4 &&
         std::all_of(v.begin(), v.end(), [](const Json& e) { return e.is_primitive() || (e.is_array() && e.empty()); });
}

void InlineText(std::string& out, const Json& v) {
  if (v.is_string()) {
    Escape(out, v.get<std::string>());
  } else if (v.is_primitive()) {
    out += v.dump();
  } else if (v.empty()) {
    out += v.is_array() ? "[]" : "{}";
  } else if (v.is_array()) {
    out += "[";
    bool first = true;
    for (const Json& e : v) {
      if (!first) out += ", ";
      first = false;
      Escape(out, e.is_string() ? "\"" + e.get<std::string>() + "\"" : e.dump());
    }
    out += "]";
  } else {
    bool first = true;
    for (const auto& [key, e] : v.items()) {
      if (!first) out += "; ";
      first = false;
      out += "<span class=\"key\">";
      Escape(out, key);
      out += "</span> ";
      InlineText(out, e);
    }
  }
}

/// Both are objects with the same keys in the same order.
bool SameKeys(const Json& a, const Json& b) {
  if (!a.is_object() || !b.is_object() || a.size() != b.size()) return false;
  auto i = a.begin();
  for (auto k = b.begin(); k != b.end(); ++k, ++i) {
    if (i.key() != k.key()) return false;
  }
  return true;
}

/// Every value of `v` (an object or array) as full-width tables, one per nested object or
/// array, headed by its dotted path: scalars (and small objects of scalars) on one line, two
/// key/value pairs a row; an array of like objects of at most 14 inline values as one table
/// with a column per key. Nested values get their own table after their parent's.
void WriteAppendix(std::string& out, const Json& v, const std::string& path) {
  out += "<h4 class=\"key\">";
  Escape(out, path.empty() ? "(the result)" : path);
  out += "</h4>\n";
  const bool columns = v.is_array() && v.front().is_object() && v.front().size() <= 14 &&
                       std::all_of(v.begin(), v.end(), [&](const Json& e) {
                         return SameKeys(e, v.front()) &&
                                std::all_of(e.begin(), e.end(), [](const Json& x) { return IsInline(x); });
                       });
  if (columns) {
    out += "<table class=\"appendix\"><thead><tr><th>#</th>";
    for (const auto& [key, unused] : v.front().items()) {
      out += "<th>";
      Escape(out, key);
      out += "</th>";
    }
    out += "</tr></thead><tbody>\n";
    std::size_t index = 0;
    for (const Json& e : v) {
      out += "<tr><td>" + std::to_string(index++) + "</td>";
      for (const auto& [key, child] : e.items()) {
        out += "<td>";
        InlineText(out, child);
        out += "</td>";
      }
      out += "</tr>\n";
    }
    out += "</tbody></table>\n";
    return;
  }
  std::vector<std::pair<std::string, const Json*>> entries;
  if (v.is_object()) {
    for (const auto& [key, child] : v.items()) entries.emplace_back(key, &child);
  } else {
    for (std::size_t i = 0; i < v.size(); ++i) entries.emplace_back(std::to_string(i), &v[i]);
  }
  out += "<table class=\"appendix\"><colgroup><col style=\"width:20%\"><col style=\"width:30%\">"
         "<col style=\"width:20%\"><col style=\"width:30%\"></colgroup><tbody>\n";
  for (std::size_t i = 0; i < entries.size(); i += 2) {
    out += "<tr>";
    for (std::size_t k = i; k < i + 2; ++k) {
      if (k >= entries.size()) {
        out += "<td></td><td></td>";
        continue;
      }
      const auto& [key, child] = entries[k];
      out += "<td class=\"key\">";
      Escape(out, key);
      out += "</td><td>";
      if (IsInline(*child)) {
        InlineText(out, *child);
      } else {
        out += "see ";
        Escape(out, path.empty() ? key : path + "." + key);
      }
      out += "</td>";
    }
    out += "</tr>\n";
  }
  out += "</tbody></table>\n";
  for (const auto& [key, child] : entries) {
    if (!IsInline(*child)) WriteAppendix(out, *child, path.empty() ? key : path + "." + key);
  }
}

void WriteProvenance(std::string& out, const Json& p) {
  OpenTable(out, {{"field", 22}, {"value", 78}});
  for (const auto& [key, value] : p.items()) {
    if (key == "inputs") continue;
    out += "<tr>";
    Cell(out, key, "key");
    out += "<td><code>";
    Escape(out, ScalarText(value));
    out += "</code></td></tr>\n";
  }
  out += "</tbody></table>\n<h3>Input files</h3>\n";
  const Json* inputs = Find(p, "inputs");
  if (!inputs || !inputs->is_array() || inputs->empty()) {
    out += "<p>None: every input was given on the command line (above) or is built in.</p>\n";
    return;
  }
  OpenTable(out, {{"role", 12}, {"path", 30}, {"SHA-256", 46}, {"bytes", 12}});
  for (const Json& f : *inputs) {
    out += "<tr>";
    Cell(out, StringAt(f, "role"));
    out += "<td><code>";
    Escape(out, StringAt(f, "path"));
    out += "</code></td><td><code>";
    Escape(out, StringAt(f, "sha256"));
    out += "</code></td>";
    Cell(out, ScalarText(f.value("size_bytes", Json(nullptr))), "num");
    out += "</tr>\n";
  }
  out += "</tbody></table>\n";
}

std::vector<std::string> TextList(const Json* v) {
  std::vector<std::string> out;
  if (!v) return out;
  if (v->is_string()) out.push_back(v->get<std::string>());
  if (v->is_array()) {
    for (const Json& e : *v) {
      if (e.is_string()) out.push_back(e.get<std::string>());
    }
  }
  if (v->is_object()) {
    for (const char* key : {"description"}) {
      if (const Json* d = Find(*v, key); d && d->is_string()) out.push_back(d->get<std::string>());
    }
  }
  return out;
}

}  // namespace

std::string HtmlReport(const ReportContent& content) {
  Json j;
  try {
    j = Json::parse(content.result_json);
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("report: result_json is not JSON (") + e.what() + ")");
  }
  if (!j.is_object()) {
    throw std::invalid_argument("report: result_json must be the JSON object a command prints with --json (got a " +
                                std::string(j.type_name()) + ")");
  }
  const Json* provenance = Find(j, "provenance");
  if (!provenance || !provenance->is_object()) {
    throw std::invalid_argument(
        "report: result_json has no \"provenance\" object (add it with report::WithProvenance)");
  }
  Assessment a;
  try {
    switch (content.kind) {
      case ReportKind::kSimulate: AssessSimulate(a, j); break;
      case ReportKind::kOptimize: AssessOptimize(a, j); break;
      case ReportKind::kSpeedLimit: AssessSpeedLimit(a, j); break;
      case ReportKind::kTrajectory: AssessTrajectory(a, j); break;
      case ReportKind::kAudit: AssessAudit(a, j); break;
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument("report: result_json is not a " + std::string(ToString(content.kind)) +
                                " result (" + e.what() + ")");
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("report: no report for a " + std::string(ToString(content.kind)) +
                                " run without a verdict: " + e.what());
  }
  std::vector<std::string> svgs;
  svgs.reserve(content.charts.size());
  for (std::size_t i = 0; i < content.charts.size(); ++i) {
    std::string prefix = "chart";  // ids of chart 1 become "chart1-gnuplot_canvas", ...
    prefix += std::to_string(i + 1);
    prefix += '-';
    svgs.push_back(internal::InlineSvg(content.charts[i].svg, prefix, i + 1));
  }

  const std::string kind(ToString(content.kind));
  const std::string word = a.safe ? "SAFE" : "UNSAFE";
  std::string out;
  out.reserve(content.result_json.size() * 3 + 32768);
  out += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'; img-src data:\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>";
  Escape(out, "covopt " + kind + " report: " + word);
  out += "</title>\n<style>";
  out += kCss;
  out += "</style>\n</head>\n<body>\n<header>\n<h1>";
  Escape(out, "Collision safety report: covopt " + kind);
  out += "</h1>\n<p class=\"meta\">";
  Escape(out, StringAt(*provenance, "software", "covopt") + " " + StringAt(*provenance, "version") + ", commit " +
                  StringAt(*provenance, "commit") + ", " + StringAt(*provenance, "date_utc"));
  out += "<br><code>";
  Escape(out, StringAt(*provenance, "command"));
  out += "</code></p>\n</header>\n";

  // The verdict: SAFE and UNSAFE in the same element, size and place; only the colours differ.
  out += "<section id=\"verdict\" class=\"verdict ";
  out += a.safe ? "safe" : "unsafe";
  out += "\" data-safe=\"";
  out += a.safe ? "true" : "false";
  out += "\">\n<div class=\"word\">" + word + "</div>\n<div class=\"headline\">";
  Escape(out, a.headline);
  out += "</div>\n<div class=\"governing\">Governing: ";
  Escape(out, a.governing.criterion.empty() ? "—" : a.governing.criterion);
  out += ", ratio <span id=\"governing-ratio\" data-value=\"";
  Escape(out, ScalarText(a.governing.ratio));
  out += "\">";
  Escape(out, a.governing.ratio.is_number() ? Significant(a.governing.ratio.get<double>()) : "none (see below)");
  out += "</span>";
  if (a.governing.ratio.is_number()) {
    out += ", margin ";
    Escape(out, Percent(1.0 - a.safety_factor * a.governing.ratio.get<double>()));
  }
  out += " (safety factor ";
  Escape(out, Significant(a.safety_factor));
  out += ")</div>\n</section>\n";
  out += "<p><b>Margin</b>, here and below, is 1 − SF × ratio, the share of the derated limit (limit / SF) left over; "
         "a ratio is value / limit. Negative margins exceed the limit.";
  if (!a.safe_means.empty()) {
    out += " ";
    Escape(out, a.safe_means);
  }
  out += "</p>\n";

  out += "<h2>What the verdict covers</h2>\n<ul>\n";
  std::vector<std::string> scope = TextList(Find(j, "scope"));
  for (const std::string& s : TextList(Find(j, "criterion"))) {
    const bool said = std::any_of(scope.begin(), scope.end(), [&](const std::string& t) { return t.find(s) != std::string::npos; });
    if (!said) scope.push_back("Criterion: " + s);
  }
  if (scope.empty()) scope.push_back("The criteria listed under Criteria and limits.");
  for (const std::string& s : scope) {
    out += "<li>";
    Escape(out, s);
    out += "</li>\n";
  }
  out += "</ul>\n";

  out += "<h2>Inputs</h2>\n";
  WriteInputs(out, j, a.input_keys);

  out += "<h2>Criteria and limits</h2>\n";
  OpenTable(out, {{"criterion", 30}, {"limit", 20}, {"source", 50}});
  std::set<std::string> seen;
  for (const Criterion& c : a.criteria) {
    if (!seen.insert(c.name + c.limit).second) continue;
    out += "<tr>";
    Cell(out, c.name);
    Cell(out, c.limit);
    Cell(out, c.source);
    out += "</tr>\n";
  }
  out += "</tbody></table>\n<p>Safety factor SF = ";
  Escape(out, Significant(a.safety_factor));
  out += ": each ratio must stay at or below 1/SF (the derated limit is limit / SF).</p>\n";

  out += "<h2>Verdicts</h2>\n";
  WriteVerdicts(out, a);

  out += "<h2>Materials</h2>\n";
  WriteMaterials(out, j);

  out += "<h2>Assumptions and validity limits</h2>\n<p>From docs/model.md, for the models this result rests on.</p>\n";
  for (const ModelText& m : ModelTexts()) {
    if (!a.models.count(m.model)) continue;
    out += "<h3>";
    Escape(out, m.title);
    out += "</h3>\n<ul>\n";
    for (const std::string_view point : m.points) {
      out += "<li>";
      Escape(out, point);
      out += "</li>\n";
    }
    out += "</ul>\n";
  }

  out += "<h2>Warnings</h2>\n";
  const std::vector<std::string> warnings = TextList(Find(j, "warnings"));
  if (warnings.empty()) {
    out += "<p>None.</p>\n";
  } else {
    out += "<ul class=\"warnings\">\n";
    for (const std::string& w : warnings) {
      out += "<li>";
      Escape(out, w);
      out += "</li>\n";
    }
    out += "</ul>\n";
  }

  out += "<h2>Charts</h2>\n";
  if (content.charts.empty()) out += "<p>No charts.</p>\n";
  for (std::size_t i = 0; i < content.charts.size(); ++i) {
    out += "<figure class=\"chart\" id=\"chart-" + std::to_string(i + 1) + "\">\n";
    out += svgs[i];
    out += "\n<figcaption><b>Figure " + std::to_string(i + 1) + ". ";
    Escape(out, content.charts[i].title);
    out += "</b> ";
    Escape(out, content.charts[i].caption);
    out += "</figcaption>\n</figure>\n";
  }

  out += "<h2>Provenance</h2>\n";
  WriteProvenance(out, *provenance);

  out += "<section class=\"appendix-section\">\n<h2>Appendix: every value of the result</h2>\n"
         "<p>The JSON object the command printed with --json, in full (SI units, as in its keys).</p>\n";
  WriteAppendix(out, j, "");
  out += "\n</section>\n</body>\n</html>\n";
  return out;
}

}  // namespace covopt::report
