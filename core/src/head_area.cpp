// The fracture-force table of the head's areas (head_area.hpp, docs/model.md §7.1).
#include "covopt/core/head_area.hpp"

#include <array>
#include <stdexcept>
#include <string>

#include "covopt/internal/text.hpp"

namespace covopt {
namespace {

// 700 lbf = 3114 N (1 lbf = 4.448 N).
constexpr std::array<FractureForce, 6> kTable = {{
    {HeadArea::kFrontal, "frontal", 3114.0, "3.1-7.3 kN by impactor (700-1650 lbf)",
     "12 cadaver heads free to rebound, struck by falling rigid cylinders of radius 1 in "
     "(4.2-7.3 kN) and 5/16 in (3.1-7.1 kN); the lowest fracture load",
     "Hodgson, Brinn, Thomas, Greenberg 1970, Fracture behavior of the skull frontal bone "
     "against cylindrical surfaces, SAE 700909 (14th Stapp)"},
    {HeadArea::kTemporoParietal, "temporo-parietal", 5000.0,
     "mean 5.0 kN (5 cm² plate), 12.5 kN (52 cm² plate)",
     "31 unembalmed fixed cadaver heads, flat rigid impactors; the mean fracture force with "
     "the smaller plate (individual minima not published in the abstract)",
     "Allsop, Perl, Warner 1991, Force/deflection and fracture characteristics of the "
     "temporo-parietal region of the human head, SAE technical paper (abstract)"},
    {HeadArea::kNasal, "nasal", 450.0, "50 % fracture risk at 450-850 N",
     "male cadavers, anterior-posterior blow of a free-falling flat impactor, fracture onset "
     "by acoustic emission; the low end of the 50 % risk estimates",
     "Cormier et al. 2010, The tolerance of the nasal bone to blunt impact, "
     "Ann. Adv. Automot. Med. 54:3-14"},
    {HeadArea::kMaxilla, "maxilla", 970.0, "50 % fracture risk at 970-1223 N",
     "38 infraorbital maxilla impacts on male cadavers, unpadded 3.2 kg cylindrical impactor "
     "at 1-5 m/s, fracture onset by acoustic emission; the low end of the 50 % risk estimate",
     "Cormier et al. 2011, J. Biomech. Eng. 133(6):064501"},
    {HeadArea::kMandibleFront, "mandible-front", 2500.0, "2.5-3.1 kN",
     "7 human mandibles struck by a pendulum, fronto-median blow; the fracture threshold",
     "Fracture properties of the human mandible, Int. J. Legal Med. 2003, "
     "doi:10.1007/s00414-003-0391-6"},
    {HeadArea::kMandibleSide, "mandible-side", 600.0, "0.6-0.8 kN",
     "7 human mandibles struck by a pendulum, lateral blow; the fracture threshold",
     "Fracture properties of the human mandible, Int. J. Legal Med. 2003, "
     "doi:10.1007/s00414-003-0391-6"},
}};

}  // namespace

std::span<const FractureForce> FractureForces() noexcept { return kTable; }

const FractureForce& FractureForceOf(HeadArea area) noexcept {
  return kTable[static_cast<std::size_t>(area)];
}

std::string_view ToString(HeadArea area) noexcept { return FractureForceOf(area).name; }

std::optional<HeadArea> ParseHeadArea(std::string_view name) noexcept {
  for (const FractureForce& row : kTable) {
    if (internal::EqualsIgnoringCase(row.name, name)) return row.area;
  }
  return std::nullopt;
}

std::string HeadAreaChoices() {
  std::string choices;
  for (const FractureForce& row : kTable) {
    if (!choices.empty()) choices += ", ";
    choices += row.name;
  }
  return choices;
}

HeadArea ParseHeadAreaOrThrow(std::string_view field, std::string_view name) {
  if (const std::optional<HeadArea> area = ParseHeadArea(name)) return *area;
  throw std::invalid_argument(std::string(field) + " must be one of " + HeadAreaChoices() + " (got \"" +
                              internal::EscapeControlCharacters(name) + "\")");
}

}  // namespace covopt
