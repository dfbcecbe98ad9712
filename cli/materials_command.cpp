#include "materials_command.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <exception>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include "covopt/materials/material.hpp"
#include "covopt/chart/curve_chart.hpp"
#include "covopt/report/materials_json.hpp"
#include "covopt/report/materials_text.hpp"
#include "covopt/scene_file/range.hpp"
#include "catalog_options.hpp"
#include "errors.hpp"
#include "output_options.hpp"
#include "plot.hpp"

namespace covopt::cli {
namespace {

using materials::Catalog;
using materials::Material;
using Json = nlohmann::ordered_json;

constexpr std::string_view kSpaces = " \t";

std::string_view Trim(std::string_view s) {
  const auto first = s.find_first_not_of(kSpaces);
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(kSpaces) - first + 1);
}

std::string Quoted(const std::vector<std::string>& words) {
  std::string joined;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) joined += (i + 1 == words.size()) ? " or " : ", ";
    joined += "'" + words[i] + "'";
  }
  return joined;
}

constexpr std::array kBases{materials::ModulusBasis::kCompressive, materials::ModulusBasis::kTensile,
                            materials::ModulusBasis::kBending,     materials::ModulusBasis::kFitted,
                            materials::ModulusBasis::kAsPrinted,   materials::ModulusBasis::kHardness};

std::vector<std::string> BasisNames() {
  std::vector<std::string> names;
  for (const auto basis : kBases) names.emplace_back(materials::ToString(basis));
  return names;
}


/// --strength: a bare end is Pa and must be plausible for a compressive strength.
constexpr QuantitySpec kStrengthSpec{QuantityKind::kModulus,
                                     false,
                                     false,
                                     materials::kPlausibleStrengthMin_Pa,
                                     materials::kPlausibleStrengthMax_Pa,
                                     {"kPa", "MPa"},
                                     "compressive strength"};

/// --stress-at-25: a bare end is Pa and must be plausible for a curve's stress.
constexpr QuantitySpec kStressAt25Spec{QuantityKind::kModulus, false, false, 100.0, 1e9, {"kPa", "MPa"},
                                       "stress at 25 %"};

constexpr std::array kCrushBehaviours{materials::CrushBehaviour::kCrushes,
                                      materials::CrushBehaviour::kDoesNotCrush,
                                      materials::CrushBehaviour::kUnknown};

std::vector<std::string> CrushNames() {
  std::vector<std::string> names;
  for (const auto b : kCrushBehaviours) names.emplace_back(materials::ToString(b));
  return names;
}

std::string CatalogDescription(const CatalogOptions& options) {
  std::vector<std::string> parts;
  if (!options.no_builtin) parts.emplace_back("the built-in catalog");
  for (const std::string& file : options.files) parts.push_back(file);
  std::string joined;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i > 0) joined += (i + 1 == parts.size()) ? " and " : ", ";
    joined += parts[i];
  }
  return joined;
}

std::string Plural(std::size_t n, std::string_view word) {
  return fmt::format("{} {}{}", n, word, n == 1 ? "" : "s");
}

