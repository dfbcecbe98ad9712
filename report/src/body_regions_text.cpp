#include "covopt/report/body_regions_text.hpp"

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/report/body_regions_json.hpp"
#include "covopt/report/wrap_words.hpp"

namespace covopt::report {
namespace {

using materials::BodyArea;
using materials::BodyRegion;
using materials::BodyRegionTable;

constexpr double kNPerCm2 = 1e4;  // Pa
constexpr double kNPerMm = 1e3;   // N/m

/// A value of the table in the standard's units, as it prints them ("140", "4.4", "0.6").
std::string Value(double value) { return fmt::format("{:g}", value); }

}  // namespace

void PrintBodyRegionTable(std::ostream& out, const BodyRegionTable& table) {
  std::size_t region_width = 6;
  std::size_t area_width = 4;
  for (const BodyRegion& r : table.regions()) {
    region_width = std::max(region_width, r.name.size());
    for (const BodyArea& a : r.areas) area_width = std::max(area_width, a.name.size());
  }
  const auto row = [&](std::string_view region, std::string_view area, std::string_view number,
                       std::string_view f_qs, std::string_view f_tr, std::string_view p_qs,
                       std::string_view p_tr, std::string_view k, std::string_view m) {
    fmt::print(out, "{:<{}}  {:<{}}  {:>3}  {:>8}  {:>13}  {:>12}  {:>12}  {:>8}  {:>8}\n", region,
               region_width, area, area_width, number, f_qs, f_tr, p_qs, p_tr, k, m);
  };
  row("region", "area", "no.", "F_qs [N]", "F_tr [N]", "p_qs [N/cm²]", "p_tr [N/cm²]",
      "k [N/mm]", "m_H [kg]");
  for (const BodyRegion& r : table.regions()) {
    const bool transient = r.transient_permitted();
    for (const BodyArea& a : r.areas) {
      row(r.name, a.name, std::to_string(a.number), Value(r.quasi_static_force_N),
          transient ? Value(r.transient_factor * r.quasi_static_force_N) : "not permitted",
          Value(a.quasi_static_pressure_Pa / kNPerCm2),
          transient ? Value(r.transient_factor * a.quasi_static_pressure_Pa / kNPerCm2) : "–",
          Value(r.stiffness_N_per_m / kNPerMm), Value(r.effective_mass_kg));
    }
  }
  const materials::LimitTableInfo& info = table.info();
  fmt::print(out,
             "\n{} regions, {} areas: {} ({}). F: force per region, p: pressure per area; qs "
             "quasi-static, tr transient; k: effective spring constant, m_H: effective mass.\n",
             table.regions().size(), table.area_count(), info.title, info.edition);
  fmt::print(out, "limit table: {}, sha256 {}\n", info.source, info.sha256);
  fmt::print(out,
             "not permitted: {} permits no transient contact with these regions (their "
             "quasi-static limits apply when clamped; the head as a whole is judged by Park et "
             "al.'s skin model).\n",
             info.NoTransientClause());
  fmt::print(out, "Titles, the default area and the sources: covopt body-regions show NAME\n");
}

namespace {

void Row(std::ostream& out, std::string_view label, std::string_view value) {
  PrintWrappedRow(out, label, 20, value, 72);
}

}  // namespace

void PrintBodyRegion(std::ostream& out, const BodyRegion& r) {
  fmt::print(out, "{}: {} ({})\n", r.name, r.title,
             r.table ? r.table->edition : materials::BuiltInEdition());
  Row(out, "quasi-static force", fmt::format("F_qs = {} N", Value(r.quasi_static_force_N)));
  Row(out, "transient contact",
      r.transient_permitted()
          ? fmt::format("{}: F_tr = {} N", TransientRule(r),
                        Value(r.transient_factor * r.quasi_static_force_N))
          : TransientRule(r) +
                ": its quasi-static limits apply when clamped; the head as a whole is judged "
                "by Park et al.'s skin model");
  Row(out, "spring constant",
      fmt::format("k = {} N/mm ({} N/m)", Value(r.stiffness_N_per_m / kNPerMm),
                  Value(r.stiffness_N_per_m)));
  Row(out, "effective mass",
      fmt::format("m_H = {} kg (infinite when clamped)", Value(r.effective_mass_kg)));
  const BodyArea& lowest = r.LowestPressureArea();
  Row(out, "default area", fmt::format("{} (the lowest pressure)", lowest.name));
  fmt::print(out, "  areas:\n");
  std::size_t name_width = 4;
  std::size_t title_width = 5;
  for (const BodyArea& a : r.areas) {
    name_width = std::max(name_width, a.name.size());
    title_width = std::max(title_width, a.title.size());
  }
  fmt::print(out, "    {:>3}  {:<{}}  {:<{}}  {:>12}  {:>12}\n", "no.", "area", name_width,
             "title", title_width, "p_qs [N/cm²]", "p_tr [N/cm²]");
  for (const BodyArea& a : r.areas) {
    fmt::print(out, "    {:>3}  {:<{}}  {:<{}}  {:>12}  {:>12}\n", a.number, a.name, name_width,
               a.title, title_width, Value(a.quasi_static_pressure_Pa / kNPerCm2),
               r.transient_permitted()
                   ? Value(r.transient_factor * a.quasi_static_pressure_Pa / kNPerCm2)
                   : "–");
  }
  fmt::print(out, "  sources (the open copies of the tables its values were checked against):\n");
  for (const std::string& source : r.sources) {
    const std::vector<std::string> lines = WrapWords(source, 88);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      fmt::print(out, "    {} {}\n", i == 0 ? "-" : " ", lines[i]);
    }
  }
  if (r.table) fmt::print(out, "  limit table: {} ({}, sha256 {})\n", r.table->title, r.table->source, r.table->sha256);
}

}  // namespace covopt::report
