#include "covopt/materials/contact_target.hpp"

#include <algorithm>

namespace covopt::materials {

std::string ContactTarget::Name() const {
  if (!limits) return "head";
  return limits->region->name + " (" + limits->area->name + ")";
}

bool ContactTarget::SameAs(const ContactTarget& other) const noexcept {
  if (is_head() || other.is_head()) return is_head() == other.is_head();
  return limits->region == other.limits->region && limits->area == other.limits->area &&
         limits->contact == other.limits->contact;
}

const BodyRegionTable& ContactTargets::Table() const {
  return table != nullptr ? *table : BodyRegionTable::BuiltIn();
}

bool ContactTargets::has_head() const noexcept {
  return std::any_of(targets.begin(), targets.end(), [](const ContactTarget& t) { return t.is_head(); });
}

bool ContactTargets::has_iso() const noexcept {
  return std::any_of(targets.begin(), targets.end(), [](const ContactTarget& t) { return !t.is_head(); });
}

std::vector<BodyLimits> ContactTargets::IsoLimits() const {
  std::vector<BodyLimits> limits;
  for (const ContactTarget& target : targets) {
    if (target.limits) limits.push_back(*target.limits);
  }
  return limits;
}

std::string ContactTargets::IsoNames(std::size_t shown) const {
  std::string text;
  std::size_t count = 0;
  for (const ContactTarget& target : targets) {
    if (target.is_head()) continue;
    if (count == shown) return text + ", ...";
    text += (count++ > 0 ? ", " : "") + target.limits->region->name;
  }
  return text;
}

}  // namespace covopt::materials
