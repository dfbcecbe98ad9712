// What the HTML report says (html_assessment.hpp): each command's --json object read into its
// verdict rows, governing ratio, criteria and models.
#include "html_assessment.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <covopt/materials/body_regions.hpp>

namespace covopt::report::internal::html {

namespace {

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
  if (const Json* validity = Find(j, "validity"); validity && validity->is_object() && !StringAt(j, "covering_law").empty()) {
    VerdictRow law;  // the covering law's validity: counted always, a yes/no
    law.subject = prefix + "covering law (" + StringAt(j, "covering_law") + ")";
    law.criterion = "within the law's validity (docs/model.md)";
    law.value = TrueAt(*validity, "within") ? "within" : "out of its validity";
    law.ratio = nullptr;
    law.safe = TrueAt(*validity, "within");
    law.note = StringAt(*validity, "note");
    a.rows.push_back(std::move(law));
  }
  VerdictRow full;  // shown: the travel rule counts only with --keep-travel (the verdict's scope)
  full.subject = prefix + "full compression";
  full.criterion = "the covering's travel rule, a limit only with --keep-travel; docs/model.md §6";
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

}  // namespace

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
                        : "NO COVERING FOUND: " + StringAt(j, "message");
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
    if (const std::string law = StringAt(*rec, "covering_law"); !law.empty()) {  // its law and validity
      const Json* validity = Find(*rec, "validity");
      a.rows_note += " Covering law " + law +
                     (validity && validity->is_object() ? "; validity: " + StringAt(*validity, "note") : "") + ".";
    }
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
    a.headline = StringAt(j, "message");
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

namespace {

bool StatusVerdict(const Json& j, std::string_view what) {
  const std::string status = StringAt(j, "status");
  if (status == "safe" || status == "at-rest") return true;
  if (status == "unsafe") return false;
  throw std::invalid_argument("the result has no verdict: " + std::string(what) + " status is '" + status + "'");
}

}  // namespace

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

}  // namespace covopt::report::internal::html
