// The HTML report's sections (html_sections.hpp): style sheet, tables, the verdict rows, the
// covering's material and the models' assumptions.
#include "html_sections.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include <covopt/materials/catalog.hpp>

#include "criterion_display.hpp"

namespace covopt::report::internal::html {

using covopt::report::internal::Display;
using covopt::report::internal::DisplayOf;

namespace {

// ---------------------------------------------------------------------------------------------
// Models: their assumptions and validity limits, from docs/model.md.

enum class Model { kHead, kBody, kFoam, kSpeedLimit, kTrajectory, kAudit, kRetime, kRobust };

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
      {Model::kFoam,
       "The foam covering: an elastic foundation on the measured curve",
       {"A covering with a measured compressive curve is a foam layer: each column under the contact is compressed "
        "by the local gap and pushes back with the curve's stress at its own strain (docs/model.md §15.2).",
        "The curve is the loading branch, piecewise linear through the measured points; beyond its last point the "
        "law has no data, and a covering compressed that far is out of the law's validity (§15.1, §15.5).",
        "Young's modulus and the Poisson ratio of the material are not read by the foam law (§15.2)."}},
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
      {Model::kRetime,
       "Re-timing: the fastest safe timing of the same path",
       {"The path (the joint positions, sample by sample) is kept; only its timing changes. Each sample's largest "
        "safe path speed is the audit's safe speed scale of that sample alone (docs/model.md, Re-timing).",
        "The timing is time-optimal among profiles whose path acceleration is constant between samples, under the "
        "safety limit, the programmed-speed cap and the joints' speed and acceleration limits (TOPP-RA: H. Pham and "
        "Q.-C. Pham, IEEE Trans. Robotics 34(3), 2018).",
        "The re-timed program is audited again at its own samples; between samples the safety limit is not "
        "checked, as in every audit.",
        "Motor torques, jerk and the controller's tracking error are not modelled: the robot must be able to follow "
        "the re-timed program as written."}},
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
@page { size: A4; margin: 13mm 12mm 14mm 12mm; }
* { box-sizing: border-box; }
html { -webkit-print-color-adjust: exact; print-color-adjust: exact; }
body { font-family: "DejaVu Sans", "Liberation Sans", Arial, sans-serif; font-size: 9pt; line-height: 1.3;
       color: #111; background: #fff; margin: 0 auto; padding: 8mm; max-width: 210mm; }
h1 { font-size: 15pt; margin: 0 0 1mm 0; }
h2 { font-size: 12pt; margin: 5mm 0 1.5mm 0; border-bottom: 1px solid #888; break-after: avoid; page-break-after: avoid; }
h3 { font-size: 10pt; margin: 2.5mm 0 1mm 0; break-after: avoid; page-break-after: avoid; }
p, li { margin: 0.7mm 0; }
ul.compact { margin: 0; padding-left: 5mm; font-size: 8.5pt; }
code { font-family: "DejaVu Sans Mono", monospace; font-size: 8pt; overflow-wrap: anywhere; }
.meta { color: #444; font-size: 9pt; margin: 0; }
#page-one { break-after: page; page-break-after: always; }
.verdict { border: 4px solid; border-radius: 3mm; padding: 2.5mm 5mm; margin: 3mm 0; text-align: center;
           break-inside: avoid; page-break-inside: avoid; }
.verdict .word { font-size: 30pt; font-weight: 800; letter-spacing: 0.08em; line-height: 1.1; }
.verdict .sentence { font-size: 11pt; font-weight: 600; margin-top: 1mm; }
.verdict .governing { font-size: 9.5pt; margin-top: 1mm; }
.verdict.safe { color: #0b5a23; background: #e3f4e8; border-color: #137333; }
.verdict.marginal { color: #6b4200; background: #fff2d6; border-color: #c77c02; }
.verdict.unsafe { color: #8c1410; background: #fde7e5; border-color: #b3261e; }
.verdict.limits { color: #0d3c78; background: #e3edfb; border-color: #1a5fb4; }
.facts { display: grid; grid-template-columns: 1fr 1fr; column-gap: 5mm; }
.facts section, #sign-off { break-inside: avoid; page-break-inside: avoid; }
dl { display: grid; grid-template-columns: 26mm 1fr; column-gap: 2mm; row-gap: 0.4mm; margin: 0; }
#sign-off dl { grid-template-columns: 30mm 1fr; }
dt { font-weight: 700; color: #333; }
dd { margin: 0; overflow-wrap: anywhere; }
dd.blank { border-bottom: 1px solid #555; min-height: 4.5mm; }
.signature-line { display: grid; grid-template-columns: 22mm 1fr 1fr 0.6fr; column-gap: 4mm; margin-top: 7mm; }
.signature-line .role { font-weight: 700; }
.signature-line .line { border-top: 1px solid #111; padding-top: 0.5mm; font-size: 7.5pt; color: #444; }
table { border-collapse: collapse; width: 100%; table-layout: fixed; font-size: 8pt; margin: 1mm 0 2mm 0; }
thead { display: table-header-group; }
tr { break-inside: avoid; page-break-inside: avoid; }
th, td { border: 1px solid #aaa; padding: 1px 3px; vertical-align: top; text-align: left; overflow-wrap: anywhere; }
th { background: #eee; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
td.ok { color: #0b5a23; font-weight: 700; }
td.bad { color: #8c1410; font-weight: 700; }
tr.binding td { font-weight: 700; background: #f6f6f6; }
table.appendix { font-size: 7pt; margin: 0 0 1mm 0; }
h4.key { margin: 2mm 0 0.5mm 0; font-weight: 700; break-after: avoid; page-break-after: avoid; }
.key { font-family: "DejaVu Sans Mono", monospace; font-size: 7.5pt; }
figure.chart { margin: 2mm 0; break-inside: avoid; page-break-inside: avoid; text-align: center; }
figure.chart svg { width: 100%; max-width: 160mm; height: auto; max-height: 95mm; }
figure.chart figcaption { text-align: left; font-size: 8.5pt; }
.warnings li { color: #6b3d00; }
section#appendix[data-appendix="full"] { break-before: page; page-break-before: always; }
.input-groups { columns: 2; column-gap: 4mm; }
.input-groups h3 { margin-top: 1.5mm; }
@media screen { body { box-shadow: 0 0 4mm #bbb; margin-top: 4mm; margin-bottom: 4mm; } }
@media print { body { padding: 0; max-width: none; } details#result-json { display: none; } }
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

std::string Scaled(double si, const Display& d) {
  return std::isnan(si) ? "unknown" : Significant(si * d.per_si);
}

/// The rows to show: all when they fit, else the binding, the failed and the largest ratios.
std::vector<const SummaryRow*> Shown(const std::vector<SummaryRow>& rows, std::size_t max_rows) {
  std::vector<const SummaryRow*> shown;
  for (const SummaryRow& row : rows) shown.push_back(&row);
  if (rows.size() <= max_rows) return shown;
  const auto rank = [](const SummaryRow* r) {
    return r->binding ? 3.0 : (r->counted && !r->passed ? 2.0 : 0.0) + std::clamp(r->ratio, 0.0, 1.0) / 2.0;
  };
  std::stable_sort(shown.begin(), shown.end(), [&](const SummaryRow* a, const SummaryRow* b) { return rank(a) > rank(b); });
  shown.resize(max_rows);
  std::sort(shown.begin(), shown.end());  // back to the summary's order
  return shown;
}

void WriteLimitRows(std::string& out, const ResultSummary& s) {
  OpenTable(out, {{"case", 28}, {"quantity", 14}, {"value", 10}, {"unit", 6}, {"binding criterion", 14},
                  {"law", 7}, {"validity", 9}, {"note", 12}});
  for (const LimitRow& row : s.limits) {
    out += "<tr>";
    Cell(out, row.target);
    Cell(out, row.quantity);
    const bool none = !(row.value > 0.0);
    Cell(out, none ? "none (no safe value)" : std::isinf(row.value) ? "not limited" : Significant(row.value),
         none ? "num bad" : "num");
    Cell(out, row.unit, "unit");
    Cell(out, row.binding_criterion);
    Cell(out, row.law);
    Cell(out, row.validity);
    Cell(out, row.note);
    out += "</tr>\n";
  }
  out += "</tbody></table>\n";
}

}  // namespace

void WriteRows(std::string& out, const ResultSummary& s, std::size_t max_rows) {
  if (s.kind == ResultSummary::Kind::kLimits) {
    WriteLimitRows(out, s);
    return;
  }
  const std::vector<const SummaryRow*> shown = Shown(s.rows, max_rows);
  OpenTable(out, {{"target", 17}, {"criterion", 12}, {"value", 9}, {"limit", 9}, {"derated limit", 9},
                  {"unit", 6}, {"ratio", 7}, {"margin", 8}, {"result", 9}, {"law, validity", 14}},
            "rows");
  for (const SummaryRow* row : shown) {
    const Display unit = DisplayOf(row->criterion, row->unit);
    out += row->binding ? "<tr class=\"binding\">" : "<tr>";
    Cell(out, row->target);
    Cell(out, row->criterion + (row->part == CriterionPart::kDesignRule ? " (design rule)" : ""));
    Cell(out, Scaled(row->value, unit), "num");
    Cell(out, Scaled(row->limit, unit), "num");
    Cell(out, Scaled(row->derated_limit, unit), "num");
    Cell(out, unit.unit.empty() || unit.unit == "1" ? "-" : std::string(unit.unit), "unit");
    Cell(out, std::isfinite(row->ratio) ? Significant(row->ratio) : "—", "num");
    Cell(out, FormatPercent(row->margin), "num");
    if (!row->counted && row->criterion == "not judged") Cell(out, "not judged");  // audit's exposure zones
    else if (!row->counted) Cell(out, row->passed ? "reported (passes)" : "reported (fails)");
    else Cell(out, std::string(SafeWord(row->passed)) + (row->binding ? ", governs" : ""), row->passed ? "ok" : "bad");
    std::string law = row->law.empty() ? "bare" : row->law;
    if (!row->validity.empty()) law += ", " + row->validity;
    if (!row->note.empty()) law += "; " + row->note;
    Cell(out, law);
    out += "</tr>\n";
  }
  out += "</tbody></table>\n";
  if (shown.size() < s.rows.size()) {
    out += "<p>" + std::to_string(shown.size()) + " of " + std::to_string(s.rows.size()) +
           " rows: the governing one, every failed one and the largest ratios; every row is in the appendix and the "
           "result's JSON.</p>\n";
  }
}

void WriteMaterial(std::string& out, const ResultSummary& summary) {
  const std::string& name = summary.covering.material;
  const materials::Material* m = summary.covering.present && !name.empty() ? materials::Catalog::BuiltIn().Find(name)
                                                                            : nullptr;
  if (!m) {
    out += summary.covering.present && !name.empty()
               ? "<p>Not in the built-in catalog: its datasheet is the catalog file the run read (Provenance).</p>\n"
               : "<p>No catalog material: the covering is given by its modulus (or there is none), so there is no "
                 "datasheet to cite.</p>\n";
    return;
  }
  out += "<p>The built-in catalog's entry for <b>";
  Escape(out, name);
  out += "</b> (<code>covopt materials show NAME</code>); a run with <code>--catalog</code> used that file's entry "
         "(its SHA-256 under Provenance).</p>\n";
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
  row("crush behaviour", std::string(materials::ToString(m->crush_behaviour)));
  row("compressive strength", m->compressive_strength_Pa ? Reading(*m->compressive_strength_Pa, {"Pa", "MPa", 1e-6}) : "");
  row("strength source", m->strength_source);
  out += "</tbody></table>\n";
}

void WriteModels(std::string& out, const ResultSummary& s, const Json& j) {
  const auto has = [&](std::initializer_list<std::string_view> names) {
    for (const SummaryRow& row : s.rows) {
      for (const std::string_view n : names) {
        if (row.criterion == n) return true;
      }
    }
    return false;
  };
  std::set<Model> models;
  if (has({"laceration", "contusion", "fracture"})) models.insert(Model::kHead);
  if (has({"force", "pressure"})) models.insert(Model::kBody);
  if (s.covering.law == "foam") models.insert(Model::kFoam);
  if (s.kind == ResultSummary::Kind::kLimits) models.insert(Model::kSpeedLimit);
  if (s.command == "robot --trajectory" || s.command == "audit" || s.command == "retime") {
    models.insert(Model::kTrajectory);
  }
  if (s.command == "audit" || s.command == "retime") models.insert(Model::kAudit);
  if (s.command == "retime") models.insert(Model::kRetime);
  if (Find(j, "uncertain_inputs")) models.insert(Model::kRobust);
  for (const ModelText& m : ModelTexts()) {
    if (!models.count(m.model)) continue;
    out += "<h3>";
    Escape(out, m.title);
    out += "</h3>\n<ul class=\"compact\">\n";
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
  return out;
}

}  // namespace covopt::report::internal::html
