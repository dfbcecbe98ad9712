// `covopt materials show|find` and compressive curves, run in-process through RunCli: show
// prints the curve's points (as the library holds them), W at the last point, σ(25 %), source,
// rate, recovers and rate factor; --json carries the curve; --plot draws it (gnuplot) and is
// refused for a material without one; find --stress-at-25 and --has-curve keep exactly what
// Catalog::Filter keeps and say how many were left out for want of a curve; a user catalog's
// curve errors are bad input naming file:line:column.

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/materials.hpp"
#include "covopt/chart/charts.hpp"

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using covopt::cli::testing::TempDir;
using covopt::materials::Catalog;
using covopt::materials::Material;
using Catch::Matchers::Contains;
using Json = nlohmann::json;

namespace {

constexpr const char* kVn600 = "vinyl-nitrile foam VN600";

}  // namespace

TEST_CASE("materials show prints the compressive curve with its source, rate and W", "[materials][curve]") {
  const CliRun run = Run({"materials", "show", kVn600});
  REQUIRE(run.exit_code == 0);
  const Material& m = *Catalog::BuiltIn().Find(kVn600);
  for (const char* label : {"curve ", "σ(25 %)", "curve rate", "recovers", "rate factor", "curve source",
                            "strain [%]", "W [kJ/m³]"}) {
    CAPTURE(label);
    CHECK_THAT(run.out, Contains(label));
  }
  CHECK_THAT(run.out, Contains("199 points to 49.63 % strain"));
  CHECK_THAT(run.out, Contains(fmt::format("W at the last point {:.4g} kJ/m³",
                                           m.compressive_curve->total_energy_density_J_per_m3() / 1e3)));
  CHECK_THAT(run.out, Contains("quasi-static"));
  CHECK_THAT(run.out, Contains("1 to 4"));
  CHECK_THAT(run.out, Contains("every 8th of the 199 points shown"));
  // A material without a curve says so.
  CHECK_THAT(Run({"materials", "show", "polystyrene foam 27.6"}).out, Contains("none: only E describes"));
  // A band names its assumed shape and range.
  const CliRun band = Run({"materials", "show", "neoprene sponge D1056 2C2"});
  CHECK_THAT(band.out, Contains("a grade band 34.4738 kPa to 62.0528 kPa stands in"));
  CHECK_THAT(band.out, Contains("assumed: VN600 (NIST), scaled"));
}

TEST_CASE("materials show --json carries the curve as the library holds it", "[materials][curve][json]") {
  const CliRun run = Run({"materials", "show", kVn600, "--json"});
  REQUIRE(run.exit_code == 0);
  const Json j = Json::parse(run.out);
  const Material& m = *Catalog::BuiltIn().Find(kVn600);
  const auto points = m.compressive_curve->points();
  REQUIRE(j["compressive_curve"].size() == points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    CHECK(j["compressive_curve"][i][0].get<double>() == points[i].strain);
    CHECK(j["compressive_curve"][i][1].get<double>() == points[i].stress_Pa);
  }
  CHECK(j["stress_at_25_Pa"].get<double>() == *covopt::materials::StressAt25Pa(m));
  CHECK(j["curve_energy_density_J_per_m3"].get<double>() == m.compressive_curve->total_energy_density_J_per_m3());
  CHECK(j["curve_rate"] == "quasi-static");
  CHECK(j["curve_rate_per_s"].is_null());
  CHECK(j["recovers"] == true);
  CHECK(j["rate_factor"] == Json::array({1.0, 4.0}));
  CHECK(j["stress_at_25_band_Pa"].is_null());
  CHECK(j["curve_shape"].is_null());
  const Json none = Json::parse(Run({"materials", "show", "polystyrene foam 27.6", "--json"}).out);
  for (const char* key : {"compressive_curve", "stress_at_25_Pa", "curve_source", "curve_rate", "recovers",
                          "rate_factor", "stress_at_25_band_Pa", "curve_shape"}) {
    CAPTURE(key);
    CHECK(none[key].is_null());
  }
  const Json pad = Json::parse(Run({"materials", "show", "helmet pad soft (FE card)", "--json"}).out);
  CHECK(pad["curve_rate_per_s"].get<double>() == 20.0);
  CHECK(pad["recovers"] == false);
}