/// The filter `find`'s options describe, checked against the catalog (families).
materials::MaterialFilter ResolveFilter(const MaterialsOptions& o, const Catalog& catalog) {
  materials::MaterialFilter filter;
  // The named specs, so that a bare end is checked as a bare number is everywhere else
  // ("--modulus 10..100" would be 10 Pa to 100 Pa).
  if (o.modulus) {
    filter.youngs_modulus_Pa =
        ParseRange(*o.modulus, quantity_specs::kCoveringModulus, "--modulus");
  }
  if (o.poisson) {
    filter.poisson_ratio = ParseRange(*o.poisson, {QuantityKind::kDimensionless}, "--poisson");
  }
  if (o.density) {
    filter.density_kg_per_m3 =
        ParseRange(*o.density, quantity_specs::kMaterialDensity, "--density");
  }
  if (o.strength) {
    filter.compressive_strength_Pa = ParseRange(*o.strength, kStrengthSpec, "--strength");
  }
  if (o.stress_at_25) {
    filter.stress_at_25_Pa = ParseRange(*o.stress_at_25, kStressAt25Spec, "--stress-at-25");
  }
  filter.has_curve = o.has_curve;
  for (const std::string& crush : o.crush) {
    const auto parsed = materials::ParseCrushBehaviour(crush);
    if (!parsed) {
      throw InputError(fmt::format("--crush: expected {} (got '{}')", Quoted(CrushNames()), crush));
    }
    filter.crush_behaviours.push_back(*parsed);
  }
  const std::vector<std::string> families = catalog.families();
  for (const std::string& family : o.families) {
    const bool known = std::any_of(families.begin(), families.end(), [&](const std::string& f) {
      return f.size() == family.size() &&
             std::equal(f.begin(), f.end(), family.begin(), [](char a, char b) {
               return std::tolower(static_cast<unsigned char>(a)) ==
                      std::tolower(static_cast<unsigned char>(b));
             });
    });
    if (!known) {
      throw InputError(fmt::format("--family: no family '{}' in the catalog; the families are {}",
                                   family, Quoted(families)));
    }
    filter.families.push_back(family);
  }
  for (const std::string& basis : o.bases) {
    const auto parsed = materials::ParseModulusBasis(basis);
    if (!parsed) {
      throw InputError(fmt::format("--basis: expected {} (got '{}')", Quoted(BasisNames()), basis));
    }
    filter.bases.push_back(*parsed);
  }
  if (o.name_contains) filter.name_contains = *o.name_contains;
  filter.include_unknown = o.include_unknown;
  return filter;
}

/// What the filter asks for, in words, for the closing line.
std::string DescribeFilter(const MaterialsOptions& o) {
  std::vector<std::string> parts;
  if (o.modulus) parts.push_back("E " + *o.modulus);
  if (o.poisson) parts.push_back("ν " + *o.poisson);
  if (o.density) parts.push_back("ρ " + *o.density);
  if (o.strength) parts.push_back("strength " + *o.strength);
  if (o.stress_at_25) parts.push_back("σ(25 %) " + *o.stress_at_25);
  if (o.has_curve) parts.push_back("has a compressive curve");
  if (!o.crush.empty()) parts.push_back("crush " + fmt::format("{}", fmt::join(o.crush, "|")));
  if (!o.families.empty()) parts.push_back("family " + fmt::format("{}", fmt::join(o.families, "|")));
  if (!o.bases.empty()) parts.push_back("basis " + fmt::format("{}", fmt::join(o.bases, "|")));
  if (o.name_contains) parts.push_back("name contains '" + *o.name_contains + "'");
  if (parts.empty()) return "no conditions";
  return fmt::format("{}", fmt::join(parts, ", "));
}

/// " N were left out for want of a curve (through 25 %)." when the filter asks for a curve.
std::string ExcludedLine(const Catalog& catalog, const materials::MaterialFilter& filter) {
  if (!filter.needs_curve()) return {};
  const std::size_t n = catalog.ExcludedForWantOfCurve(filter);
  return fmt::format(" {} that pass{} the other conditions {} left out: {}.", Plural(n, "material"),
                     n == 1 ? "es" : "", n == 1 ? "was" : "were",
                     filter.stress_at_25_Pa.unbounded() ? "no compressive curve" : "no compressive curve through 25 %");
}

/// Why `materials show --plot FILE` cannot draw: no curve, or a file name that is not a chart's.
std::optional<std::string> PlotProblem(const Material& m, const std::string& file) {
  if (!PlotFormatFor(file)) {
    return fmt::format("--plot: cannot tell the format of '{}'; name the file *.png or *.svg", file);
  }
  if (!m.compressive_curve) {
    return fmt::format("--plot: material '{}' has no compressive curve to draw (materials find --has-curve lists "
                       "those that have one)",
                       m.name);
  }
  return std::nullopt;
}

}  // namespace


Json MaterialToJson(const Material& m) { return Json::parse(report::MaterialJson(m)); }

