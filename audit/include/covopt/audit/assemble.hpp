#pragma once
/// @file assemble.hpp
/// The one assembly of an audit from its inputs, for every front end: `covopt audit` and
/// covopt.audit() each resolve their own spelling of the shared inputs (the robot model, the
/// scene, the body regions) and hand the rest over as plain values and paths; AssembleAudit
/// reads the robot's surface, the trajectory and the link coverings, takes the design's
/// materials from the catalog, applies the audit's rules (no robot mass, speed or radius: each
/// point brings its own; transient contacts only; the design's inputs only with the design;
/// the design's rule on unknown strengths) and says what it assumed. Its messages name each
/// input by the front end's own spelling (AuditFieldNames).
///
///     covopt::audit::AuditInputs in{chain, "fr3.urdf"};
///     in.trajectory = std::string("pick.csv");
///     in.scene = scene;                                   // covering of every link, head, braking
///     in.regions = table.AllLimits(covopt::ContactType::kTransient);
///     in.head = true;
///     const auto audit = covopt::audit::AssembleAudit(in);
///     const auto result = covopt::audit::Audit(audit.setup, audit.trajectory, audit.options);

#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <covopt/core/body_contact.hpp>
#include <covopt/core/scene.hpp>
#include <covopt/materials/body_regions.hpp>
#include <covopt/materials/catalog.hpp>
#include <covopt/optim/body_region_check.hpp>
#include <covopt/robot/kinematic_chain.hpp>
#include <covopt/robot/surface.hpp>
#include <covopt/robot/trajectory.hpp>
#include <covopt/scene_file/exposure_file.hpp>
#include <covopt/scene_file/link_coverings.hpp>

#include "covopt/audit/audit.hpp"

namespace covopt::audit {

/// The body regions an audit judges when the caller names none, as a body-region list: every
/// region ISO/TS 15066 permits in a transient contact, and the head.
inline constexpr const char* kDefaultBodyRegions = "all";

/// How a front end spells each input AssembleAudit names in its messages. The defaults are
/// the library's (and Python's keywords); the CLI passes its flags ("--trajectory", ...).
struct AuditFieldNames {
  std::string urdf = "urdf";
  std::string urdf_text = "urdf_text";
  std::string surface_file = "surface_file";
  std::string trajectory = "trajectory";
  std::string link_coverings = "link_coverings";
  std::string contact = "contact";
  std::string design = "design";
  std::string design_materials = "materials";
  std::string families = "families";
  std::string allow_unknown_strength = "allow_unknown_strength";
  std::string max_thickness = "max_thickness";
  std::string thickness_step = "thickness_step";
  std::string robot_mass = "robot_mass";
  std::string speed = "speed";
  std::string robot_radius = "robot_radius";
  std::string tool_surface = "tool_surface";
  std::string payload_surface = "payload_surface";
  std::string exposure = "exposure";
};

/// What an audit is assembled from: the inputs every command shares already resolved by the
/// front end (the chain from the robot model, the scene, the body regions and the rule), the
/// audit's own as plain values and paths.
struct AuditInputs {
  /// The chain (URDF, base, tip, payload) and where its collision geometry is read: the URDF
  /// file, or its text when urdf_text is set.
  AuditInputs(robot::KinematicChain chain_in, std::string urdf_file_in)
      : chain(std::move(chain_in)), urdf_file(std::move(urdf_file_in)) {}
  robot::KinematicChain chain;
  std::string urdf_file;
  std::optional<std::string> urdf_text;
  /// The surface's spacing, box edge radius and surface file (robot/surface.hpp).
  robot::SurfaceOptions surface;
  /// The tool's and the payload's shapes in the flange frame, as specs (tool_surface.hpp,
  /// ParseTipShape): the surface rows "tool" and "payload", carried by the chain's tip link
  /// (after a surface file's [[tool]] and [[payload]] shapes).
  std::vector<std::string> tool_surface;
  std::vector<std::string> payload_surface;
  /// The exposure zones (AuditSetup::exposure_zones): an exposure file (TOML,
  /// scene_file::ReadExposureFile), or the zones themselves; empty: every region everywhere.
  std::optional<std::variant<std::string, std::vector<ExposureZone>>> exposure;
  /// The radius a covering is judged on at a flat point (AuditSetup::flat_face_radius_m).
  std::optional<double> flat_face_radius_m;
  robot::ReflectedMassOptions reflected_mass;
  /// The motion: a trajectory CSV file (robot::ReadJointTrajectory) or its samples.
  std::variant<std::string, robot::JointTrajectory> trajectory;
  /// The covering of every link, the head's model and the robot's braking (its mass, speed and
  /// radius are each point's).
  Scene scene;
  /// The scene's robot mass, speed or radius where the caller gave one, by field name
  /// ("robot.mass", "robot.speed", "robot.radius") -> the value as given: refused, since each
  /// surface point and sample brings its own.
  std::map<std::string, std::string> given_robot_inputs;
  /// The exposed body regions, the contact they were resolved for (an audit refuses a clamped
  /// one), the bare robot's contact area [m²] (0: not given), and whether the head is judged.
  std::vector<materials::BodyLimits> regions;
  ContactType contact = ContactType::kTransient;
  double contact_area_m2 = 0.0;
  bool head = false;
  /// The rule and the all-links covering's catalog material (optim::BodyRegionOptions).
  optim::BodyRegionOptions judge;
  /// Per link its own covering: a link-covering file (TOML), or its entries as read.
  std::optional<std::variant<std::string, std::vector<scene_file::LinkCoveringEntry>>> link_coverings;
  /// The catalog of link_coverings' and the design's materials; null: the built-in one.
  const materials::Catalog* catalog = nullptr;
  /// The per-link design (AuditDesignOptions): its materials by name and family, unknown
  /// strengths allowed, the thickest covering tried and the stock step [m].
  bool design = false;
  std::vector<std::string> design_materials;
  std::vector<std::string> families;
  bool allow_unknown_strength = false;
  std::optional<double> max_thickness_m;
  std::optional<double> thickness_step_m;
  /// Keep the samples × links ratio matrix (AuditOptions::keep_ratio_over_time).
  bool keep_ratio_over_time = true;
  /// What the front end's scene resolution warned of (assumed defaults, crush notes).
  std::vector<std::string> scene_warnings;
  /// The front end's spelling of the inputs, for the messages.
  AuditFieldNames names;
};

/// An audit ready to run: Audit(setup, trajectory, options).
struct AssembledAudit {
  explicit AssembledAudit(AuditSetup setup_in) : setup(std::move(setup_in)) {}
  AuditSetup setup;
  robot::JointTrajectory trajectory;
  AuditOptions options;
  /// The exposure file's title and source, when one was read (for the report).
  std::string exposure_title;
  std::string exposure_source;
  /// What the inputs assumed (an assumed Poisson ratio of a link's material), then the
  /// scene's warnings: the input warnings of the report (report::AuditJson).
  std::vector<std::string> input_warnings;
};

/// Assembles the audit of `inputs`.
/// @throws std::invalid_argument naming the input by inputs.names: the scene's robot mass,
///         speed or radius (given_robot_inputs), a clamped contact, a
///         design input without the design, an unreadable surface, trajectory or link-covering
///         file, a bad tool or payload shape spec, an unreadable exposure file, a chain without
///         collision geometry (and no tool), a link covering for a link not on the
///         surface, a material or family not in the catalog.
AssembledAudit AssembleAudit(const AuditInputs& inputs);

}  // namespace covopt::audit