TEST_CASE("materials show --plot draws the curve, and refuses a material without one", "[materials][curve][plot]") {
  const CliRun none = Run({"materials", "show", "polystyrene foam 27.6", "--plot", "x.svg"});
  CHECK(none.exit_code == 2);
  CHECK(none.out.empty());
  CHECK_THAT(none.err, Contains("has no compressive curve to draw"));
  const CliRun format = Run({"materials", "show", kVn600, "--plot", "x.pdf"});
  CHECK(format.exit_code == 2);
  CHECK_THAT(format.err, Contains("name the file *.png or *.svg"));
  if (!covopt::report::FindOnPath("gnuplot")) return;  // drawing needs gnuplot
  const TempDir dir;
  const std::string file = (dir / "vn600.svg").string();
  const CliRun run = Run({"materials", "show", kVn600, "--plot", file});
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("Wrote      " + file));
  REQUIRE(std::filesystem::exists(file));
  CHECK(std::filesystem::file_size(file) > 1000);
}

TEST_CASE("materials find --stress-at-25 keeps what the library keeps and counts those left out",
          "[materials][curve][find]") {
  const CliRun run = Run({"materials", "find", "--stress-at-25", "30kPa..80kPa", "--json"});
  REQUIRE(run.exit_code == 0);
  covopt::materials::MaterialFilter filter;
  filter.stress_at_25_Pa = {30e3, 80e3};
  const auto kept = Catalog::BuiltIn().Filter(filter);
  const Json json = Json::parse(run.out);
  REQUIRE(json.size() == kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) {
    CHECK(json[i]["name"] == kept[i]->name);
    const double s = json[i]["stress_at_25_Pa"].get<double>();
    CHECK(s >= 30e3);
    CHECK(s <= 80e3);
  }
  const CliRun text = Run({"materials", "find", "--stress-at-25", "30kPa..80kPa"});
  REQUIRE(text.exit_code == 0);
  CHECK_THAT(text.out, Contains(fmt::format("{} of {} materials match σ(25 %) 30kPa..80kPa", kept.size(),
                                            Catalog::BuiltIn().size())));
  CHECK_THAT(text.out, Contains(fmt::format("{} materials that pass the other conditions were left out: no "
                                            "compressive curve through 25 %",
                                            Catalog::BuiltIn().ExcludedForWantOfCurve(filter))));
  // --has-curve alone lists every curve.
  const Json curves = Json::parse(Run({"materials", "find", "--has-curve", "--json"}).out);
  for (const Json& m : curves) CHECK(!m["compressive_curve"].is_null());
  std::size_t with_curve = 0;
  for (const Material& m : Catalog::BuiltIn().materials()) with_curve += m.compressive_curve ? 1 : 0;
  CHECK(curves.size() == with_curve);
  // A bare end is Pa and must be plausible, as for every range.
  const CliRun bare = Run({"materials", "find", "--stress-at-25", "30..80"});
  CHECK(bare.exit_code == 2);
  CHECK_THAT(bare.err, Contains("--stress-at-25 30: a bare number is in pascals"));
  const CliRun inverted = Run({"materials", "find", "--stress-at-25", "80kPa..30kPa"});
  CHECK(inverted.exit_code == 2);
}

TEST_CASE("a user catalog's curve is found, and its errors are bad input at file:line:column",
          "[materials][curve][catalog]") {
  const TempDir dir;
  const auto good = dir.Write("mine.toml", R"([[material]]
name = "my sponge"
family = "foam"
youngs_modulus_Pa = "200 kPa"
modulus_basis = "compressive"
source = "a datasheet"
compressive_curve = [[0.1, "30 kPa"], ["25%", "45 kPa"], [0.5, "120 kPa"]]
curve_source = "read off the datasheet"
curve_rate = "quasi-static"
recovers = true
)");
  const Json found = Json::parse(
      Run({"materials", "find", "--no-builtin", "--catalog", good.string(), "--stress-at-25", "40kPa..50kPa", "--json"})
          .out);
  REQUIRE(found.size() == 1);
  CHECK(found[0]["stress_at_25_Pa"].get<double>() == 45e3);
  const auto bad = dir.Write("bad.toml", R"([[material]]
name = "my sponge"
family = "foam"
youngs_modulus_Pa = "200 kPa"
modulus_basis = "compressive"
source = "a datasheet"
compressive_curve = [[0.1, "30 kPa"], [0.05, "45 kPa"]]
curve_source = "read off the datasheet"
curve_rate = "quasi-static"
recovers = true
)");
  const CliRun run = Run({"materials", "list", "--catalog", bad.string()});
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Contains(bad.string() + ":7:39: material 'my sponge': compressive_curve point 2: strain 0.05 "
                                              "must exceed the previous point's 0.1"));
}
