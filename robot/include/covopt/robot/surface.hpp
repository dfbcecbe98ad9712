#pragma once
/// @file surface.hpp
/// The robot's surface: per link of a chain, the shapes that can hit a person and points
/// sampled on them, each with its outward normal and its surface radius of curvature, so that
/// an audit can take each point's velocity and reflected mass (ContactJacobian and
/// ReflectedMass at the point, given in the link's frame).
///
///     const auto chain = covopt::robot::KinematicChain::FromUrdfFile("fr3.urdf", {"", "fr3_link8"});
///     covopt::robot::SurfaceOptions options;
///     options.spacing_m = 0.05;
///     const auto surface = covopt::robot::SurfaceFromUrdfFile("fr3.urdf", chain, options);
///     for (const auto& link : surface.links) for (const auto& p : link.points) { ... }
///
/// Where the shapes come from (robot/README.md, "The surface"):
/// - the URDF's <collision> geometry of each chain link: <sphere>, <cylinder>, <box> (with
///   the edge radius SurfaceOptions::box_edge_radius_m the user gives) and capsules written
///   as a <cylinder> with a <sphere> of the same radius centred on each end (detected);
/// - or a surface file (TOML, ReadSurfaceFile) with per link segments (capsules: two points
///   and a radius) or points with their radius. It replaces the URDF's geometry of the links
///   it names; a link whose collision geometry is a <mesh> needs one.
/// Links after the tip and the base link are not part of the surface (the base does not move).

#include <cstddef>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "covopt/robot/kinematic_chain.hpp"