void SetupMaterials(CLI::App* materials, MaterialsOptions& options) {
  materials->require_subcommand(1);
  materials->footer(
      "The built-in catalog holds sourced foams, elastomers and paddings, among them the\n"
      "paper's Table IV coverings. Every entry states how its E was obtained (compressive,\n"
      "tensile, bending, fitted, as-printed, hardness): compare like with like. Each\n"
      "states its compressive strength, or that it does not crush, or that it is unknown.\n"
      "Some carry a compressive curve (measured points, or a grade band with a named shape):\n"
      "materials find --has-curve lists them, materials show NAME --plot FILE draws one.\n"
      "Exit codes: 0 done; 2 bad input.");

  CLI::App* list = materials->add_subcommand("list", "List every material: name, family, E, ν, "
                                                     "density, strength and the basis of E");
  AddJsonFlag(*list, options.json, "print a JSON array of objects (SI units)");
  AddCatalogOptions(*list, options.catalog);
  list->callback([&options] { options.action = MaterialsAction::kList; });

  CLI::App* show = materials->add_subcommand(
      "show",
      "Show one material with its source, how its E was obtained and its compressive "
      "strength (or that it does not crush) with the strength's method and source");
  // The name may come as one quoted argument or as several words.
  show->add_option_function<std::vector<std::string>>(
          "name",
          [&options](const std::vector<std::string>& words) {
            options.name.clear();
            for (const std::string& word : words) {
              if (!options.name.empty()) options.name += ' ';
              options.name += word;
            }
          },
          "the material's name, ignoring case, e.g. \"polystyrene foam 27.6\"")
      ->type_name("NAME")
      ->required();
  AddJsonFlag(*show, options.json, "print the material as one JSON object (SI units)");
  AddOutputFileOption(*show, "--plot", options.plot_file,
                      "chart with gnuplot: the material's compressive curve (stress and W over strain)",
                      "FILE.png|FILE.svg");
  AddCatalogOptions(*show, options.catalog);
  show->callback([&options] { options.action = MaterialsAction::kShow; });

  CLI::App* find = materials->add_subcommand(
      "find",
      "Find materials by ranges of E, ν, density and strength, by crush behaviour, family, "
      "basis or name");
  find->add_option("--modulus", options.modulus,
                   "Young's modulus range, e.g. 10MPa..100MPa, 10MPa.. or ..100MPa")
      ->type_name("LO..HI")
      ->group("Filters");
  find->add_option("--poisson", options.poisson, "Poisson ratio range, e.g. 0.2..0.3")
      ->type_name("LO..HI")
      ->group("Filters");
  find->add_option("--density", options.density,
                   "density range in kg/m3 or g/cm3, e.g. ..60kg/m3")
      ->type_name("LO..HI")
      ->group("Filters");
  find->add_option("--strength", options.strength,
                   "compressive strength range, e.g. 100kPa..1MPa or 1MPa..: keeps only "
                   "materials whose strength is known and in range (not those that do not "
                   "crush, nor those whose strength is unknown)")
      ->type_name("LO..HI")
      ->group("Filters");
  find->add_option("--stress-at-25", options.stress_at_25,
                   "range of the compressive curve's stress at 25 % strain, e.g. 30kPa..80kPa: keeps only "
                   "materials with a curve through 25 % (the output says how many were left out for want of one)")
      ->type_name("LO..HI")
      ->group("Filters");
  find->add_flag("--has-curve", options.has_curve, "keep only materials with a compressive curve")
      ->group("Filters");
  find->add_option("--crush", options.crush,
                   "keep this crush behaviour: crushes, does-not-crush or unknown; repeatable: "
                   "any of them")
      ->type_name("BEHAVIOUR")
      ->allow_extra_args(false)
      ->group("Filters");
  find->add_option("--family", options.families,
                   "keep this family (foam, elastomer, padding, ...); repeatable: any of them")
      ->type_name("FAMILY")
      ->allow_extra_args(false)
      ->group("Filters");
  find->add_option("--basis", options.bases,
                   "keep this basis of E (compressive, tensile, bending, fitted, as-printed, "
                   "hardness); repeatable")
      ->type_name("BASIS")
      ->allow_extra_args(false)
      ->group("Filters");
  find->add_option("--name", options.name_contains, "keep names containing TEXT (ignoring case)")
      ->type_name("TEXT")
      ->group("Filters");
  find->add_flag("--include-unknown", options.include_unknown,
                 "let materials whose ν or density is unknown pass a --poisson or --density "
                 "range (by default they are left out)")
      ->group("Filters");
  AddJsonFlag(*find, options.json, "print a JSON array of objects (SI units)");
  AddCatalogOptions(*find, options.catalog);
  find->footer("Ranges are closed; a bare number is SI (Pa, kg/m³) and must be plausible\n"
               "(--modulus 10..100 is refused: write 10MPa..100MPa). Units: Pa, kPa, MPa, GPa;\n"
               "kg/m3, g/cm3. Exit codes: 0 done (also when nothing matches); 2 bad input.");
  find->callback([&options] { options.action = MaterialsAction::kFind; });
}

