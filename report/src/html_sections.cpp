// The HTML report's sections (html_sections.hpp): style sheet, tables, inputs, verdicts,
// materials and the models' assumptions.
#include "html_sections.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <covopt/materials/catalog.hpp>

namespace covopt::report::internal::html {

namespace {

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

}  // namespace

// ---------------------------------------------------------------------------------------------
// HTML pieces

const std::string_view kCss = R"css(
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

void OpenTable(std::string& out, std::initializer_list<std::pair<std::string_view, int>> columns, std::string_view cls) {
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

void Cell(std::string& out, std::string_view text, std::string_view cls) {
  out += cls.empty() ? "<td>" : "<td class=\"" + std::string(cls) + "\">";
  Escape(out, text);
  out += "</td>";
}

namespace {

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

}  // namespace

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

namespace {

/// The margin 1 − SF × ratio, as a percentage of the derated limit.
std::string MarginText(const VerdictRow& row) {
  if (!row.ratio.is_number()) return "";
  return Percent(1.0 - row.safety_factor * row.ratio.get<double>());
}

}  // namespace

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

namespace {

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

}  // namespace

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

void WriteModels(std::string& out, const Assessment& a) {
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

}  // namespace covopt::report::internal::html
