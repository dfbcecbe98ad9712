#include "audit.hpp"

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

/// Lengths read by the audit's own flags.
constexpr QuantitySpec kSpacing{QuantityKind::kLength, false, false, robot::kMinSurfaceSpacingM,
                                robot::kMaxSurfaceSpacingM, {"mm", "cm"}, "surface spacing"};
constexpr QuantitySpec kEdgeRadius{QuantityKind::kLength, false, false, 1e-4, 0.5, {"mm", "cm"}, "box edge radius"};
constexpr QuantitySpec kFlatRadius{QuantityKind::kLength, false, false, 1e-3, 1.0, {"mm", "cm"}, "flat-face radius"};

/// Everything the outputs need: the assembled audit (covopt::audit::AssembleAudit).
struct AuditRun {
  explicit AuditRun(audit::AssembledAudit a) : assembled(std::move(a)) {}
  audit::AssembledAudit assembled;
  std::optional<PlotFormat> plot_format;
  ResultInputs inputs;  ///< the scene file's [report] table
};

double PositiveLength(const std::string& typed, const QuantitySpec& spec, const char* flag) {
  const double value = ParseQuantity(typed, spec, flag);
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(fmt::format("{} must be a length > 0 (got '{}')", flag, typed));
  }
  return value;
}

std::string CoveringText(const audit::AuditCovering& c) {
  if (!(c.covering.thickness_m > 0.0)) return "bare";
  // The law that describes it (auto: the foam law for a measured curve): each cell counts its validity.
  const bool foam = c.covering.compressive_curve && c.covering.law != CoveringLaw::kHertz;
  return fmt::format("{}{} (E {}, ν {:g}; {} law)", c.material ? c.material->name + " " : std::string(),
                     FormatQuantity(c.covering.thickness_m, QuantityKind::kLength),
                     FormatQuantity(c.covering.youngs_modulus_Pa, QuantityKind::kModulus), c.covering.poisson_ratio,
                     foam ? "foam" : "hertz");
}

/// The scene inputs an ISO region reads in an audit (the rest belong to the head's model).
bool ReadByRegions(std::string_view field) {
  return field.starts_with("covering.") || field == "robot.reaction_delay" || field == "robot.braking" ||
         field == "limits.safety_factor";
}

/// The audit's inputs as the CLI spells them, for the library's messages.
audit::AuditFieldNames FlagNames() {
  audit::AuditFieldNames n;
  n.urdf = "--urdf";
  n.surface_file = "--surface-file";
  n.trajectory = "--trajectory";
  n.link_coverings = "--link-coverings";
  n.contact = "--contact";
  n.design = "--design";
  n.design_materials = "--design-material";
  n.families = "--family";
  n.allow_unknown_strength = "--allow-unknown-strength";
  n.max_thickness = "--max-thickness";
  n.thickness_step = "--thickness-step";
  n.robot_mass = "--robot-mass";
  n.speed = "--speed";
  n.robot_radius = "--robot-radius";
  n.tool_surface = "--tool-surface";
  n.payload_surface = "--payload-surface";
  n.exposure = "--exposure";
  return n;
}

