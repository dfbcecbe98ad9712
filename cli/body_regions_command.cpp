#include "body_regions_command.hpp"

#include <algorithm>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/materials/body_regions.hpp"
#include "covopt/scene_file/targets.hpp"
#include "covopt/report/body_regions_json.hpp"
#include "covopt/report/body_regions_text.hpp"
#include "body_region_options.hpp"
#include "errors.hpp"
#include "catalog_options.hpp"
#include "output_options.hpp"

namespace covopt::cli {

using materials::BodyRegion;
using materials::BodyRegionTable;

void SetupBodyRegions(CLI::App* command, BodyRegionsOptions& options) {
  command->require_subcommand(1);
  command->footer(
      "Tables A.2 (biomechanical limits) and A.3 (effective spring constant and mass) of\n"
      "ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M: 12 regions, 29 areas; --limits FILE\n"
      "shows a table of your own (docs/guide/limits.md). Exit codes: 0 done; 2 bad input.");

  CLI::App* list = command->add_subcommand(
      "list", "List every area: its region's forces, its pressures, k and m_H");
  AddJsonFlag(*list, options.json, "print a JSON array of the regions (SI units)");
  AddLimitsOption(*list, options.limits);
  list->callback([&options] { options.action = BodyRegionsAction::kList; });

  CLI::App* show = command->add_subcommand(
      "show", "Show one region: its limits, k, m_H, areas and sources");
  show->add_option("name", options.name,
                   "the region's name, ignoring case, \"_\", \"/\" and \" \" read as \"-\", e.g. "
                   "hands-fingers, chest, \"hands and fingers\"")
      ->type_name("NAME")
      ->required();
  AddJsonFlag(*show, options.json, "print the region as one JSON object (SI units)");
  AddLimitsOption(*show, options.limits);
  show->callback([&options] { options.action = BodyRegionsAction::kShow; });
}

int RunBodyRegions(const BodyRegionsOptions& options, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(
      err, options.action == BodyRegionsAction::kShow ? "body-regions show" : "body-regions list");
  const BodyRegionTable* limits = nullptr;
  try {
    limits = &scene_file::LimitTable(options.limits);
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(AsFlags(e.what()));
  }
  const BodyRegionTable& table = *limits;
  switch (options.action) {
    case BodyRegionsAction::kNone:
      return errors.BadInput("no subcommand given; use list or show");
    case BodyRegionsAction::kList:
      if (options.json) {
        out << report::BodyRegionsJson(table.regions()) << '\n';
      } else {
        report::PrintBodyRegionTable(out, table);
      }
      break;
    case BodyRegionsAction::kShow: {
      const BodyRegion* region = nullptr;
      try {
        region = &table.Region(options.name);
      } catch (const materials::BodyRegionError& e) {
        return errors.BadInput(AsFlags(e.what()));  // "(... --body-region head)"
      }
      if (options.json) {
        out << WithRunProvenance(report::BodyRegionJson(*region), options.run) << '\n';
      } else {
        report::PrintBodyRegion(out, *region);
      }
      break;
    }
  }
  out.flush();
  if (!out) return errors.Failed("cannot write to standard output");
  return 0;
}

}  // namespace covopt::cli
