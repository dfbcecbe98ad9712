#pragma once
/// @file audit.hpp
/// `covopt audit`: the whole robot along its motion (docs/guide/audit.md). Every surface
/// point of every link, at every sample of the trajectory, against every exposed body region
/// (audit::Audit).
///
///     covopt audit --urdf FILE [--base LINK] --tip LINK --trajectory FILE.csv
///                  [--surface-file FILE.toml] [--surface-spacing 50mm] [--box-edge-radius 5mm]
///                  [--flat-face-radius 20mm] [--payload-mass M ...]
///                  [--covering-thickness 10mm --material NAME | --covering-modulus E]
///                  [--link-coverings FILE.toml] [--body-region all|NAME,...|head]
///                  [--contact-area 1cm2] [--safety-factor X] [--reaction-delay T --braking A]
///                  [--design [--family F] [--design-material NAME]]
///                  [--json] [--csv FILE|-] [--samples-csv FILE|-] [--plot FILE.png|FILE.svg]
///
/// The flags are the other commands' groups: the robot model (robot_model_options.hpp), the
/// scene's covering, head and braking flags with --material and the catalog (simulate.hpp),
/// the body regions (body_region_options.hpp; default: every transient region and the head).
/// Exit codes: 0 an answer (safe, unsafe or at rest), 1 an output could not be written,
/// 2 bad input.

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "robot_model_options.hpp"
#include "run_context.hpp"
#include "simulation_plan.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The options of `covopt audit`, as typed.
struct AuditCommandOptions {
  RobotModelOptions model;                     ///< --urdf, --base, --tip, --payload-*, ...
  std::optional<std::string> trajectory;       ///< --trajectory FILE.csv
  std::optional<std::string> surface_file;     ///< --surface-file FILE.toml
  std::optional<std::string> surface_spacing;  ///< --surface-spacing (default 50 mm)
  std::optional<std::string> box_edge_radius;  ///< --box-edge-radius (URDF boxes)
  std::optional<std::string> flat_face_radius; ///< --flat-face-radius (a covering on flat points)
  /// The covering for all links, the head's model, braking, the limits, --material and the
  /// catalog, --body-region and its group, --safety-factor: as `simulate` reads them.
  SimulateOptions scene;
  std::optional<std::string> link_coverings;   ///< --link-coverings FILE.toml
  std::vector<std::string> tool_surface;       ///< --tool-surface SPEC (repeatable)
  std::vector<std::string> payload_surface;    ///< --payload-surface SPEC (repeatable)
  std::optional<std::string> exposure;         ///< --exposure FILE.toml
  bool allow_full_compression = false;         ///< --allow-full-compression
  bool allow_crushing = false;                 ///< --allow-crushing
  bool design = false;                         ///< --design: per link the thinnest catalog covering
  std::vector<std::string> families;           ///< --family (repeatable), with --design
  std::vector<std::string> design_materials;   ///< --design-material (repeatable), with --design
  bool allow_unknown_strength = false;         ///< --allow-unknown-strength, with --design
  std::optional<std::string> max_thickness;    ///< --max-thickness (default 50 mm), with --design
  std::optional<std::string> thickness_step;   ///< --thickness-step (default 0.5 mm), with --design
  bool json = false;                           ///< --json: report::AuditJson
  std::optional<std::string> csv_file;         ///< --csv FILE|-: one row per link × region
  std::optional<std::string> samples_csv;      ///< --samples-csv FILE|-: one row per sample, streamed
  std::optional<std::string> plot_file;        ///< --plot FILE.png|FILE.svg: the heat map
  ReportFlags report;  ///< --report FILE.html|FILE.pdf and the sign-off flags (report_option.hpp)
  /// Not typed: the command line and input files for the JSON's provenance, set by RunCli.
  std::optional<RunContext> run;
};

/// Registers the options of the `audit` subcommand `sub` (made by RunCli with its name and
/// summary); `options` must outlive the parse.
void SetupAudit(CLI::App* sub, AuditCommandOptions& options);

/// Runs the audit; returns the exit code (0, 1 or 2).
int RunAudit(const AuditCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace covopt::cli
