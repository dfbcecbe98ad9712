#include "audit.hpp"

#include "audit_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ostream.h>

#include "body_region_options.hpp"
#include "covopt/audit/assemble.hpp"
#include "covopt/audit/audit.hpp"
#include "covopt/audit/summary.hpp"
#include "covopt/chart/region_charts.hpp"
#include "covopt/optim/input_warnings.hpp"
#include "covopt/report/audit_json.hpp"
#include "covopt/report/csv.hpp"
#include "covopt/report/summary_json.hpp"
#include "covopt/robot/surface.hpp"
#include "design_flag_ranges.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "plot.hpp"
#include "quantity.hpp"
#include "report_option.hpp"
#include "scene_fields.hpp"
#include "output_options.hpp"
#include "rule_options.hpp"

namespace covopt::cli {
namespace {

/// The regions the text shows per link (all of them in --json and --csv).
constexpr std::size_t kRegionsShownPerLink = 3;

constexpr std::string_view kFooter = R"(For every sample of the trajectory and every point sampled on the robot's surface
(the URDF's <collision> spheres, cylinders, capsules and boxes, or a surface file):
the point's velocity, the reflected mass along it, and each exposed body region's
largest safe speed at that mass on that link's covering (ISO/TS 15066:2016 Table
A.2, transient; the head under Park et al. 2011). The ratio v / (SF v_max) per
link and region at its governing sample and point, the program's safe speed scale
(the minimum over links and regions of v_max / v) and the link and region that
set it. --design: per link, the thinnest catalog covering that makes the program
safe at full speed, checked again.

Default regions: every region ISO/TS 15066 permits in a transient contact, and the
head. The covering of every link: --covering-thickness with --material NAME or
--covering-modulus; per link from --link-coverings FILE.toml ([[link]] name,
material or modulus (and poisson), thickness; docs/guide/audit.md). A covering on a
flat face (a box's face, a cylinder's end) needs --flat-face-radius.

Exit codes: 0 an answer (safe, unsafe or at rest); 1 an output could not be
written; 2 bad input.)";


/// Everything the outputs need: the assembled audit (covopt::audit::AssembleAudit).
struct AuditRun {
  explicit AuditRun(ResolvedAuditInputs r) : assembled(std::move(r.assembled)), inputs(std::move(r.inputs)) {}
  audit::AssembledAudit assembled;
  ResultInputs inputs;  ///< the scene file's [report] table
  std::optional<PlotFormat> plot_format;
};

/// The checks of the audit's output flags.
std::optional<PlotFormat> CheckOutputFlags(const AuditCommandOptions& o) {
  if (o.csv_file && o.csv_file->empty()) throw InputError("--csv: empty file name");
  if (o.samples_csv && o.samples_csv->empty()) throw InputError("--samples-csv: empty file name");
  const int to_stdout = (o.json ? 1 : 0) + (o.csv_file && *o.csv_file == "-" ? 1 : 0) +
                        (o.samples_csv && *o.samples_csv == "-" ? 1 : 0);
  if (to_stdout > 1) {
    throw InputError("--json, --csv - and --samples-csv - each print to stdout; give only one of them, the others a "
                     "file name");
  }
  if (!o.plot_file) return std::nullopt;
  std::optional<PlotFormat> plot_format = PlotFormatFor(*o.plot_file);
  if (!plot_format) {
    throw InputError(fmt::format("--plot: cannot tell the format of '{}'; name the file *.png or *.svg", *o.plot_file));
  }
  return plot_format;
}

std::string RatioText(double ratio) { return std::isfinite(ratio) ? fmt::format("{:.3f}", ratio) : "no safe speed"; }

std::string ScaleText(double scale) { return std::isfinite(scale) ? fmt::format("{:.4g}", scale) : "-"; }

void PrintText(std::ostream& out, const AuditCommandOptions& o, const AuditRun& run, const audit::AuditResult& r) {
  const audit::AuditSetup& setup = run.assembled.setup;
  PrintAuditInputs(out, o, run.assembled, r.sample_count);
  if (!r.exposure_zones.empty()) {
    fmt::print(out, "Exposure   {} zone{} ({}); {} of {} link × region cells not judged (Scope lists the zones)\n",
               r.exposure_zones.size(), r.exposure_zones.size() == 1 ? "" : "s", *o.exposure, r.not_judged_cells,
               r.cells.size());
  }
  fmt::print(out, "Verdict    {}\n{}", r.message, report::SummaryText(audit::SummarizeAudit(setup, r), 11));
  if (r.limiting_cell) {
    const audit::AuditCell& c = r.cells[*r.limiting_cell];
    fmt::print(out, "Limit      safe speed scale {}: {} against {} ({}) at t = {:.4g} s, point {} m (base frame)\n",
               ScaleText(r.safe_speed_scale), r.links[c.link], r.regions[c.region], c.binding_name(),
               c.time_s, PointText(c.point_in_base_m));
  }

  fmt::print(out, "\nPer link, the {} regions with the largest ratio (all {} in --json and --csv)\n",
             kRegionsShownPerLink, r.regions.size());
  fmt::print(out, "  {:<14} {:<34} {:>8}  {:<16} {:>8}  {:<26} {:>9} {:>9} {:>9} {:>8}\n", "link", "region", "ratio",
             "binds", "t [s]", "point, base frame [m]", "speed m/s", "mass kg", "max safe", "scale");
  for (std::size_t l = 0; l < r.links.size(); ++l) {
    std::vector<std::size_t> order(r.regions.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return r.cell(l, a).governing_ratio > r.cell(l, b).governing_ratio;
    });
    if (order.empty() || !r.cell(l, order.front()).sample) {
      const std::string& why = order.empty() ? std::string() : r.cell(l, order.front()).not_judged;
      fmt::print(out, "  {:<14} {}\n", r.links[l], why.empty() ? "(never moves: limits nothing)" : "(not judged: " + why + ")");
      continue;
    }
    for (std::size_t k = 0; k < std::min(kRegionsShownPerLink, order.size()); ++k) {
      const audit::AuditCell& c = r.cell(l, order[k]);
      if (!c.sample) break;  // not judged (exposure zones): the scope and warnings say so
      fmt::print(out, "  {:<14} {:<34} {:>8}  {:<16} {:>8.4g}  {:<26} {:>9.4g} {:>9.4g} {:>9.4g} {:>8}\n",
                 k == 0 ? r.links[l] : "", r.regions[c.region], RatioText(c.governing_ratio),
                 c.binding_name(), c.time_s, PointText(c.point_in_base_m), c.speed_m_per_s, c.reflected_mass_kg,
                 c.max_safe_speed_m_per_s, ScaleText(c.speed_scale));
    }
  }
  if (!r.link_designs.empty()) {
    fmt::print(out, "\nPer-link design: the thinnest catalog covering safe at full speed (checked again)\n");
    fmt::print(out, "  {:<14} {:<28} {:>10} {:>8}  {}\n", "link", "material", "thickness", "ratio", "");
    for (const audit::AuditLinkDesign& d : r.link_designs) {
      fmt::print(out, "  {:<14} {:<28} {:>10} {:>8}  {}\n", r.links[d.link], d.material ? d.material->name : "-",
                 d.thickness_m ? FormatQuantity(*d.thickness_m, QuantityKind::kLength) : "-",
                 d.thickness_m ? RatioText(d.governing_ratio) : "-", d.message);
    }
  }
  fmt::print(out, "\nScope\n");
  for (const std::string& s : r.scope) fmt::print(out, "  {}\n", s);
  std::vector<std::string> warnings = run.assembled.input_warnings;
  warnings.insert(warnings.end(), r.warnings.begin(), r.warnings.end());
  if (warnings.empty()) fmt::print(out, "\nWarnings: none\n");
  for (const std::string& w : warnings) fmt::print(out, "Warning: {}\n", w);
  const std::vector<std::string> files = [&] {
    std::vector<std::string> f;
    for (const auto& file : {o.csv_file, o.samples_csv, o.plot_file}) {
      if (file && *file != "-") f.push_back(*file);
    }
    return f;
  }();
  if (!files.empty()) fmt::print(out, "Wrote      {}\n", fmt::join(files, ", "));
}

