// `covopt measure`'s JSON and text (measurement_json.hpp).
#include "covopt/report/measurement_json.hpp"

#include <cmath>
#include <string>

#include <covopt/core/measuring_device.hpp>
#include <covopt/core/number_format.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "covopt/report/body_contact_json.hpp"
#include "json_number.hpp"
#include "summary_object.hpp"

namespace covopt::report {

namespace {

using internal::Number;
using nlohmann::ordered_json;

constexpr double kPaPerNPerCm2 = 1e4;

ordered_json LayerObject(const DeviceLayer& l) {
  return {{"modulus_Pa", Number(l.modulus_Pa)},
          {"poisson_ratio", Number(l.poisson_ratio)},
          {"thickness_m", Number(l.thickness_m)},
          {"share", Number(l.share)},
          {"deflection_m", Number(l.deflection_m)},
          {"strain", Number(l.strain)},
          {"bottomed_out", l.bottomed_out},
          {"within", l.validity.within},
          {"note", l.validity.note}};
}

ordered_json DeviceObject(const optim::MeasurementPrediction& p) {
  const DeviceReading& r = p.device;
  const MeasuringDevice& d = r.device;
  const BodyContactResult& c = r.contact;
  const materials::BodyLimits& limits = p.body.limits;
  ordered_json j;
  j["name"] = d.name;
  j["spring_N_per_m"] = Number(d.spring_N_per_m);
  j["pad_shore_a"] = Number(d.pad_shore_a);
  j["pad_modulus_Pa"] = Number(r.pad.modulus_Pa);
  j["pad_modulus_source"] = std::string(kShoreAModulusSource);
  j["pad_poisson_ratio"] = Number(r.pad.poisson_ratio);
  j["pad_thickness_m"] = Number(d.pad_thickness_m);
  j["pad_thickness_assumed"] = d.pad_thickness_assumed;
  j["reduced_mass_kg"] = Number(c.reduced_mass_kg);
  j["peak_force_N"] = Number(c.peak_force_N);
  j["stiff_pad_force_N"] = Number(r.stiff_pad_force_N);
  j["peak_pressure_Pa"] = Number(c.peak_pressure_Pa);
  j["contact_radius_m"] = Number(c.contact_radius_m);
  j["fully_compressed"] = c.fully_compressed;
  j["pad"] = LayerObject(r.pad);
  j["covering"] = r.covering ? LayerObject(*r.covering) : ordered_json(nullptr);
  j["validity"] = {{"within", r.validity.within}, {"ratio", Number(r.validity.ratio)}, {"note", r.validity.note}};
  j["force"] = {{"value_N", Number(c.peak_force_N)}, {"limit_N", Number(limits.force_N)},
                {"ratio", Number(p.device_force_ratio)}};
  j["pressure"] = {{"value_Pa", Number(c.peak_pressure_Pa)}, {"limit_Pa", Number(limits.pressure_Pa)},
                   {"ratio", Number(p.device_pressure_ratio)}};
  j["admissible"] = p.device_verdict.safe();
  return j;
}

std::string VerdictWords(const Verdict& v) {
  if (v.safe()) return "safe";
  return "NOT SAFE (" + std::string(v.governing_name()) + ")";
}

std::string Cell(const std::optional<double>& value, double scale, int decimals) {
  return value ? FormatFixed(*value / scale, decimals) : std::string("-");
}

}  // namespace

std::string MeasurementJson(const BodyContactScene& scene, const std::optional<std::string>& material,
                            const optim::MeasurementPrediction& p, double safety_factor,
                            std::span<const std::string> warnings) {
  ordered_json j;
  j["scene"] = ordered_json::parse(BodyContactSceneJson(optim::WithRegion(scene, p.body.limits), material));
  j["safety_factor"] = Number(safety_factor);
  j["device"] = DeviceObject(p);
  j["body_model"] = ordered_json::parse(BodyRegionJudgementJson(p.body, safety_factor));
  j["comparison"] = {{"force_difference_N", Number(p.force_difference_N)},
                     {"force_ratio", Number(p.force_ratio)},
                     {"pressure_difference_Pa", Number(p.pressure_difference_Pa)},
                     {"pressure_ratio", Number(p.pressure_ratio)}};
  j["safe"] = p.body.admissible && p.device_verdict.safe();
  j["scope"] = p.scope;
  j["summary"] = internal::SummaryObject(optim::SummarizeMeasurement(scene, material.value_or(""), p));
  ordered_json w = ordered_json::array();
  for (const std::string& s : warnings) w.push_back(s);
  j["warnings"] = w;
  return j.dump(2);
}

std::string MeasurementText(const BodyContactScene& scene, const optim::MeasurementPrediction& p,
                            std::span<const std::string> warnings) {
  const DeviceReading& r = p.device;
  const MeasuringDevice& d = r.device;
  const materials::BodyLimits& limits = p.body.limits;
  const BodyContactResult& bc = p.body.contact;
  const BodyContactResult& dc = r.contact;
  std::string out;
  out += fmt::format("Robot        {} kg at {} m/s, radius {} mm{}\n", FormatSignificant(scene.robot_mass_kg, 4),
                     FormatSignificant(scene.speed_m_per_s, 4), FormatSignificant(scene.robot_radius_m * 1e3, 4),
                     scene.has_covering()
                         ? fmt::format(", covering {} mm (E {} MPa, ν {})", FormatSignificant(scene.covering.thickness_m * 1e3, 4),
                                       FormatSignificant(scene.covering.youngs_modulus_Pa / 1e6, 4),
                                       FormatSignificant(scene.covering.poisson_ratio, 3))
                         : std::string(", bare"));
  out += fmt::format("Device       {}: spring {} N/mm, pad {} Shore A (E {} MPa, Ruess), {} mm{}; fixed\n", d.name,
                     FormatSignificant(d.spring_N_per_m / 1e3, 4), FormatSignificant(d.pad_shore_a, 3),
                     FormatSignificant(r.pad.modulus_Pa / 1e6, 3), FormatSignificant(d.pad_thickness_m * 1e3, 3),
                     d.pad_thickness_assumed ? " (assumed)" : "");
  out += fmt::format("Body model   {} ({}), {}: k_H {} N/mm, m_H {}\n", limits.region->name, limits.area->name,
                     ToString(limits.contact), FormatSignificant(limits.stiffness_N_per_m() / 1e3, 4),
                     std::isinf(limits.effective_mass_kg()) ? std::string("fixed")
                                                            : FormatSignificant(limits.effective_mass_kg(), 4) + " kg");
  out += "\n";
  out += fmt::format("  {:<22}{:>14}{:>14}{:>10}\n", "", "device", "body model", "limit");
  out += fmt::format("  {:<22}{:>14}{:>14}{:>10}\n", "reduced mass [kg]", FormatSignificant(dc.reduced_mass_kg, 4),
                     FormatSignificant(bc.reduced_mass_kg, 4), "");
  out += fmt::format("  {:<22}{:>14}{:>14}{:>10}\n", "peak force [N]", FormatFixed(dc.peak_force_N, 1),
                     FormatFixed(bc.peak_force_N, 1), FormatFixed(limits.force_N, 0));
  out += fmt::format("  {:<22}{:>14}{:>14}{:>10}\n", "  ratio to the limit", FormatFixed(p.device_force_ratio, 3),
                     FormatFixed(p.body.force_ratio, 3), "");
  out += fmt::format("  {:<22}{:>14}{:>14}{:>10}\n", "peak pressure [N/cm²]", Cell(dc.peak_pressure_Pa, kPaPerNPerCm2, 1),
                     Cell(bc.peak_pressure_Pa, kPaPerNPerCm2, 1), FormatFixed(limits.pressure_Pa / kPaPerNPerCm2, 0));
  out += fmt::format("  {:<22}{:>14}{:>14}{:>10}\n", "  ratio to the limit", Cell(p.device_pressure_ratio, 1.0, 3),
                     Cell(p.body.pressure_ratio, 1.0, 3), "");
  out += fmt::format("  {:<22}{:>14}{:>14}{:>10}\n", "stiff pad force [N]", FormatFixed(r.stiff_pad_force_N, 1), "", "");
  out += "\n";
  out += fmt::format("Verdict      device: {}; body model: {}\n", VerdictWords(p.device_verdict), VerdictWords(p.body.verdict));
  out += fmt::format("Difference   the device reads {} N {} ({}× the body model's force){}\n",
                     FormatSignificant(std::abs(p.force_difference_N), 4), p.force_difference_N >= 0.0 ? "more" : "less",
                     FormatSignificant(p.force_ratio, 4),
                     p.pressure_ratio ? fmt::format("; pressure {}×", FormatSignificant(*p.pressure_ratio, 4))
                                      : std::string());
  out += fmt::format("Pad          deflection {} mm (strain {}); {}\n", FormatSignificant(r.pad.deflection_m * 1e3, 3),
                     FormatSignificant(r.pad.strain, 3), r.validity.within ? "within the Hertz law" : "outside the Hertz law");
  out += fmt::format("Scope        {}\n", p.scope);
  for (const std::string& w : warnings) out += fmt::format("Warning: {}\n", w);
  return out;
}

}  // namespace covopt::report
