#pragma once
/// @file audit_inputs.hpp
/// The audit's inputs on the command line, shared by `covopt audit` and `covopt retime`: the
/// robot model, the trajectory, the surface, the coverings, the scene, the body regions, the
/// rule and the per-link design; their flags (AddAuditInputOptions), their resolution into the
/// one assembly of an audit (covopt::audit::AssembleAudit), and the text lines that describe
/// them.

#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "covopt/audit/assemble.hpp"
#include "report_option.hpp"
#include "robot_model_options.hpp"
#include "simulation_plan.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The audit's inputs as typed: the robot model, the trajectory, the surface, the coverings,
/// the scene, the body regions, the rule and the per-link design. Shared by `covopt audit` and
/// `covopt retime` (AddAuditInputOptions, ResolveAuditInputs).
struct AuditInputOptions {
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
};


/// Registers the audit's input flags on `sub` (groups "Robot model", "Audit", "Scene", the
/// body regions', the rule's, "Design (--design)"); `options` must outlive the parse.
/// `design_help` is --design's help text (what the design does in that command).
void AddAuditInputOptions(CLI::App& sub, AuditInputOptions& options, const char* design_help);

/// The audit assembled from its input flags (covopt::audit::AssembleAudit), and what the
/// scene file's [report] table and the inputs' sources add to the result.
struct ResolvedAuditInputs {
  explicit ResolvedAuditInputs(audit::AssembledAudit a) : assembled(std::move(a)) {}
  audit::AssembledAudit assembled;
  ResultInputs inputs;
};

/// Resolves the input flags: the robot model, the scene, the body regions (default: every
/// transient region and the head), the audit's own flags; assembles the audit.
/// @throws InputError (or the library's std::invalid_argument) naming the flag and the value.
ResolvedAuditInputs ResolveAuditInputs(const AuditInputOptions& options);

/// The covering's one-line description: "PORON 10 mm (E 2.1 MPa, ν 0.3; foam law)" or "bare".
std::string AuditCoveringText(const audit::AuditCovering& covering);

/// The lines the text output opens with: the robot, the trajectory, the surface, the
/// coverings, the regions, the criterion and the braking.
void PrintAuditInputs(std::ostream& out, const AuditInputOptions& options, const audit::AssembledAudit& assembled,
                      std::size_t sample_count);

/// "(0.223, 0.108, 0.672)": a point [m], 3 decimals.
std::string PointText(const Eigen::Vector3d& p);

}  // namespace covopt::cli