std::string CellsCsv(const audit::AuditResult& r) {
  std::string text;
  report::AppendCsvRecord(text, report::AuditCellColumns());
  for (const audit::AuditCell& cell : r.cells) report::AppendCsvRecord(text, report::AuditCellCsvCells(r, cell));
  return text;
}

}  // namespace

void SetupAudit(CLI::App* sub, AuditCommandOptions& options) {
  sub->footer(std::string(kFooter));
  AddAuditInputOptions(*sub, options, "per link, the thinnest catalog covering that makes the program safe at full speed");
  AddJsonFlag(*sub, options.json);
  AddOutputFileOption(*sub, "--csv", options.csv_file, "write one row per link x region ('-': to stdout)", "FILE.csv|-");
  AddOutputFileOption(*sub, "--samples-csv", options.samples_csv, "stream one row per sample: per link its largest ratio and region ('-': to stdout; memory does not "
                  "grow with the trajectory)", "FILE.csv|-");
  AddOutputFileOption(*sub, "--plot", options.plot_file, "heat map of the governing ratio over time and links (gnuplot)", "FILE.png|FILE.svg");
  AddReportOption(*sub, options.report);
}

int RunAudit(const AuditCommandOptions& o, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "audit");
  std::optional<AuditRun> resolved;
  try {
    const std::optional<PlotFormat> plot_format = CheckOutputFlags(o);
    resolved.emplace(ResolveAuditInputs(o));
    resolved->plot_format = plot_format;
  } catch (const std::invalid_argument& e) {  // InputError and the library's own checks
    return errors.BadInput(e.what());
  }
  AuditRun& run = *resolved;
  try {
    if ((o.plot_file || o.report.file) && !FindOnPath("gnuplot")) return errors.Failed(kGnuplotMissing);
    // The per-sample stream: written as the audit runs (a file through OutputFile).
    std::optional<OutputFile> stream_file;
    std::vector<std::string> link_names;
    for (const robot::LinkSurface& l : run.assembled.setup.surface.links) link_names.push_back(l.link);
    const std::vector<std::string> region_names = audit::AuditRegionNames(run.assembled.setup);
    if (o.samples_csv) {
      std::string header;
      report::AppendCsvRecord(header, report::AuditSampleColumns(link_names));
      if (*o.samples_csv != "-") {
        stream_file.emplace(*o.samples_csv);
        stream_file->Write(header);
      } else {
        out << header;
      }
      run.assembled.options.keep_ratio_over_time = o.plot_file || o.report.file;  // the heat map's data
      run.assembled.options.on_sample = [&](const audit::AuditSampleRow& row) {
        std::string line;
        report::AppendCsvRecord(line, report::AuditSampleCsvCells(row, region_names));
        if (stream_file) stream_file->Write(line);
        else out << line;
      };
    }
    audit::AuditResult result;
    try {
      result = audit::Audit(run.assembled.setup, run.assembled.trajectory, run.assembled.options);
    } catch (const std::invalid_argument& e) {
      return errors.BadInput(e.what());
    }
    if (stream_file) stream_file->Commit();
    if (o.csv_file && *o.csv_file != "-") WriteFileAtomically(*o.csv_file, CellsCsv(result));
    // The heat map, made once for --plot and --report.
    std::optional<chart::GnuplotChart> heat_map_chart;
    const auto heat_map = [&]() -> const chart::GnuplotChart& {
      if (!heat_map_chart) {
        heat_map_chart = chart::AuditHeatMap(result, run.assembled.setup.rule.safety_factor,
                                              std::filesystem::path(*o.trajectory).filename().string());
      }
      return *heat_map_chart;
    };
    if (o.plot_file) RunGnuplot(*o.plot_file, heat_map());
    if (o.json || o.report.file) {
      PrintAndReport(out, o.json, report::AuditJson(run.assembled.setup, result, run.assembled.input_warnings), o.run, o.report, run.inputs,
                     report::ReportKind::kAudit, [&] {
                       return std::vector{chart::AuditRegionMap(result, run.assembled.setup.rule.safety_factor), heat_map()};
                     });
    }
    if (!o.json && o.csv_file && *o.csv_file == "-") {
      out << CellsCsv(result);
    } else if (!o.json && !(o.samples_csv && *o.samples_csv == "-")) {
      PrintText(out, o, run, result);
    }
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace covopt::cli
