#pragma once
/// @file scene_headline.hpp
/// A scene in one short line, for the titles of tables and charts (the CLI's and the charts'
/// of charts.hpp).

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/scene.hpp"

namespace covopt::report {

/// The scene in one short line, for titles: "10 kg at 2 m/s, R 15 mm; covering 15 mm,
/// 27.6 MPa; head 4.5 kg". The speed [m/s] goes with the body that moves: a fixed robot
/// reads "fixed robot, R 15 mm; ...; head 4.5 kg dropped onto it at 2.2 m/s", a fixed head
/// "...; head fixed, hit by the robot". Fields named in `omitted_fields` (dotted names:
/// robot.mass, robot.speed, robot.radius, covering.thickness, covering.modulus, head.mass)
/// are left out, e.g. the swept ones of a sweep chart; a body whose mass is omitted is
/// called neither fixed nor free.
std::string SceneHeadline(const Scene& scene, std::span<const std::string_view> omitted_fields = {});

/// The headline of a scene whose covering a design finds: its covering left out and called
/// "covering to be designed" (optimize's and workprecision --design's "Scene" line).
std::string DesignedSceneHeadline(const Scene& scene);

/// The scene inputs SceneHeadline does not show that differ from the paper's scene
/// (Scene{}), skipping `omitted_fields`: {"scalp-thickness 4 mm", "literal thresholds"}.
std::vector<std::string> SceneDetailsBeyondHeadline(
    const Scene& scene, std::span<const std::string_view> omitted_fields = {});

}  // namespace covopt::report
