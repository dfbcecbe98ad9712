#include "simulate.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/chart/region_charts.hpp"
#include "covopt/core/quantity.hpp"
#include "covopt/report/body_contact_json.hpp"
#include "covopt/report/csv.hpp"
#include "body_region_output.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "report_option.hpp"

namespace covopt::cli {

using namespace body_text;

namespace {

/// The head's `simulate`, as the command prints it (text or JSON), without the body flags.
int RunHead(const SimulateOptions& options, std::ostream& out, std::ostream& err, bool json) {
  SimulateOptions head = options;
  head.body = {};
  head.json = json;
  head.run.reset();          // its object is nested in the regions' one, which carries the provenance
  head.report.file.reset();  // and the report is the regions' one
  return RunSimulate(head, out, err);
}

/// The head's outputs: `text` as printed (its JSON object with --json, else its text) and
/// `object`, its JSON object for the regions' --json and report (made only when one is asked for).
int RunHeadOutputs(const SimulateOptions& options, bool json, std::ostream& err, std::optional<std::string>& text,
                   std::optional<std::string>& object) {
  for (const bool as_json : {json, true}) {
    if (as_json && !json && !options.report.file) break;  // the text alone is wanted
    std::ostringstream out;
    if (const int code = RunHead(options, out, err, as_json); code != 0) return code;
    (as_json ? object : text) = out.str();
    if (json) break;
  }
  return 0;
}

/// One ISO region's block of the table: the region, the peaks, the time path's self-check
/// (`time_path`, if computed) and the verdicts.
void PrintRegionBlock(std::ostream& out, const BodyTarget& target, const BodyRegionJudgement& v,
                      const BodyContactResult* time_path, const BodyContactScene& scene) {
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
             Mm(c.covering_deflection_m), FormatPercent(v.compression_ratio),
             c.fully_compressed ? ", fully compressed" : "", Mm(c.body_deflection_m), c.energy_transferred_J,
             scene.robot_brakes()
                 ? fmt::format(" (unbraked ½ mu v² = {:.4g} J); {}", 0.5 * c.reduced_mass_kg *
                                                                                         scene.speed_m_per_s *
                                                                                         scene.speed_m_per_s,
                               c.method)
                 : std::string());
  if (time_path) {
    const BodyContactResult& t = *time_path;
    fmt::print(out, "  Time path  force {} ({}); relative difference to the exact path {:.2g}; energy residual {:.2g} (self-check)\n",
               Newtons(t.peak_force_N), t.method, std::abs(t.peak_force_N - c.peak_force_N) / c.peak_force_N,
               t.energy_residual.value_or(0.0));
  }
  fmt::print(out, "  Verdicts\n");
  PrintJudgement(out, v, "    ");
  fmt::print(out, "  Verdict    {}\n", VerdictWord(v));
  fmt::print(out, "  Scope      {}\n", v.scope);  // begins with the limits' Describe()
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

  std::optional<std::string> head_text;  // as printed: the JSON object with --json, else the text
  std::optional<std::string> head_json;  // the report's (and --json's) object
  if (regions.has_head()) {
    if (const int code = RunHeadOutputs(options, plan.json, err, head_text, head_json); code != 0) return code;
  }
  if (plan.json || options.report.file) {
    try {
      PrintAndReport(out, plan.json,
                     report::BodyContactSimulationJson(scene, MaterialName(plan), judgements, sf, head_json, warnings),
                     options.run, options.report, plan.inputs, report::ReportKind::kSimulate,
                     [&] { return chart::BodyRegionSimulationCharts(scene, judgements, rule, MaterialName(plan)); });
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (!plan.json) {
    fmt::print(out, "Robot        {} at {:g} m/s; {}\n", Mass(scene.robot_mass_kg), scene.speed_m_per_s,
               RobotSurface(scene, MaterialName(plan)));
    fmt::print(out, "Contact      {}\n", ContactText(regions));
    if (regions.has_iso()) fmt::print(out, "Limits       {}\n", LimitTableText(regions));
    if (scene.robot_brakes()) fmt::print(out, "Braking      {}\n", BrakingText(scene));
    if (sf != 1.0) fmt::print(out, "Safety       factor {:g}: each limit derated by it (each criterion shows both)\n", sf);
    std::size_t iso = 0;
    for (const BodyTarget& target : regions.targets) {
      out << '\n';
      if (target.is_head()) {
        fmt::print(out, "Head ({})\n", HeadCriteriaName());
        out << *head_text;
        continue;
      }
      PrintRegionBlock(out, target, judgements[iso], time_paths[iso] ? &*time_paths[iso] : nullptr, scene);
      ++iso;
    }
    if (!warnings.empty()) out << '\n';
    for (const std::string& w : warnings) fmt::print(out, "Warning: {}\n", w);
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace covopt::cli
