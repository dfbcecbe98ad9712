#include "body_region_commands.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/core/quantity.hpp"
#include "covopt/report/body_contact_json.hpp"
#include "covopt/report/csv.hpp"
#include "covopt/scene_file/targets.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "report_option.hpp"

namespace covopt::cli {
namespace {

using optim::BodyRegionJudgement;

std::string Newtons(double n) { return fmt::format("{:.4g} N", n); }
std::string NPerCm2(double pa) { return fmt::format("{:.4g} N/cm²", pa * 1e-4); }
std::string Mm(double m) { return fmt::format("{:.3g} mm", m * 1e3); }
std::string Mass(double kg) { return std::isinf(kg) ? std::string("fixed") : fmt::format("{:.4g} kg", kg); }
std::string Percent(double fraction) { return fmt::format("{:.1f} %", 100.0 * fraction); }

/// "radius 15 mm; covering 15 mm, 27.6 MPa, ν 0.25 (material)" or "flat; bare".
std::string RobotSurface(const BodyContactScene& s, const std::optional<std::string>& material) {
  std::string text = std::isinf(s.robot_radius_m) ? std::string("flat robot") : "robot radius " + Mm(s.robot_radius_m);
  if (s.has_covering()) {
    text += fmt::format("; covering {}, {}, ν {:g}{}", Mm(s.covering.thickness_m),
                        FormatQuantity(s.covering.youngs_modulus_Pa, QuantityKind::kModulus), s.covering.poisson_ratio,
                        material ? " (" + *material + ")" : std::string());
  } else {
    text += "; bare (no covering)";
  }
  return text;
}

/// "100 m/s² after 5 ms, while the robot still moves forward (time path)".
std::string BrakingText(const BodyContactScene& s) {
  return fmt::format("{} after {}, while the robot still moves forward (the time path answers)",
                     FormatQuantity(s.braking_m_per_s2, QuantityKind::kAcceleration),
                     FormatQuantity(s.reaction_delay_s, QuantityKind::kTime));
}

std::string ContactText(const BodyRegionPlan& regions) {
  return fmt::format("{} contact; bare robot's contact area {}", ToString(regions.contact),
                     regions.contact_area_m2 > 0.0 ? FormatQuantity(regions.contact_area_m2, QuantityKind::kArea)
                                                   : std::string("not given"));
}

std::optional<std::string> MaterialName(const SimulationPlan& plan) {
  if (plan.covering_material && plan.scene.covering.thickness_m > 0.0) return plan.covering_material->name;
  return std::nullopt;
}

/// "ok" or "EXCEEDED" for a ratio under the safety factor.
std::string_view Mark(double ratio, double sf) { return sf * ratio <= 1.0 ? "ok" : "EXCEEDED"; }

/// The verdict block of one judgement (simulate; optimize's recommendation).
void PrintJudgement(std::ostream& out, const BodyRegionJudgement& v, double sf, std::string_view indent) {
  const BodyContactResult& c = v.contact;
  fmt::print(out, "{}{:<12} {:<12} limit {:<12} ratio {:.3f}  {}\n", indent, "force", Newtons(c.peak_force_N),
             Newtons(v.limits.force_N), v.force_ratio, Mark(v.force_ratio, sf));
  if (v.pressure_ratio && c.peak_pressure_Pa) {
    fmt::print(out, "{}{:<12} {:<12} limit {:<12} ratio {:.3f}  {}\n", indent, "pressure", NPerCm2(*c.peak_pressure_Pa),
               NPerCm2(v.limits.pressure_Pa), *v.pressure_ratio, Mark(*v.pressure_ratio, sf));
  } else {
    fmt::print(out, "{}{:<12} not evaluated (no --contact-area); limit {}\n", indent, "pressure",
               NPerCm2(v.limits.pressure_Pa));
  }
  if (c.covering_deflection_m > 0.0 || c.fully_compressed) {
    fmt::print(out, "{}{:<12} {} of the travel{}  ratio {:.3f}  {}\n", indent, "compression", Percent(v.compression_ratio),
               c.fully_compressed ? " (fully compressed)" : "", v.compression_ratio,
               c.fully_compressed ? std::string_view("EXCEEDED") : Mark(v.compression_ratio, sf));
  }
  if (v.crush_check == optim::CrushCheck::kChecked) {
    fmt::print(out, "{}{:<12} ratio {:.3f} of the compressive strength  {}\n", indent, "crush", v.crush_ratio,
               Mark(v.crush_ratio, sf));
  } else if (v.crush_check != optim::CrushCheck::kNoMaterial) {
    fmt::print(out, "{}{:<12} {}\n", indent, "crush", optim::ToString(v.crush_check));
  }
}

std::string VerdictWord(const BodyRegionJudgement& v) {
  return fmt::format("{}: governed by {} (ratio {:.3f}, margin {})", v.admissible ? "safe" : "NOT SAFE",
                     optim::ToString(v.governing), v.governing_ratio, Percent(v.margin));
}

/// The head's `simulate`, as the command prints it (text or JSON), without the body flags.
int RunHead(const SimulateOptions& options, std::ostream& out, std::ostream& err, bool json) {
  SimulateOptions head = options;
  head.body = {};
  head.json = json;
  head.run.reset();          // its object is nested in the regions' one, which carries the provenance
  head.report_file.reset();  // and the report is the regions' one
  return RunSimulate(head, out, err);
}

}  // namespace

int RunBodyRegionSimulate(const SimulateOptions& options, const BodyRegionPlan& regions, std::ostream& out,
                          std::ostream& err) {
  const CommandErrors errors(err, "simulate");
  SimulationPlan plan;
  try {
    if (options.sensitivities || options.uncertainty.samples || !options.uncertainty.distributions.empty()) {
      throw InputError(fmt::format("{} is computed for the head's model only, not with --body-region",
                                   options.sensitivities ? "--sensitivities" : options.uncertainty.samples ? "--samples"
                                                                                                            : "--distribution"));
    }
    plan = ResolveSimulation(options);
    CheckBodyRegionScene(regions, plan);
  } catch (const InputError& e) {
    return errors.BadInput(e.what());
  }
  const BodyContactScene scene = BodyContactSceneOf(plan.scene, regions);
  const optim::BodyRegionOptions rule = BodyRegionOptionsOf(plan, false, false);
  const double sf = plan.safety_factor;
  std::vector<BodyRegionJudgement> judgements;
  std::vector<std::optional<BodyContactResult>> time_paths;
  try {
    for (const materials::BodyLimits& limits : regions.IsoLimits()) {
      // A braking robot has only the time path: --method exact is refused (by Solve), and the
      // judgement itself is the time path's, with --method/--rtol/--max-steps.
      if (scene.robot_brakes() && plan.solve.path == PathChoice::kExact) {
        (void)Solve(optim::WithRegion(scene, limits), plan.solve);
      }
      judgements.push_back(optim::JudgeBodyContact(scene, limits, rule, plan.solve.time_path));
      if (!judgements.back().contact.ok()) {
        const BodyContactResult& failed = judgements.back().contact;
        return errors.Failed(fmt::format("the time path failed on {} ({}): {}", limits.region->name,
                                         ToString(failed.status), failed.message));
      }
      if (plan.solve.path == PathChoice::kTimePath && !scene.robot_brakes()) {
        BodyContactResult timed = Solve(optim::WithRegion(scene, limits), plan.solve);
        if (!timed.ok()) {
          return errors.Failed(fmt::format("the time path failed on {} ({}): {}", limits.region->name,
                                           ToString(timed.status), timed.message));
        }
        time_paths.emplace_back(std::move(timed));
      } else {
        time_paths.emplace_back();
      }
    }
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(AttributeError(e.what(), plan));
  }
  std::vector<std::string> warnings = InputWarnings(plan);
  warnings.insert(warnings.end(), regions.notes.begin(), regions.notes.end());
  if (const auto note = ContactAreaNote(regions, plan.scene, false)) warnings.push_back(*note);
  // The time path's self-check (a braking robot's judgement is its time path), per region.
  for (std::size_t i = 0; i < judgements.size(); ++i) {
    for (std::string& w : report::TimePathWarnings(judgements[i], time_paths[i] ? &*time_paths[i] : nullptr)) {
      warnings.push_back(std::move(w));
    }
  }

  std::optional<std::string> head_text;
  if (regions.has_head()) {
    std::ostringstream head_out;
    const int code = RunHead(options, head_out, err, plan.json);
    if (code != 0) return code;
    head_text = head_out.str();
  }
  if (plan.json || options.report_file) {
    try {
      PrintAndReport(out, plan.json,
                     report::BodyContactSimulationJson(scene, MaterialName(plan), judgements, sf, head_text, warnings),
                     options.run, options.report_file, report::ReportKind::kSimulate, nullptr);
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (!plan.json) {
    fmt::print(out, "Robot        {} at {:g} m/s; {}\n", Mass(scene.robot_mass_kg), scene.speed_m_per_s,
               RobotSurface(scene, MaterialName(plan)));
    fmt::print(out, "Contact      {}\n", ContactText(regions));
    if (scene.robot_brakes()) fmt::print(out, "Braking      {}\n", BrakingText(scene));
    if (sf != 1.0) fmt::print(out, "Safety       factor {:g}: each ratio must stay <= {:.4g}\n", sf, 1.0 / sf);
    std::size_t iso = 0;
    for (const BodyTarget& target : regions.targets) {
      out << '\n';
      if (target.is_head()) {
        fmt::print(out, "Head ({})\n", HeadCriteriaName());
        out << *head_text;
        continue;
      }
      const BodyRegionJudgement& v = judgements[iso];
      const BodyContactResult& c = v.contact;
      fmt::print(out, "Body region  {}: {}, {} contact\n", target.Name(), v.limits.area->title, ToString(v.limits.contact));
      fmt::print(out, "  Region     k_H {}, m_H {}; reduced mass {}\n",
                 FormatQuantity(v.limits.stiffness_N_per_m(), QuantityKind::kStiffness),
                 Mass(v.limits.effective_mass_kg()), Mass(c.reduced_mass_kg));
      std::string peaks = fmt::format("force {}; pressure {}", Newtons(c.peak_force_N),
                                      c.peak_pressure_Pa ? NPerCm2(*c.peak_pressure_Pa)
                                                         : std::string("not evaluated (no --contact-area)"));
      if (c.peak_pressure_Pa && c.contact_radius_m > 0.0) peaks += fmt::format(" (Hertz, contact radius {})", Mm(c.contact_radius_m));
      fmt::print(out, "  Peaks      {}\n", peaks);
      fmt::print(out, "             covering deflection {} (compression {}{}); body deflection {}; energy {:.4g} J{}\n",
                 Mm(c.covering_deflection_m), Percent(v.compression_ratio),
                 c.fully_compressed ? ", fully compressed" : "", Mm(c.body_deflection_m), c.energy_transferred_J,
                 scene.robot_brakes()
                     ? fmt::format(" (unbraked ½ mu v² = {:.4g} J); {}", 0.5 * c.reduced_mass_kg *
                                                                                             scene.speed_m_per_s *
                                                                                             scene.speed_m_per_s,
                                   c.method)
                     : std::string());
      if (time_paths[iso]) {
        const BodyContactResult& t = *time_paths[iso];
        fmt::print(out, "  Time path  force {} ({}); relative difference to the exact path {:.2g}; energy residual {:.2g} (self-check)\n",
                   Newtons(t.peak_force_N), t.method, std::abs(t.peak_force_N - c.peak_force_N) / c.peak_force_N,
                   t.energy_residual.value_or(0.0));
      }
      fmt::print(out, "  Verdicts\n");
      PrintJudgement(out, v, sf, "    ");
      fmt::print(out, "  Verdict    {}\n", VerdictWord(v));
      fmt::print(out, "  Scope      {}\n", v.scope);  // begins with the limits' Describe()
      ++iso;
    }
    if (!warnings.empty()) out << '\n';
    for (const std::string& w : warnings) fmt::print(out, "Warning: {}\n", w);
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

int RunBodyRegionSpeedLimit(const SpeedLimitCommandOptions& options, const BodyRegionPlan& regions,
                            std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "speed-limit");
  SpeedLimitPlan plan;
  try {
    if (options.solve_for && *options.solve_for == "mass") {
      throw InputError("--solve-for mass with --body-region: the body-region table solves for the speed; drop one");
    }
    if (options.plot_file) throw InputError("--plot with --body-region: the table has no chart; drop --plot");
    plan = ResolveSpeedLimit(options);
    // A braking robot's limits are bracketed on the time path, which --method/--rtol/--max-steps set.
    if (options.oracle.given() && !plan.coverings.front().scene.robot_brakes()) {
      throw InputError("--oracle/--method/--rtol with --body-region: the body-region limits are in closed form on the "
                       "energy balance; drop them");
    }
    for (const SimulationPlan& covering : plan.coverings) {
      if (!covering.ranges.empty()) {
        throw InputError(fmt::format("{} '{}': scene ranges (uncertain inputs) are not taken with --body-region",
                                     covering.ranges.front().source, covering.ranges.front().text));
      }
      CheckBodyRegionScene(regions, covering);
    }
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(e.what());
  }

  const std::vector<materials::BodyLimits> iso = regions.IsoLimits();
  std::vector<report::BodyRegionTableRow> rows;
  const std::string head_criteria = HeadCriteriaName();
  optim::DesignRule rule;
  try {
    for (const SimulationPlan& covering : plan.coverings) {
      const optim::BodyRegionOptions body_options =
          BodyRegionOptionsOf(covering, options.allow_full_compression, options.allow_crushing);
      rule = body_options.rule;
      const std::string material = MaterialName(covering).value_or("");
      for (const double mass : plan.values) {
        BodyContactScene scene = BodyContactSceneOf(covering.scene, regions);
        scene.robot_mass_kg = mass;
        const std::vector<optim::BodyRegionSpeedLimitRow> table =
            iso.empty() ? std::vector<optim::BodyRegionSpeedLimitRow>{}
                        : optim::BodyRegionSpeedLimitTable(scene, iso, body_options, plan.options.oracle.time_path);
        // A limit the time path could not answer (a braking robot) is no answer at all: exit 1.
        for (const optim::BodyRegionSpeedLimitRow& row : table) {
          for (const optim::BodyRegionSpeedLimit* limit : {&row.bare, row.covered ? &*row.covered : nullptr}) {
            if (limit && limit->status == optim::SpeedLimitStatus::kEvaluationFailed) {
              return errors.Failed("the speed limit could not be evaluated: " + limit->message);
            }
          }
        }
        std::size_t next = 0;
        for (const BodyTarget& target : regions.targets) {
          report::BodyRegionTableRow row;
          if (target.is_head()) {
            optim::SpeedLimitOptions head_options = plan.options;
            head_options.covering_compressive_strength_Pa = CrushCheckOf(covering).compressive_strength_Pa;
            Scene head = covering.scene;
            head.robot.mass_kg = mass;
            std::optional<optim::SpeedLimit> covered;
            if (head.covering.thickness_m > 0.0) covered = optim::MaxSafeSpeed(head, head_options);
            head.covering.thickness_m = 0.0;
            head_options.covering_compressive_strength_Pa = 0.0;
            const optim::SpeedLimit bare = optim::MaxSafeSpeed(head, head_options);
            for (const optim::SpeedLimit* limit : {&bare, covered ? static_cast<const optim::SpeedLimit*>(&*covered) : nullptr}) {
              if (limit && limit->status == optim::SpeedLimitStatus::kEvaluationFailed) {
                return errors.Failed("the head's speed limit could not be evaluated: " + limit->message);
              }
            }
            row = report::HeadTableRow(mass, bare, covered, head_criteria);
          } else {
            row = report::TableRow(mass, table.at(next++));
          }
          row.material = material;
          rows.push_back(std::move(row));
        }
      }
    }
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(AttributeError(e.what(), plan.coverings.front()));
  }

  std::vector<std::string> warnings;
  for (const SimulationPlan& covering : plan.coverings) {
    for (std::string& w : InputWarnings(covering)) {
      if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(std::move(w));
    }
  }
  warnings.insert(warnings.end(), regions.notes.begin(), regions.notes.end());
  if (const auto note = scene_file::BarePressureNote(regions)) warnings.push_back(AsFlags(*note));
  const auto csv_text = [&] {
    std::string text;
    report::AppendCsvRecord(text, report::BodyRegionTableColumns());
    for (const report::BodyRegionTableRow& row : rows) report::AppendCsvRecord(text, report::BodyRegionTableCsvCells(row));
    return text;
  };
  try {
    if (plan.csv_file && *plan.csv_file != "-") WriteFileAtomically(*plan.csv_file, csv_text());
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }
  const SimulationPlan& first = plan.coverings.front();
  const BodyContactScene first_scene = BodyContactSceneOf(first.scene, regions);
  if (plan.json || options.report_file) {
    try {
      PrintAndReport(out, plan.json,
                     report::BodyRegionSpeedLimitJson(first_scene,
                                                      plan.coverings.size() == 1 ? MaterialName(first) : std::nullopt,
                                                      BodyCriterion(rule, regions.has_head()), rule.safety_factor,
                                                      rows, warnings),
                     options.run, options.report_file, report::ReportKind::kSpeedLimit, nullptr);
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (!plan.json && plan.csv_file && *plan.csv_file == "-") {
    out << csv_text();
  } else if (!plan.json) {
    fmt::print(out, "Robot      {}\n",
               plan.coverings.size() == 1 ? RobotSurface(first_scene, MaterialName(first))
                                          : fmt::format("{}; covering {} of {} materials, one block each",
                                                        std::isinf(first_scene.robot_radius_m)
                                                            ? std::string("flat robot")
                                                            : "robot radius " + Mm(first_scene.robot_radius_m),
                                                        Mm(first_scene.covering.thickness_m), plan.coverings.size()));
    fmt::print(out, "Contact    {}\n", ContactText(regions));
    if (first_scene.robot_brakes()) {
      fmt::print(out, "Braking    {}: each ISO limit bracketed on it from the unbraked one\n", BrakingText(first_scene));
    }
    fmt::print(out, "Criterion  {}\n", BodyCriterion(rule, regions.has_head()));
    fmt::print(out, "Speeds     the largest safe impact speed, bare and with the covering; 'binds' is the limit reached\n");
    std::string block;
    for (const report::BodyRegionTableRow& row : rows) {
      const std::string key = fmt::format("{}|{}", row.material, row.robot_mass_kg);
      if (key != block) {
        block = key;
        fmt::print(out, "\n{}robot mass {}\n", row.material.empty() ? "" : "Material " + row.material + ", ",
                   Mass(row.robot_mass_kg));
        fmt::print(out, "  {:<18} {:<34} {:>7} {:>8}  {:>9}  {:<16} {:>11}  {:<16} {:>7}\n", "region", "area",
                   "F_lim N", "p_lim", "bare m/s", "bare binds", "covered m/s", "covered binds", "gain");
      }
      const auto speed = [](const std::optional<double>& v, const std::string& status) {
        if (!v) return std::string("none");
        return fmt::format("{}{:.4f}", status == "safe-up-to-search-limit" ? ">=" : "", *v);
      };
      fmt::print(out, "  {:<18} {:<34} {:>7} {:>8}  {:>9}  {:<16} {:>11}  {:<16} {:>7}\n", row.region,
                 row.area.empty() ? "-" : row.area,
                 row.force_limit_N ? fmt::format("{:.0f}", *row.force_limit_N) : std::string("-"),
                 row.pressure_limit_Pa ? fmt::format("{:.0f}", *row.pressure_limit_Pa * 1e-4) : std::string("-"),
                 speed(row.bare_max_speed_m_per_s, row.bare_status), row.bare_limited_by,
                 row.has_covering ? speed(row.covered_max_speed_m_per_s, row.covered_status) : std::string("-"),
                 row.has_covering ? row.covered_limited_by : std::string("-"),
                 row.gain ? fmt::format("{:.2f}×", *row.gain) : std::string("-"));
    }
    fmt::print(out, "\nScope      (p_lim in N/cm²)\n");
    if (iso.size() <= 3) {
      for (const materials::BodyLimits& limits : iso) fmt::print(out, "  {}\n", limits.Describe());
    } else if (!iso.empty()) {
      fmt::print(out, "  ISO/TS 15066:2016 Table A.2, {} contact{}: each row's F_lim and p_lim; Table A.3's k_H and m_H\n",
                 ToString(regions.contact),
                 regions.contact == ContactType::kTransient ? " (2× quasi-static; not permitted: skull-forehead, face)"
                                                            : " (quasi-static)");
    }
    if (regions.has_head()) {
      fmt::print(out, "  head: {}\n", head_criteria);
      for (const std::string& line :
           optim::HeadVerdictScope(LimitRule(plan.options, first))) {
        fmt::print(out, "    {}\n", line);
      }
    }
    for (const std::string& w : warnings) fmt::print(out, "Warning: {}\n", w);
    if (plan.csv_file) fmt::print(out, "Wrote      {}\n", *plan.csv_file);
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

int RunBodyRegionOptimize(const OptimizeOptions& options, const optim::DesignRequest& head,
                          const std::vector<std::string>& scene_warnings, const BodyRegionPlan& regions,
                          std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "optimize");
  std::vector<std::string> input_warnings = scene_warnings;
  input_warnings.insert(input_warnings.end(), regions.notes.begin(), regions.notes.end());
  optim::BodyRegionDesignRequest request;
  try {
    const auto refuse = [](bool given, std::string_view flag, std::string_view why) {
      if (given) throw InputError(fmt::format("{} with --body-region: {}; drop it", flag, why));
    };
    refuse(options.thickness.has_value(), "--thickness", "the body-region design finds the thinnest covering");
    refuse(options.csv.has_value(), "--csv", "the body-region design has no candidate CSV");
    refuse(options.oracle_flags.given(), "--oracle/--method/--rtol", "its verdicts are in closed form");
    refuse(options.uncertainty.samples.has_value() || options.max_injury_probability.has_value() ||
               !options.uncertainty.distributions.empty(),
           "--samples/--distribution/--max-injury-probability", "the head's robust design is not combined with it");
    refuse(options.global_algorithm.has_value() || options.min_modulus.has_value() || options.max_modulus.has_value(),
           "--global/--min-modulus/--max-modulus", "it designs over the catalog's materials, not a continuous modulus");
    refuse(options.laceration_limit.has_value() || options.contusion_limit.has_value(),
           "--laceration-limit/--contusion-limit", "the head is judged by Park et al.'s limits (1 MPa, 2.52 J/cm²) here");
    if (!regions.has_head()) {
      for (const auto& [field, typed] : options.scene_values) {
        if (field != "robot.mass" && field != "robot.speed" && field != "robot.radius") {
          throw InputError(fmt::format("--{} '{}' does not apply to the ISO/TS 15066 body regions: it is an input of "
                                       "the head's model; drop it, or add --body-region head",
                                       FindSceneField(field) ? std::string(FindSceneField(field)->name) : field, typed));
        }
      }
      if (options.thresholds) throw InputError("--thresholds applies to the head's model; add --body-region head");
      if (options.head_area) throw InputError("--head-area applies to the head's model; add --body-region head");
    }
    if (std::isinf(head.scene.robot.radius_m)) {
      throw InputError("--robot-radius flat: a covering on a body region needs a finite robot radius (its Hertz contact "
                       "is sphere-on-flat); give the radius, e.g. --robot-radius 15mm");
    }
  } catch (const InputError& e) {
    return errors.BadInput(e.what());
  }
  request.scene = BodyContactSceneOf(head.scene, regions);
  request.regions = regions.IsoLimits();
  if (regions.has_head()) request.head = head.scene;
  request.materials = head.materials;
  request.rule = optim::DesignRule{head.options.safety_factor,
                                   head.options.allow_full_compression ? optim::DesignCriterion::kPaper
                                                                       : optim::DesignCriterion::kNoFullCompression,
                                   head.options.allow_crushing, head.options.allow_unknown_strength};
  request.max_thickness_m = head.options.space.max_thickness_m;
  request.thickness_step_m = head.options.thickness_step_m;
  optim::BodyRegionDesignResult result;
  try {
    result = optim::DesignForBodyRegions(request);
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(e.what());
  }
  if (options.json || options.report_file) {
    try {
      PrintAndReport(out, options.json,
                     report::BodyRegionDesignJson(request, result, BodyCriterion(request.rule, regions.has_head()),
                                                  input_warnings),
                     options.run, options.report_file, report::ReportKind::kOptimize, nullptr);
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (options.json) {
    out.flush();
    return out ? 0 : errors.Failed("cannot write the results to standard output");
  }
  const double sf = request.rule.safety_factor;
  std::string named;
  for (const BodyTarget& target : regions.targets) named += (named.empty() ? "" : ", ") + target.Name();
  fmt::print(out, "Design     the covering that lets the robot reach {:g} m/s for: {}\n", request.scene.speed_m_per_s,
             named);
  fmt::print(out, "Robot      {}, {}\n", Mass(request.scene.robot_mass_kg),
             std::isinf(request.scene.robot_radius_m) ? std::string("flat") : "radius " + Mm(request.scene.robot_radius_m));
  fmt::print(out, "Contact    {}\n", ContactText(regions));
  fmt::print(out, "Criterion  {}\n", BodyCriterion(request.rule, regions.has_head()));
  fmt::print(out, "\n{}\n", result.message);
  const auto print_head = [&](const optim::DesignScore& score) {
    fmt::print(out, "  head ({}): laceration ratio {:.3f}, contusion ratio {:.3f}{}\n", HeadCriteriaName(),
               score.laceration_ratio, score.contusion_ratio,
               score.bare() ? std::string() : fmt::format(", compression {:.3f}", score.compression_ratio));
  };
  const auto print_regions = [&](const std::vector<BodyRegionJudgement>& judgements) {
    for (const BodyRegionJudgement& v : judgements) {
      fmt::print(out, "  {} {}: {}\n", v.limits.region->name, "(" + v.limits.area->name + ")", VerdictWord(v));
      PrintJudgement(out, v, sf, "      ");
    }
  };
  if (result.recommendation) {
    const optim::BodyRegionDesignCandidate& c = result.candidates.at(*result.recommendation);
    fmt::print(out, "\nRecommended {} ({}, ν {:.2f}) at {}: every verdict at that thickness\n", c.material.name,
               FormatQuantity(c.material.youngs_modulus_Pa, QuantityKind::kModulus), c.material.poisson_ratio,
               Mm(*c.thickness_m));
    print_regions(c.regions);
    if (c.head) print_head(*c.head);
  }
  fmt::print(out, "\nBare robot at {:g} m/s: {}\n", request.scene.speed_m_per_s,
             result.bare_robot_safe ? "safe for every region named" : "NOT safe for every region named");
  print_regions(result.bare_robot);
  if (result.bare_head) print_head(*result.bare_head);
  // --top N (checked by optimize's Resolve), default 8.
  const std::size_t top = options.runners_up ? std::stoul(*options.runners_up) : 8;
  const std::size_t shown = std::min<std::size_t>(result.candidates.size(), top);
  if (shown > 0) {
    fmt::print(out, "\nCandidates (first {} of {})\n", shown, result.candidates.size());
    fmt::print(out, "  {:<3} {:<28} {:>10} {:>10} {:>9}  {}\n", "#", "material", "E", "thickness", "governing",
               "where");
    for (std::size_t i = 0; i < shown; ++i) {
      const optim::BodyRegionDesignCandidate& c = result.candidates[i];
      fmt::print(out, "  {:<3} {:<28} {:>10} {:>10} {:>9.3f}  {}\n", i + 1, c.material.name.substr(0, 28),
                 FormatQuantity(c.material.youngs_modulus_Pa, QuantityKind::kModulus),
                 c.thickness_m ? Mm(*c.thickness_m) : "> " + Mm(request.max_thickness_m), c.governing_ratio,
                 c.governing_where);
    }
  }
  fmt::print(out, "\nScope\n");
  for (const std::string& line : result.scope) fmt::print(out, "  {}\n", line);
  for (const std::string& w : input_warnings) fmt::print(out, "Warning: {}\n", w);
  for (const std::string& w : result.warnings) fmt::print(out, "Warning: {}\n", w);
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace covopt::cli
