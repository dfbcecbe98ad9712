// covopt.Catalog's extension functions: a catalog of the built-in entries and users' files, its
// materials as the CLI's JSON, and find() with the stress-at-25 and has-curve filters
// (materials::Catalog::Filter, the same library call as `covopt materials find`).
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "covopt/materials/catalog.hpp"
#include "covopt/report/materials_json.hpp"
#include "scene_keywords.hpp"

namespace py = pybind11;

namespace covopt::python {

materials::Catalog LoadCatalogFiles(const std::vector<std::string>& files, bool no_builtin) {
  if (no_builtin && files.empty()) throw std::invalid_argument("no_builtin leaves no catalog; add catalog=FILE");
  materials::Catalog catalog = no_builtin ? materials::Catalog() : materials::Catalog::BuiltIn();
  try {
    for (const std::string& file : files) catalog.Add(materials::Catalog::FromTomlFile(file));
  } catch (const materials::CatalogError& e) {
    throw std::invalid_argument(std::string("catalog: ") + e.what());
  }
  return catalog;
}

namespace {

py::object MaterialsAsPython(const std::vector<const materials::Material*>& rows) {
  return JsonToPython(report::MaterialsJson(rows, -1));
}

py::object CatalogMaterials(const std::vector<std::string>& files, bool no_builtin) {
  const materials::Catalog catalog = LoadCatalogFiles(files, no_builtin);
  std::vector<const materials::Material*> rows;
  for (const materials::Material& m : catalog.materials()) rows.push_back(&m);
  return MaterialsAsPython(rows);
}

py::object CatalogMaterial(const std::vector<std::string>& files, bool no_builtin, const std::string& name) {
  const materials::Catalog catalog = LoadCatalogFiles(files, no_builtin);
  const materials::Material* m = catalog.Find(name);
  if (m == nullptr) throw std::invalid_argument(catalog.MissingMaterialMessage(name));
  return JsonToPython(report::MaterialJson(*m, -1));
}

/// stress_at_25=(low_Pa, high_Pa): either bound may be None; finite, >= 0, low <= high.
materials::Range StressRange(const py::handle& value) {
  const std::string shown = py::repr(value).cast<std::string>();
  const std::string rule = "stress_at_25 must be (low_Pa, high_Pa), stresses in Pa with 0 <= low <= high "
                           "(None for an open end), e.g. (30e3, 80e3) (got " + shown + ")";
  if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) || py::len(value) != 2) {
    throw std::invalid_argument(rule);
  }
  const py::sequence pair = value.cast<py::sequence>();
  materials::Range range;
  std::optional<double>* ends[2] = {&range.min, &range.max};
  for (std::size_t i = 0; i < 2; ++i) {
    const py::object end = pair[i];
    if (end.is_none()) continue;
    if (py::isinstance<py::bool_>(end) || !(py::isinstance<py::int_>(end) || py::isinstance<py::float_>(end))) {
      throw std::invalid_argument(rule);
    }
    const double v = end.cast<double>();
    if (!std::isfinite(v) || v < 0.0) throw std::invalid_argument(rule);
    *ends[i] = v;
  }
  if (range.min && range.max && *range.min > *range.max) throw std::invalid_argument(rule);
  return range;
}

py::dict CatalogFind(const std::vector<std::string>& files, bool no_builtin, const py::object& stress_at_25,
                     bool has_curve, const std::vector<std::string>& families, const std::string& name_contains) {
  const materials::Catalog catalog = LoadCatalogFiles(files, no_builtin);
  materials::MaterialFilter filter;
  if (!stress_at_25.is_none()) filter.stress_at_25_Pa = StressRange(stress_at_25);
  filter.has_curve = has_curve;
  filter.families = families;
  filter.name_contains = name_contains;
  py::dict found;
  found["materials"] = MaterialsAsPython(catalog.Filter(filter));
  found["excluded_for_want_of_curve"] = catalog.ExcludedForWantOfCurve(filter);
  return found;
}

}  // namespace

void BindCatalog(py::module_& m) {
  m.def("catalog_materials", &CatalogMaterials, py::arg("files"), py::arg("no_builtin"));
  m.def("catalog_material", &CatalogMaterial, py::arg("files"), py::arg("no_builtin"), py::arg("name"));
  m.def("catalog_find", &CatalogFind, py::arg("files"), py::arg("no_builtin"), py::arg("stress_at_25"),
        py::arg("has_curve"), py::arg("families"), py::arg("name_contains"));
}

}  // namespace covopt::python
