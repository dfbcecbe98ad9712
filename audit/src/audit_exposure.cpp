// The exposure zones of an audit (AuditSetup::exposure_zones) resolved against the regions it
// judges: the predicate of audit_internal.hpp's Exposure.
#include <cctype>
#include <cmath>
#include <cstddef>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <covopt/core/number_format.hpp>
#include <covopt/materials/body_regions.hpp>
#include <covopt/scene_file/exposure_file.hpp>

#include "audit_internal.hpp"

namespace covopt::audit::detail {
namespace {

/// "above the table (exposure.toml:3:1)": the zone as a message names it.
std::string ZoneWhere(const ExposureZone& zone, std::size_t index) {
  std::string where = "exposure_zones[" + std::to_string(index) + "] '" + zone.name + "'";
  if (!zone.origin.empty()) where = zone.origin + ": " + where;
  return where;
}

constexpr const char* kAxes[] = {"x", "y", "z"};

std::string Lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string Corner(const Eigen::Vector3d& p) {
  std::string out = "[";
  for (int k = 0; k < 3; ++k) out += (k ? ", " : "") + FormatShortest(p[k]);
  return out + "]";
}

/// Marks in `mask` the judged regions `name` stands for. A name of the table's (or the head)
/// that the audit does not judge marks nothing; a name that is no region throws.
void MarkRegions(const AuditSetup& setup, const std::vector<std::string>& names, const std::string& name,
                 const std::string& where, std::vector<std::uint8_t>& mask) {
  const std::string key = Lower(name);
  if (key == "all") {
    mask.assign(mask.size(), 1);
    return;
  }
  bool known = false;
  for (std::size_t r = 0; r < names.size(); ++r) {
    if (Lower(names[r]) == key) mask[r] = 1, known = true;
  }
  if (key == "head" || key == "head (park et al. 2011)") {
    if (setup.head) mask[names.size() - 1] = 1;
    return;
  }
  if (known) return;
  // A region of the table (all its areas), or one the audit does not judge here: marks nothing.
  if (const auto problem = scene_file::ExposureRegionProblem(name)) throw std::invalid_argument(where + ": regions: " + *problem);
  const std::string canonical = materials::BodyRegionTable::BuiltIn().Region(key.substr(0, key.find(" ("))).name;
  if (key.find(" (") != std::string::npos) return;  // an area the audit does not judge
  for (std::size_t r = 0; r < setup.regions.size(); ++r) {
    if (setup.regions[r].region->name == canonical) mask[r] = 1;
  }
}

}  // namespace

Exposure::Exposure(const AuditSetup& setup, const std::vector<std::string>& region_names)
    : n_regions_(region_names.size()), anywhere_(region_names.size(), 0) {
  std::set<std::string> seen;
  for (std::size_t i = 0; i < setup.exposure_zones.size(); ++i) {
    const ExposureZone& zone = setup.exposure_zones[i];
    const std::string where = ZoneWhere(zone, i);
    if (zone.name.empty()) throw std::invalid_argument(where + ": name: empty (each zone needs one)");
    if (!seen.insert(zone.name).second) {
      throw std::invalid_argument(where + ": name: '" + zone.name + "' names two zones (each zone's name is its own)");
    }
    if (!zone.min_m.allFinite() || !zone.max_m.allFinite()) {
      throw std::invalid_argument(where + ": min_m " + Corner(zone.min_m) + ", max_m " + Corner(zone.max_m) +
                                  ": every coordinate must be a finite number [m]");
    }
    for (int k = 0; k < 3; ++k) {
      if (zone.min_m[k] > zone.max_m[k]) {
        throw std::invalid_argument(where + ": min_m " + Corner(zone.min_m) + " lies above max_m " +
                                    Corner(zone.max_m) + " along " + kAxes[k] +
                                    " (min_m must be <= max_m on every axis)");
      }
    }
    if (zone.regions.empty()) {
      throw std::invalid_argument(where + ": regions: empty (name the body regions a person can present there)");
    }
    Zone z{zone.min_m, zone.max_m, std::vector<std::uint8_t>(n_regions_, 0)};
    for (const std::string& name : zone.regions) MarkRegions(setup, region_names, name, where, z.regions);
    for (std::size_t r = 0; r < n_regions_; ++r) anywhere_[r] |= z.regions[r];
    zones_.push_back(std::move(z));
  }
}

}  // namespace covopt::audit::detail
