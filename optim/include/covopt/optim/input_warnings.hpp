#pragma once
/// @file input_warnings.hpp
/// What the reader of an answer must know about the inputs that produced it: a safety factor
/// and the limits it derates, a catalog material whose Poisson ratio is assumed, and covering
/// inputs that no covering (thickness 0) makes moot. One set of words for the CLI and Python,
/// which differ only in how they name where an input came from ("--safety-factor '2'",
/// "safety_factor=2").

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <covopt/core/scene.hpp>
#include <covopt/materials/material.hpp>

namespace covopt::optim {

/// Where a scene input came from, for a dotted field name ("limits.safety_factor",
/// "covering.material", "covering.modulus", "covering.poisson", "covering.thickness"); empty
/// when not given.
using InputSource = std::function<std::optional<std::string>(std::string_view field)>;

/// The warnings, in order: the safety factor (judged against limit / safety_factor);
/// without a covering, a material (then nothing else) or a covering modulus / ν that are
/// ignored; with a covering, the default covering assumed (no covering input given: the
/// text of DefaultCoveringNote, speed_limit.hpp) or a catalog material whose ν is unknown
/// (0.25 assumed). Every assumed default is warned here, so every front end says it.
/// `covering_material`: the catalog entry the covering came from, or nullptr.
std::vector<std::string> SceneInputWarnings(const Scene& scene, const InjuryLimits& limits,
                                            double safety_factor,
                                            const materials::Material* covering_material,
                                            const InputSource& source_of);

/// `warnings` with those of `more` it does not hold yet appended (the crush notes after the
/// input warnings: the default covering is in both).
void AppendNewWarnings(std::vector<std::string>& warnings, const std::vector<std::string>& more);

}  // namespace covopt::optim