int RunMaterials(const MaterialsOptions& options, std::ostream& out, std::ostream& err) {
  const std::string_view command = options.action == MaterialsAction::kShow   ? "show"
                                   : options.action == MaterialsAction::kFind ? "find"
                                                                              : "list";
  const CommandErrors errors(err, std::string("materials ").append(command));

  Catalog catalog;
  try {
    catalog = LoadCatalog(options.catalog);
  } catch (const InputError& e) {
    return errors.BadInput(e.what());
  }
  const std::string where = CatalogDescription(options.catalog);

  switch (options.action) {
    case MaterialsAction::kNone:
      return errors.BadInput("no subcommand given; use list, show or find");
    case MaterialsAction::kList: {
      std::vector<const Material*> rows;
      for (const Material& m : catalog.materials()) rows.push_back(&m);
      if (options.json) {
        out << report::MaterialsJson(rows) << '\n';
      } else {
        report::PrintMaterialTable(out, rows, fmt::format("{} ({}).", Plural(rows.size(), "material"), where));
      }
      break;
    }
    case MaterialsAction::kShow: {
      const Material* m = catalog.Find(Trim(options.name));
      if (m == nullptr) return errors.BadInput(NoSuchMaterial(catalog, Trim(options.name)));
      if (options.plot_file) {
        if (auto problem = PlotProblem(*m, *options.plot_file)) return errors.BadInput(*problem);
        try {
          RunGnuplot(*options.plot_file, chart::CompressiveCurveChart(*m));
        } catch (const OutputError& e) {
          return errors.Failed(e);
        }
      }
      if (options.json) {
        out << WithRunProvenance(report::MaterialJson(*m), options.run) << '\n';
      } else {
        report::PrintMaterial(out, *m);
        if (options.plot_file) fmt::print(out, "\nWrote      {}\n", *options.plot_file);
      }
      break;
    }
    case MaterialsAction::kFind: {
      materials::MaterialFilter filter;
      try {
        filter = ResolveFilter(options, catalog);
      } catch (const InputError& e) {
        return errors.BadInput(e.what());
      }
      const std::vector<const Material*> rows = catalog.Filter(filter);
      const std::string excluded = ExcludedLine(catalog, filter);
      if (options.json) {
        out << report::MaterialsJson(rows) << '\n';
      } else if (rows.empty()) {
        fmt::print(out, "No material of {} ({}) matches {}.{}\n", where,
                   Plural(catalog.size(), "material"), DescribeFilter(options), excluded);
      } else {
        report::PrintMaterialTable(out, rows,
                           fmt::format("{} of {} match {} ({}).{}", rows.size(),
                                       Plural(catalog.size(), "material"),
                                       DescribeFilter(options), where, excluded));
      }
      break;
    }
  }
  out.flush();
  if (!out) return errors.Failed("cannot write to standard output");
  return 0;
}

}  // namespace covopt::cli
