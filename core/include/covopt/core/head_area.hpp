#pragma once
/// @file head_area.hpp
/// Where the robot strikes the head, and the lowest published fracture force of the bone
/// there (docs/model.md §7.1). Park et al.'s skin model judges the scalp; the fracture check
/// judges the bone under it: a peak force above the struck area's fracture force is not safe.

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace covopt {

/// The struck area of the head.
enum class HeadArea {
  kFrontal,          ///< the forehead (frontal bone): Park et al.'s impact site, the default
  kTemporoParietal,  ///< the side of the skull (temporal and parietal bones)
  kNasal,            ///< the nasal bones, struck front to back
  kMaxilla,          ///< the infraorbital maxilla (below the eye)
  kMandibleFront,    ///< the chin (mandible, fronto-median blow)
  kMandibleSide,     ///< the side of the jaw (mandible, lateral blow)
};

/// One row of the fracture-force table: the lowest published force for an area, what it is
/// and where it comes from.
struct FractureForce {
  HeadArea area = HeadArea::kFrontal;
  std::string_view name;        ///< the area's name, as typed ("frontal", "temporo-parietal", ...)
  double force_N = 0.0;         ///< the lowest published fracture force for the area [N]
  std::string_view range;       ///< the published range the value is the low end of, in words
  std::string_view conditions;  ///< the specimens, impactor and loading
  std::string_view source;      ///< the citation
};

/// The table, in the order of HeadArea.
std::span<const FractureForce> FractureForces() noexcept;
/// The row of `area`.
const FractureForce& FractureForceOf(HeadArea area) noexcept;
/// "frontal", "temporo-parietal", "nasal", "maxilla", "mandible-front", "mandible-side".
std::string_view ToString(HeadArea area) noexcept;
/// The inverse of ToString, ignoring case; empty for an unknown name.
std::optional<HeadArea> ParseHeadArea(std::string_view name) noexcept;
/// The names, comma separated, in the order of HeadArea (for messages).
std::string HeadAreaChoices();
/// ParseHeadArea or std::invalid_argument naming `field`, the value and the choices, e.g.
/// "head.area must be one of frontal, temporo-parietal, ... (got \"cheek\")".
HeadArea ParseHeadAreaOrThrow(std::string_view field, std::string_view name);

}  // namespace covopt