namespace covopt::robot {

/// The radius of curvature of a flat face [m]: +infinity.
inline constexpr double kFlat = std::numeric_limits<double>::infinity();

/// The smallest and largest sampling spacing [m] (a finer spacing would only multiply points;
/// a coarser one would skip whole links).
inline constexpr double kMinSurfaceSpacingM = 1e-3;
inline constexpr double kMaxSurfaceSpacingM = 1.0;
/// The most points one surface may have (a bound on memory and time for a fine spacing or a
/// large shape: 64 bytes a point). The count is estimated from the shapes and the spacing
/// (EstimateShapePoints) and a surface above it refused before any point is made.
inline constexpr std::size_t kMaxSurfacePoints = 1000000;
/// The largest surface file read [bytes]: 1 MiB.
inline constexpr std::size_t kMaxSurfaceFileBytes = std::size_t{1} << 20;

/// The kinds of shape on a link.
enum class SurfaceShapeType {
  kSphere,    ///< centre `a_m`, radius
  kCylinder,  ///< axis from `a_m` to `b_m`, radius; flat end discs
  kCapsule,   ///< the points within `radius_m` of the segment `a_m`–`b_m` (a cylinder with
              ///< hemispherical ends)
  kBox,       ///< `pose` (box frame in the link frame), full extents `size_m`, edges and
              ///< corners rounded with `edge_radius_m` inside those extents
  kPoint,     ///< one surface point given in a surface file: at `a_m`, with the surface's
              ///< radius of curvature `radius_m` there (kFlat allowed), no normal
};
/// "sphere", "cylinder", "capsule", "box" or "point".
const char* ToString(SurfaceShapeType type) noexcept;

/// One shape of a link, in the link's frame [m].
struct SurfaceShape {
  SurfaceShapeType type = SurfaceShapeType::kSphere;
  Eigen::Vector3d a_m = Eigen::Vector3d::Zero();  ///< sphere centre; cylinder/capsule axis start
  Eigen::Vector3d b_m = Eigen::Vector3d::Zero();  ///< cylinder/capsule axis end
  double radius_m = 0.0;  ///< sphere, cylinder, capsule radius; kPoint: radius of curvature
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< box frame in the link frame
  Eigen::Vector3d size_m = Eigen::Vector3d::Zero();        ///< box full extents
  double edge_radius_m = 0.0;                              ///< box edge and corner radius
  /// Where it was read: "URDF <collision> 2 of link 'fr3_link3'", "surface file:12:3".
  std::string origin;
};

/// A point of the surface, in its link's frame.
struct SurfacePoint {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  ///< on the shape's surface [m]
  /// The outward unit normal [-]; zero for a point given alone in a surface file (it faces
  /// every direction).
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  /// The surface's radius of curvature there [m]: a cylinder's or capsule's radius, a sphere's
  /// radius, a box's edge radius at its edges and corners, kFlat on a flat face.
  double radius_of_curvature_m = kFlat;
  std::size_t shape_index = 0;  ///< which of the link's shapes it lies on
};

/// The surface of one chain link, or of what a link carries (the tool, the payload).
struct LinkSurface {
  /// The URDF link name; "tool" or "payload" for the shapes the tip link carries (AddTipSurface).
  std::string link;
  /// The chain link whose frame the shapes are given in and that moves them; empty: `link`
  /// itself. The tool and the payload: the chain's tip link (the flange).
  std::string frame_link;
  /// The chain link that moves the shapes: frame_link, or link when it is empty.
  const std::string& carrier() const noexcept { return frame_link.empty() ? link : frame_link; }
  std::vector<SurfaceShape> shapes;   ///< in the order read
  std::vector<SurfacePoint> points;   ///< sampled on the shapes (SurfaceOptions::spacing_m)
};

/// The surface of a chain: the links after the base, base to tip, that have shapes.
struct RobotSurface {
  std::vector<LinkSurface> links;
  double spacing_m = 0.0;             ///< the sampling spacing used [m]
  /// What a reader must know: chain links without collision geometry (never checked).
  std::vector<std::string> warnings;
  /// The number of points over all links.
  std::size_t point_count() const noexcept;
};

/// How to read and sample the surface.
struct SurfaceOptions {
  /// The largest distance between neighbouring points along and around a shape [m], in
  /// [kMinSurfaceSpacingM, kMaxSurfaceSpacingM]. Default 0.05 m.
  double spacing_m = 0.05;
  /// The edge and corner radius of every URDF <box> [m] (URDF boxes have sharp edges; a
  /// real housing is rounded). Required when the chain has a box; > 0 and at most half the
  /// box's smallest extent.
  std::optional<double> box_edge_radius_m;
  /// A surface file (TOML, ReadSurfaceFile): its links replace the URDF's geometry.
  std::optional<std::filesystem::path> surface_file;
};

/// The shapes of a surface file, per link (not yet checked against a chain).
struct SurfaceFileShapes {
  std::string source;                 ///< the file's path, for messages
  std::vector<LinkSurface> links;     ///< shapes only; no points yet
  /// The [[tool]] and [[payload]] tables' shapes in the tip link's frame (link "tool",
  /// "payload"); no shapes: none given.
  LinkSurface tool;
  LinkSurface payload;
};

/// Reads a surface file (format: robot/README.md, "Surface files"):
///
///     [[link]]
///     name = "upper_arm_link"
///     segments = [ { from_m = [0, 0, 0.138], to_m = [-0.425, 0, 0.138], radius_m = 0.054 } ]
///     points = [ { at_m = [0, 0, 0.2], radius_m = 0.04 } ]
///
///     [[tool]]                          # what the flange carries, in the tip link's frame
///     segments = [ { from_m = [0, 0, 0.02], to_m = [0, 0, 0.12], radius_m = 0.04 } ]
///     [[payload]]                       # the same keys
///
/// @throws std::invalid_argument "file:line:column: ..." naming the key and the value: not
///         TOML, an unknown key, a link without name or with neither segments nor points, a
///         link named twice, a coordinate that is not a finite number within ±kMaxLengthM, a
///         radius (of a segment, or of a point unless "flat") outside [covopt::kMinRadius_m,
///         kMaxLengthM] (0.1 mm .. 1000 m), a file over kMaxSurfaceFileBytes.
SurfaceFileShapes ReadSurfaceFile(const std::filesystem::path& path);
/// As ReadSurfaceFile, from the TOML text; messages call it `source_name`.
SurfaceFileShapes ParseSurfaceFile(const std::string& toml_text, const std::string& source_name);

/// The surface of `chain`, read from the URDF text the chain was built from (and the surface
/// file of `options`), sampled at options.spacing_m.
/// @throws std::invalid_argument in one line naming the link and the value: a chain link
///         whose collision geometry is a <mesh> (and that the surface file does not name), a
///         surface file naming a link that is not on the chain (naming the chain's links), a
///         radius, length or box extent outside [covopt::kMinRadius_m, kMaxLengthM] (0.1 mm ..
///         1000 m; only the shapes of the chain's moving links that the surface file does not
///         replace are read), a box without box_edge_radius_m or with one below kMinRadius_m or
///         over half its smallest extent, a spacing outside [kMinSurfaceSpacingM,
///         kMaxSurfaceSpacingM], shapes whose EstimateShapePoints add up to more than
///         kMaxSurfacePoints (before any point is made: the message names the shape giving
///         the most and a spacing that would do), and whatever urdfdom refuses (an unknown
///         geometry type: "malformed URDF: ...").
RobotSurface SurfaceFromUrdfString(const std::string& urdf_text, const KinematicChain& chain,
                                   const SurfaceOptions& options = {},
                                   const std::string& source_name = "URDF text");
/// As SurfaceFromUrdfString, with a surface file's shapes already read (ParseSurfaceFile;
/// nullptr: none) in place of options.surface_file, which is not read.
RobotSurface SurfaceFromUrdfString(const std::string& urdf_text, const KinematicChain& chain,
                                   const SurfaceOptions& options, const std::string& source_name,
                                   const SurfaceFileShapes* surface_file);
/// Adds shapes the chain's tip link carries (the tool, the payload), given in its frame (the
/// flange), to `surface` as the LinkSurface named `name` ("tool", "payload") with frame_link the
/// tip link, sampled at surface.spacing_m; shapes added under a name already on the surface join
/// its shapes. Nothing happens for no shapes.
/// @throws std::invalid_argument as SampleShape, and for shapes that would take the surface
///         over kMaxSurfacePoints.
void AddTipSurface(RobotSurface& surface, const KinematicChain& chain, const std::string& name,
                   const std::vector<SurfaceShape>& shapes);

/// As SurfaceFromUrdfString, from the URDF file at `path`.
RobotSurface SurfaceFromUrdfFile(const std::filesystem::path& path, const KinematicChain& chain,
                                 const SurfaceOptions& options = {});

/// The points sampled on one shape at `spacing_m` (what SurfaceFromUrdfString does per shape;
/// a kPoint shape gives its one point). Sampling: along an axis, stations at most
/// `spacing_m` apart including both ends; around a circle of radius r, max(4, ⌈2πr/spacing⌉)
/// points; on a sphere or a capsule's hemispherical end, rings of latitude at most `spacing_m`
/// apart along the meridian (the poles included), each ring sampled as a circle; on a box's
/// flat faces a grid at most `spacing_m` apart (kFlat), on its rounded edges stations along
/// the edge at most `spacing_m` apart and ⌈(π/2)e/spacing⌉ points across the quarter circle,
/// one point at each corner along its diagonal. A cylinder's end discs: rings as a flat disc (kFlat).
/// @throws std::invalid_argument for a spacing outside its range, or a shape whose
///         EstimateShapePoints exceeds kMaxSurfacePoints (checked before any point is made).
std::vector<SurfacePoint> SampleShape(const SurfaceShape& shape, double spacing_m,
                                      std::size_t shape_index = 0);

/// An upper bound of SampleShape(shape, spacing_m).size(), from the shape's dimensions and the
/// spacing alone (no point is made; O(1) for any size). Exact for a box, a point and a
/// cylinder's or capsule's side; on a sphere, a capsule's ends and a cylinder's end discs, where
/// the rings' sizes are summed in closed form, it exceeds the count by about half a point per
/// ring (about s / 8r of the count on a sphere of radius r: 1.6 % at r = 10 s, 0.13 % at
/// r = 100 s). +inf for a shape with a non-finite dimension.
/// @throws std::invalid_argument for a spacing outside its range.
double EstimateShapePoints(const SurfaceShape& shape, double spacing_m);

}  // namespace covopt::robot
