#pragma once
/// @file tool_surface.hpp
/// The tool's and the payload's geometry for an audit (`covopt audit --tool-surface`,
/// `--payload-surface`; covopt.audit(tool_surface=[...], payload_surface=[...])): shapes in the
/// flange frame (the chain's tip link), written as one compact spec each:
///
///     capsule:from=0,0,0.02;to=0,0,0.12;radius=40mm
///     sphere:center=0,0,0.1;radius=30mm
///     box:center=0,0,0.06;size=0.08,0.2,0.1;edge=5mm
///
///     box:center=0,0,0.05;size=0.08,0.2,0.1;edge=10mm;rpy=0,0,-0.7854
///
/// Each length is in metres unless it carries its unit (mm, cm, m): "0,0,120mm". A box is
/// aligned with the flange frame unless rotated by rpy (roll, pitch, yaw about the fixed x, y,
/// z [rad], as a URDF origin's); its edge (and corner) radius is required, as for URDF boxes.
/// The shapes become the surface rows "tool" and "payload" (robot::AddTipSurface), judged like
/// links, with their own covering when link coverings name them.

#include <string>
#include <string_view>

#include <covopt/robot/surface.hpp>

namespace covopt::audit {

/// The largest distance of a tool shape's point from the flange [m] (any coordinate): 2 m.
inline constexpr double kMaxToolCoordinate_m = 2.0;
/// The largest radius or box extent of a tool shape [m]: 1 m and 2 m.
inline constexpr double kMaxToolRadius_m = 1.0;
inline constexpr double kMaxToolExtent_m = 2.0;

/// Reads one shape spec (the grammar above). `field` names it in messages ("--tool-surface",
/// "tool_surface[0]").
/// @throws std::invalid_argument "<field> '<spec>': <key>: <problem> (got <value>)": an unknown
///         shape or key (naming the keys it takes), a missing or repeated key, a value that is
///         not three numbers (from, to, center, size) or one length (radius, edge), a coordinate
///         beyond ±kMaxToolCoordinate_m, a radius outside [0.1 mm, kMaxToolRadius_m], a box
///         extent outside [0.2 mm, kMaxToolExtent_m], an edge radius outside [0.1 mm, half the
///         smallest extent], a capsule whose ends coincide.
robot::SurfaceShape ParseTipShape(std::string_view spec, std::string_view field);

}  // namespace covopt::audit
