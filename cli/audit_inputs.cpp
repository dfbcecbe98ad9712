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

/// Lengths read by the audit's own flags.
constexpr QuantitySpec kSpacing{QuantityKind::kLength, false, false, robot::kMinSurfaceSpacingM,
                                robot::kMaxSurfaceSpacingM, {"mm", "cm"}, "surface spacing"};
constexpr QuantitySpec kEdgeRadius{QuantityKind::kLength, false, false, 1e-4, 0.5, {"mm", "cm"}, "box edge radius"};
constexpr QuantitySpec kFlatRadius{QuantityKind::kLength, false, false, 1e-3, 1.0, {"mm", "cm"}, "flat-face radius"};

double PositiveLength(const std::string& typed, const QuantitySpec& spec, const char* flag) {
  const double value = ParseQuantity(typed, spec, flag);
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(fmt::format("{} must be a length > 0 (got '{}')", flag, typed));
  }
  return value;
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

/// The checks of the input flags no library input stands for: the robot model's flags the
/// audit does not take.
void CheckInputFlags(const AuditInputOptions& o) {
  const RobotModelOptions& model = o.model;
  if (!o.trajectory) throw InputError("--trajectory FILE.csv is required (the motion)");
  if (!model.urdf) throw InputError("--urdf FILE is required (the robot)");
  for (const auto& [typed, flag, why] :
       {std::tuple{model.joints, "--joints", "the trajectory gives each sample's joint positions"},
        std::tuple{model.point, "--point", "every point of the robot's surface is audited"},
        std::tuple{model.direction, "--direction", "each impact is along the point's motion"}}) {
    if (typed) throw InputError(fmt::format("{} '{}': not used by audit ({}); drop {}", flag, *typed, why, flag));
  }
}


/// The surface's flags.
robot::SurfaceOptions SurfaceOptionsOf(const AuditInputOptions& o) {
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
void SetDesignFlags(const AuditInputOptions& o, audit::AuditInputs& in) {
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


}  // namespace

std::string PointText(const Eigen::Vector3d& p) { return fmt::format("({:.3f}, {:.3f}, {:.3f})", p[0], p[1], p[2]); }

std::string AuditCoveringText(const audit::AuditCovering& c) {
  if (!(c.covering.thickness_m > 0.0)) return "bare";
  // The law that describes it (auto: the foam law for a measured curve): each cell counts its validity.
  const bool foam = c.covering.compressive_curve && c.covering.law != CoveringLaw::kHertz;
  return fmt::format("{}{} (E {}, ν {:g}; {} law)", c.material ? c.material->name + " " : std::string(),
                     FormatQuantity(c.covering.thickness_m, QuantityKind::kLength),
                     FormatQuantity(c.covering.youngs_modulus_Pa, QuantityKind::kModulus), c.covering.poisson_ratio,
                     foam ? "foam" : "hertz");
}


// The flags resolved by the groups every command shares (robot model, scene, body regions),
// the audit assembled by the library from them and the audit's own flags.
ResolvedAuditInputs ResolveAuditInputs(const AuditInputOptions& o) {
  CheckInputFlags(o);
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
  ResolvedAuditInputs run(audit::AssembleAudit(in));
  run.assembled.setup.keep_travel = o.scene.keep_travel;
  run.inputs = plan.inputs;
  if (o.design) {  // optimize's ranges, named by the flags (the library names its own fields)
    const audit::AuditDesignOptions& design = run.assembled.options.design;
    RequireMaxThickness(design.max_thickness_m, design.min_thickness_m, o.max_thickness);
    RequireThicknessStep(design.thickness_step_m, o.thickness_step);
  }
  return run;
}

void PrintAuditInputs(std::ostream& out, const AuditInputOptions& o, const audit::AssembledAudit& assembled,
                      std::size_t sample_count) {
  const audit::AuditSetup& setup = assembled.setup;
  const robot::KinematicChain& chain = setup.chain;
  std::string robot_line = fmt::format("{}: {} -> {}, {} movable joint{}", chain.robot_name(), chain.base_link(),
                                       chain.tip_link(), chain.joint_count(), chain.joint_count() == 1 ? "" : "s");
  if (const robot::Payload& payload = chain.payload(); !payload.empty()) {
    robot_line += fmt::format("; payload {:.4g} kg at {} m (tip frame)", payload.mass_kg, PointText(payload.center_of_mass_m));
  }
  fmt::print(out, "Robot      {}\n", robot_line);
  const auto& times = assembled.trajectory.time_s;
  fmt::print(out, "Trajectory {}: {} samples, t = {:g} .. {:g} s\n", *o.trajectory, sample_count,
             times.empty() ? 0.0 : times.front(), times.empty() ? 0.0 : times.back());
  fmt::print(out, "Surface    {} links, {} points (spacing {}){}\n", setup.surface.links.size(),
             setup.surface.point_count(), FormatQuantity(setup.surface.spacing_m, QuantityKind::kLength),
             o.surface_file ? fmt::format(", surface file {}", *o.surface_file) : std::string());
  fmt::print(out, "Covering   all links: {}\n", AuditCoveringText(setup.covering));
  for (const auto& [link, covering] : setup.link_coverings) {
    fmt::print(out, "           {}: {} (--link-coverings)\n", link, AuditCoveringText(covering));
  }
  const materials::LimitTableInfo* table =
      setup.regions.empty() || !setup.regions.front().region ? nullptr : setup.regions.front().region->table.get();
  fmt::print(out, "Regions    {} body region{} (transient){}\n", setup.regions.size(),
             setup.regions.size() == 1 ? "" : "s", setup.head ? fmt::format(" and the head ({})", HeadCriteriaName()) : "");
  if (table) {
    fmt::print(out, "Limits     {}\n", LimitTableText(*table));
  }
  optim::DesignRule judged = setup.rule;  // the travel rule counts only with --keep-travel
  if (!setup.keep_travel) judged.criterion = optim::DesignCriterion::kPaper;
  fmt::print(out, "Criterion  {}\n",
             optim::BodyRegionCriterion(judged, setup.head.has_value(), table ? table->edition : std::string_view()));
  if (setup.braking_m_per_s2 > 0.0) {
    fmt::print(out, "Braking    reaction delay {}, braking {}\n",
               FormatQuantity(setup.reaction_delay_s, QuantityKind::kTime),
               FormatQuantity(setup.braking_m_per_s2, QuantityKind::kAcceleration));
  }
}

void AddAuditInputOptions(CLI::App& command, AuditInputOptions& options, const char* design_help) {
  CLI::App* sub = &command;
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
  sub->add_flag("--design", options.design, design_help)
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
}

}  // namespace covopt::cli
