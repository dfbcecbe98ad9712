#pragma once
/// @file body_region_inputs.hpp
/// The body-region keywords (body_region, body_area, contact, contact_area, the criterion
/// flags) as body_contact.cpp reads them, for the other binding files (covopt.audit).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <pybind11/pybind11.h>

#include "covopt/core/body_contact.hpp"
#include "covopt/materials/body_regions.hpp"
#include "covopt/optim/body_region_check.hpp"
#include "scene_keywords.hpp"

namespace covopt::python {

/// What the keywords name.
struct BodyRegionSelection {
  std::vector<materials::BodyLimits> limits;  ///< the ISO regions' limits, in order
  bool head = false;                          ///< the head (Park et al.) too
  ContactType contact = ContactType::kTransient;
  double contact_area_m2 = 0.0;               ///< contact_area=; 0: not given
  /// The safety factor, allow_full_compression=, allow_crushing=, and the covering's catalog
  /// material (material=) with its crush data.
  optim::BodyRegionOptions judge;
};

/// limits= of `kwargs`: the path of a body-region table file (a str or os.PathLike); none: the
/// built-in table. @throws std::invalid_argument for another type.
std::optional<std::string> LimitsPath(const pybind11::dict& kwargs);

/// A library message naming the body-region fields (body.region, body.contact=clamped) with
/// the keywords (body_region, contact='clamped'): Python's one table of their spellings.
std::string AsKeywords(std::string_view message);

/// Reads body_region= ("all", a name, "head" or a list), body_area=, contact=,
/// contact_area= and the criterion flags of `kwargs`, as covopt.simulate(body_region=...).
/// @throws std::invalid_argument naming the keyword and the value.
BodyRegionSelection SelectBodyRegions(const SceneInputs& inputs, const pybind11::kwargs& kwargs);

/// One ISO region's contact as covopt.simulate(body_region=...) reads it: one region (not the
/// head), no keyword the body-region model does not read, the bare robot's contact area; the
/// robot's contact scene, the judging options and the warnings simulate gives for it.
struct OneRegionContact {
  materials::BodyLimits limits;
  BodyContactScene scene;
  optim::BodyRegionOptions judge;
  std::optional<std::string> material;  ///< the covering's catalog name, if any
  std::vector<std::string> warnings;
};
/// @throws std::invalid_argument naming the keyword (`function` names the call).
OneRegionContact ReadOneRegionContact(const SceneInputs& inputs, const pybind11::kwargs& kwargs, const char* function);

}  // namespace covopt::python