/// The checks of the flags no library input stands for: the robot model's flags audit does not
/// take, the outputs' files.
std::optional<PlotFormat> CheckFlags(const AuditCommandOptions& o) {
  const RobotModelOptions& model = o.model;
  if (!o.trajectory) throw InputError("--trajectory FILE.csv is required (the motion to audit)");
  if (!model.urdf) throw InputError("--urdf FILE is required (the robot to audit)");
  for (const auto& [typed, flag, why] :
       {std::tuple{model.joints, "--joints", "the trajectory gives each sample's joint positions"},
        std::tuple{model.point, "--point", "every point of the robot's surface is audited"},
        std::tuple{model.direction, "--direction", "each impact is along the point's motion"}}) {
    if (typed) throw InputError(fmt::format("{} '{}': not used by audit ({}); drop {}", flag, *typed, why, flag));
  }
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

/// The surface's flags.
robot::SurfaceOptions SurfaceOptionsOf(const AuditCommandOptions& o) {
  robot::SurfaceOptions surface;
  if (o.surface_spacing) surface.spacing_m = PositiveLength(*o.surface_spacing, kSpacing, "--surface-spacing");
  if (o.box_edge_radius) surface.box_edge_radius_m = PositiveLength(*o.box_edge_radius, kEdgeRadius, "--box-edge-radius");
  if (o.surface_file) {
    if (o.surface_file->empty()) throw InputError("--surface-file: empty file name");
    surface.surface_file = *o.surface_file;
  }
  return surface;
}

/// The design's flags.
void SetDesignFlags(const AuditCommandOptions& o, audit::AuditInputs& in) {
  in.design = o.design;
  in.design_materials = o.design_materials;
  in.families = o.families;
  in.allow_unknown_strength = o.allow_unknown_strength;
  if (o.max_thickness) {
    in.max_thickness_m = ParseQuantity(*o.max_thickness, quantity_specs::kCoveringThickness, "--max-thickness");
  }
  if (o.thickness_step) {
    in.thickness_step_m = ParseQuantity(*o.thickness_step, quantity_specs::kThicknessStep, "--thickness-step");
  }
}

/// The flags resolved by the groups every command shares (robot model, scene, body regions),
/// the audit assembled by the library from them and the audit's own flags.
AuditRun Resolve(const AuditCommandOptions& o) {
  const std::optional<PlotFormat> plot_format = CheckFlags(o);
  // The regions: the body-region group, default every transient region and the head.
  BodyRegionFlags body = o.scene.body;
  if (body.regions.empty()) body.regions.push_back(audit::kDefaultBodyRegions);
  const std::optional<BodyRegionPlan> regions = ResolveBodyRegions(body);
  const bool head = regions->has_head();
  const SimulationPlan plan = ResolveSimulation(o.scene);
  if (!head) {
    for (const auto& [field, source] : plan.sources) {
      if (ReadByRegions(field)) continue;
      throw InputError(fmt::format("{} from {} is an input of the head's model, which --body-region does not name; "
                                   "drop it, or add --body-region head",
                                   field, source));
    }
  }
  audit::AuditInputs in(ResolveRobotModelChain(o.model).chain, *o.model.urdf);
  in.names = FlagNames();
  in.surface = SurfaceOptionsOf(o);
  if (o.flat_face_radius) in.flat_face_radius_m = PositiveLength(*o.flat_face_radius, kFlatRadius, "--flat-face-radius");
  in.reflected_mass = o.model.reflected_mass_options();
  in.trajectory = *o.trajectory;
  in.scene = plan.scene;
  for (const char* field : {"robot.mass", "robot.speed", "robot.radius"}) {
    if (const auto typed = o.scene.scene_values.find(field); typed != o.scene.scene_values.end()) {
      in.given_robot_inputs.emplace(field, typed->second);
    }
  }
  in.regions = regions->IsoLimits();
  in.contact = regions->contact;
  in.contact_area_m2 = regions->contact_area_m2;
  in.head = head;
  in.judge = BodyRegionOptionsOf(plan, o.allow_full_compression, o.allow_crushing);
  if (o.link_coverings) in.link_coverings = *o.link_coverings;
  // The tool, the payload and the exposure zones.
  in.tool_surface = o.tool_surface;
  in.payload_surface = o.payload_surface;
  if (o.exposure) in.exposure = *o.exposure;
  SetDesignFlags(o, in);
  // The catalog, for --link-coverings and --design.
  std::optional<materials::Catalog> catalog;
  if (o.link_coverings || o.design) {
    try {
      catalog = LoadCatalog(o.scene.catalog);
    } catch (const InputError& e) {
      const std::string what = e.what();
      throw InputError(what.rfind("--", 0) == 0 ? what : "--catalog: " + what);
    }
    in.catalog = &*catalog;
  }
  in.scene_warnings = InputWarnings(plan);
  optim::AppendNewWarnings(in.scene_warnings, CrushCheckOf(plan).notes);  // the default covering is in both
  AuditRun run(audit::AssembleAudit(in));
  run.assembled.setup.keep_travel = o.scene.keep_travel;
  run.plot_format = plot_format;
  run.inputs = plan.inputs;
  if (o.design) {  // optimize's ranges, named by the flags (the library names its own fields)
    const audit::AuditDesignOptions& design = run.assembled.options.design;
    RequireMaxThickness(design.max_thickness_m, design.min_thickness_m, o.max_thickness);
    RequireThicknessStep(design.thickness_step_m, o.thickness_step);
  }
  return run;
}

std::string Point(const Eigen::Vector3d& p) { return fmt::format("({:.3f}, {:.3f}, {:.3f})", p[0], p[1], p[2]); }

std::string RatioText(double ratio) { return std::isfinite(ratio) ? fmt::format("{:.3f}", ratio) : "no safe speed"; }

std::string ScaleText(double scale) { return std::isfinite(scale) ? fmt::format("{:.4g}", scale) : "-"; }


void PrintText(std::ostream& out, const AuditCommandOptions& o, const AuditRun& run, const audit::AuditResult& r) {
  const audit::AuditSetup& setup = run.assembled.setup;
  const robot::KinematicChain& chain = setup.chain;
  std::string robot_line = fmt::format("{}: {} -> {}, {} movable joint{}", chain.robot_name(), chain.base_link(),
                                       chain.tip_link(), chain.joint_count(), chain.joint_count() == 1 ? "" : "s");
  if (const robot::Payload& payload = chain.payload(); !payload.empty()) {
    robot_line += fmt::format("; payload {:.4g} kg at {} m (tip frame)", payload.mass_kg, Point(payload.center_of_mass_m));
  }
  fmt::print(out, "Robot      {}\n", robot_line);
  const auto& times = run.assembled.trajectory.time_s;
  fmt::print(out, "Trajectory {}: {} samples, t = {:g} .. {:g} s\n", *o.trajectory, r.sample_count,
             times.empty() ? 0.0 : times.front(), times.empty() ? 0.0 : times.back());
  fmt::print(out, "Surface    {} links, {} points (spacing {}){}\n", setup.surface.links.size(),
             setup.surface.point_count(), FormatQuantity(setup.surface.spacing_m, QuantityKind::kLength),
             o.surface_file ? fmt::format(", surface file {}", *o.surface_file) : std::string());
  if (!r.exposure_zones.empty()) {
    fmt::print(out, "Exposure   {} zone{} ({}); {} of {} link × region cells not judged (Scope lists the zones)\n",
               r.exposure_zones.size(), r.exposure_zones.size() == 1 ? "" : "s", *o.exposure, r.not_judged_cells,
               r.cells.size());
  }
  fmt::print(out, "Covering   all links: {}\n", CoveringText(setup.covering));
  for (const auto& [link, covering] : setup.link_coverings) {
    fmt::print(out, "           {}: {} (--link-coverings)\n", link, CoveringText(covering));
  }
  fmt::print(out, "Regions    {} ISO/TS 15066 region{} (transient){}\n", setup.regions.size(),
             setup.regions.size() == 1 ? "" : "s", setup.head ? fmt::format(" and the head ({})", HeadCriteriaName()) : "");
  optim::DesignRule judged = setup.rule;  // the travel rule counts only with --keep-travel
  if (!setup.keep_travel) judged.criterion = optim::DesignCriterion::kPaper;
  fmt::print(out, "Criterion  {}\n", BodyCriterion(judged, setup.head.has_value()));
  if (setup.braking_m_per_s2 > 0.0) {
    fmt::print(out, "Braking    reaction delay {}, braking {}\n",
               FormatQuantity(setup.reaction_delay_s, QuantityKind::kTime),
               FormatQuantity(setup.braking_m_per_s2, QuantityKind::kAcceleration));
  }
  fmt::print(out, "Verdict    {}\n{}", r.message, report::SummaryText(audit::SummarizeAudit(setup, r), 11));
  if (r.limiting_cell) {
    const audit::AuditCell& c = r.cells[*r.limiting_cell];
    fmt::print(out, "Limit      safe speed scale {}: {} against {} ({}) at t = {:.4g} s, point {} m (base frame)\n",
               ScaleText(r.safe_speed_scale), r.links[c.link], r.regions[c.region], c.binding_name(),
               c.time_s, Point(c.point_in_base_m));
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
                 c.binding_name(), c.time_s, Point(c.point_in_base_m), c.speed_m_per_s, c.reflected_mass_kg,
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
  AddRobotModelOptions(*sub, options.model, false, "Robot model");
  // Each surface point brings its own point and direction; the trajectory its joints.
  for (const char* flag : {"--joints", "--point", "--direction"}) sub->get_option(flag)->group("");
  constexpr const char* kAudit = "Audit";
  sub->add_option("--trajectory", options.trajectory,
                  "the motion (CSV: an optional header, then time [s], the n joint positions, the n joint velocities "
                  "per line)")
      ->type_name("FILE.csv")
      ->group(kAudit);
  sub->add_option("--surface-file", options.surface_file,
                  "the surface of links whose collision geometry is a mesh (TOML: [[link]] segments, points; "
                  "robot/README.md)")
      ->type_name("FILE.toml")
      ->group(kAudit);
  sub->add_option("--surface-spacing", options.surface_spacing,
                  "the largest distance between surface points, 1 mm to 1 m (default 50mm)")
      ->type_name("LENGTH")
      ->group(kAudit);
  sub->add_option("--box-edge-radius", options.box_edge_radius,
                  "the edge radius of the URDF's boxes (required when the chain has one), e.g. 5mm")
      ->type_name("LENGTH")
      ->group(kAudit);
  sub->add_option("--flat-face-radius", options.flat_face_radius,
                  "the radius a covering is judged on at a flat point (a box's face, a cylinder's end), e.g. 20mm; "
                  "required when a covered link has one")
      ->type_name("LENGTH")
      ->group(kAudit);
  sub->add_option("--link-coverings", options.link_coverings,
                  "a covering per link (TOML: [[link]] name, material or modulus and poisson, thickness); the others "
                  "keep the covering flags'")
      ->type_name("FILE.toml")
      ->group(kAudit);
  // The tool, the payload and the exposure zones.
  sub->add_option("--tool-surface", options.tool_surface,
                  "a shape of the tool in the flange frame (repeatable): capsule:from=X,Y,Z;to=X,Y,Z;radius=R, "
                  "sphere:center=X,Y,Z;radius=R or box:center=X,Y,Z;size=X,Y,Z;edge=R[;rpy=R,P,Y]; m unless suffixed")
      ->type_name("SPEC")
      ->group(kAudit);
  sub->add_option("--payload-surface", options.payload_surface,
                  "a shape of the payload in the flange frame (repeatable; as --tool-surface), its own row 'payload'")
      ->type_name("SPEC")
      ->group(kAudit);
  sub->add_option("--exposure", options.exposure,
                  "the zones of the cell (base frame) and the body regions a person can present in each (TOML: "
                  "[[zone]] name, min_m, max_m, regions); outside them nothing is judged")
      ->type_name("FILE.toml")
      ->group(kAudit);
  AddSceneOptions(*sub, options.scene);
  AddBodyRegionOptions(*sub, options.scene.body);
  for (const char* flag : {"--robot-mass", "--speed", "--robot-radius"}) sub->get_option(flag)->group("");
  AddRuleOptions(*sub, {.safety_factor = &options.scene.safety_factor,
                        .allow_full_compression = &options.allow_full_compression,
                        .allow_crushing = &options.allow_crushing,
                        .keep_travel = &options.scene.keep_travel});
  constexpr const char* kDesign = "Design (--design)";
  sub->add_flag("--design", options.design,
                "per link, the thinnest catalog covering that makes the program safe at full speed")
      ->group(kDesign);
  AddRuleOptions(*sub, {.allow_unknown_strength = &options.allow_unknown_strength}, kDesign);
  sub->add_option("--family", options.families, "only materials of this family (repeatable)")
      ->type_name("NAME")
      ->group(kDesign);
  sub->add_option("--design-material", options.design_materials, "only this catalog material (repeatable)")
      ->type_name("NAME")
      ->group(kDesign);
  sub->add_option("--max-thickness", options.max_thickness, "the thickest covering tried (default 50mm)")
      ->type_name("LENGTH")
      ->group(kDesign);
  sub->add_option("--thickness-step", options.thickness_step, "the recommendation is rounded up to it (default 0.5mm)")
      ->type_name("LENGTH")
      ->group(kDesign);
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
    resolved.emplace(Resolve(o));
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
