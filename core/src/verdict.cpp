#include "covopt/core/verdict.hpp"

#include "covopt/core/number_format.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace covopt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();


bool PartPassed(const Verdict& v, CriterionPart part) noexcept {
  for (const Criterion& c : v.criteria) {
    if (c.part == part && c.counted && !c.passed) return false;
  }
  return true;
}

}  // namespace

std::string_view ToString(CriterionPart part) noexcept {
  switch (part) {
    case CriterionPart::kInjury: return "injury";
    case CriterionPart::kDesignRule: return "design-rule";
  }
  return "unknown";
}

Criterion& Verdict::Add(std::string_view name, CriterionPart part, std::string_view unit, double value,
                        double limit, std::string_view source, bool counted, bool forced_fail) {
  Criterion c;
  c.name = name;
  c.part = part;
  c.unit = unit;
  c.value = value;
  c.limit = limit;
  c.derated_limit = limit / safety_factor;
  c.ratio = value / limit;
  c.counted = counted;
  c.passed = !forced_fail && safety_factor * c.ratio <= 1.0;
  c.source = source;
  criteria.push_back(c);
  return criteria.back();
}

Criterion& AddLawValidity(Verdict& verdict, bool within, double validity_ratio) {
  Criterion& c = verdict.Add(kLawValidityRule, CriterionPart::kDesignRule, "1", validity_ratio, 1.0,
                             "the covering law's validity", true, !within);
  c.derated_limit = 1.0;                                  // the model's range: not derated by the safety factor
  c.ratio = validity_ratio / verdict.safety_factor;       // so SF × ratio is the validity ratio
  c.passed = within;
  if (!within) c.note = "out of the covering law's validity (see the validity note)";
  return c;
}

Criterion& AddLawValidity(Verdict& verdict, bool within) { return AddLawValidity(verdict, within, within ? 0.0 : 1.0); }

const Criterion* Verdict::Find(std::string_view name) const noexcept {
  for (const Criterion& c : criteria) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

const Criterion* Verdict::governing() const noexcept {
  const Criterion* best = nullptr;
  for (const Criterion& c : criteria) {
    if (c.counted && !std::isnan(c.ratio) && (best == nullptr || c.ratio > best->ratio)) best = &c;
  }
  return best;
}

double Verdict::governing_ratio() const noexcept {
  if (!evaluated) return kInf;
  const Criterion* g = governing();
  return g == nullptr ? 0.0 : g->ratio;
}

std::string_view Verdict::governing_name() const noexcept {
  const Criterion* g = governing();
  return g == nullptr ? std::string_view("none") : std::string_view(g->name);
}

double Verdict::margin() const noexcept { return 1.0 - safety_factor * governing_ratio(); }

bool Verdict::injury_safe() const noexcept { return PartPassed(*this, CriterionPart::kInjury); }

bool Verdict::design_rules_met() const noexcept { return PartPassed(*this, CriterionPart::kDesignRule); }

std::vector<std::string> Verdict::CountedNames() const {
  std::vector<std::string> names;
  for (const Criterion& c : criteria) {
    if (c.counted) names.emplace_back(c.name);
  }
  return names;
}

std::string FormatPercent(double fraction) {
  return std::isfinite(fraction) ? FormatFixed(100.0 * fraction, 1) + " %" : std::string("none");
}

std::string_view SafeWord(bool safe) noexcept { return safe ? "SAFE" : "UNSAFE"; }

}  // namespace covopt
