/// @file body_regions.cpp
/// covopt.body_regions and covopt.body_region_limits: the body-region table of ISO/TS
/// 15066:2016 Annex A = ISO 10218-2:2025 Annex M (materials::BodyRegionTable::BuiltIn()), or the
/// user's own (limits=). The regions are report::BodyRegionsJson's
/// objects, those `covopt body-regions list --json` prints. See python/covopt/__init__.py for
/// the documentation.

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "covopt/core/body_contact.hpp"
#include "covopt/materials/body_regions.hpp"
#include "covopt/report/body_regions_json.hpp"
#include "covopt/scene_file/targets.hpp"
#include "body_region_inputs.hpp"
#include "scene_keywords.hpp"

namespace py = pybind11;

namespace covopt::python {
namespace {

using materials::BodyRegionTable;

/// The table limits= names (the built-in one without it); a bad table raises ValueError.
const BodyRegionTable& Table(const py::dict& kwargs) {
  const std::optional<std::string> path = LimitsPath(kwargs);
  try {
    return scene_file::LimitTable(path);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(AsKeywords(e.what()));
  }
}

py::object BodyRegions(const py::kwargs& kwargs) {
  return JsonToPython(report::BodyRegionsJson(Table(kwargs).regions(), -1));
}

/// The limits of one area under one contact; bad names raise ValueError with the library's
/// message.
py::dict BodyRegionLimits(const std::string& region, const std::optional<std::string>& area,
                          const std::string& contact, const py::kwargs& kwargs) {
  const BodyRegionTable& table = Table(kwargs);
  const std::optional<ContactType> type = ParseContactType(contact);
  if (!type) {
    throw std::invalid_argument("contact: expected 'transient' or 'clamped' (got '" + contact +
                                "')");
  }
  const materials::BodyLimits limits = [&] {
    try {
      return table.Limits(region, area.value_or(""), *type);
    } catch (const materials::BodyRegionError& e) {
      throw std::invalid_argument(AsKeywords(e.what()));  // "use contact='clamped'"
    }
  }();
  py::dict result;
  result["region"] = limits.region->name;
  result["area"] = limits.area->name;
  result["area_number"] = limits.area->number;
  result["contact"] = std::string(ToString(limits.contact));
  result["force_N"] = limits.force_N;
  result["pressure_Pa"] = limits.pressure_Pa;
  result["stiffness_N_per_m"] = limits.stiffness_N_per_m();
  result["effective_mass_kg"] = limits.effective_mass_kg();
  result["describe"] = limits.Describe();
  result["edition"] = limits.Citation();
  return result;
}

}  // namespace

void RegisterBodyRegions(py::module_& m) {
  m.def("body_regions", &BodyRegions);
  m.def("body_region_limits", &BodyRegionLimits, py::arg("region"), py::arg("area"),
        py::arg("contact"));
  // The library's resolver decides what names the head (scene_file/targets.hpp).
  m.def("names_the_head", [](std::string_view name) { return scene_file::NamesTheHead(name); }, py::arg("name"));
}

}  // namespace covopt::python
