#include "catalog_options.hpp"

#include <CLI/CLI.hpp>

#include "covopt/scene_file/range.hpp"
#include "errors.hpp"

namespace covopt::cli {

using materials::Catalog;

void AddCatalogOptions(CLI::App& command, CatalogOptions& options) {
  command
      .add_option("--catalog", options.files,
                  "a catalog file (TOML, the format of materials/data/catalog.toml) added to "
                  "the built-in catalog; repeatable")
      ->type_name("FILE.toml")
      ->allow_extra_args(false)
      ->group("Catalog");
  command
      .add_flag("--no-builtin", options.no_builtin,
                "use only the --catalog files, not the built-in catalog")
      ->group("Catalog");
}

materials::Catalog LoadCatalog(const CatalogOptions& options) {
  if (options.no_builtin && options.files.empty()) {
    throw InputError("--no-builtin leaves no catalog; add --catalog FILE");
  }
  try {
    Catalog catalog = options.no_builtin ? Catalog() : Catalog::BuiltIn();
    for (const std::string& file : options.files) catalog.Add(Catalog::FromTomlFile(file));
    return catalog;
  } catch (const materials::CatalogError& e) {
    throw InputError(e.what());
  }
}

std::string NoSuchMaterial(const materials::Catalog& catalog, std::string_view name) {
  return catalog.MissingMaterialMessage(name);
}

materials::Range ParseRange(std::string_view text, const QuantitySpec& spec,
                            std::string_view name) {
  return AsInputError([&] {
    return scene_file::ParseQuantityRange(text, spec, name, name == "--strength" ? "100kPa..1MPa" : "");
  });
}

}  // namespace covopt::cli
