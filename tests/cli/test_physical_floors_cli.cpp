// The physical floors through the real command line (docs/guide/inputs-and-errors.md,
// "Physical floors"): a length, area, mass, time, modulus, strength or limit below its floor
// is exit 2 with one line naming it, before anything is computed, from a flag, a scene file or
// a catalog; at the floor the answer is finite. A denormal radius once printed
// ">= 100 m/s, limited by none" with -nan ratios; a 1e-300 s reaction delay and a 5e-324 kg
// torso were solver failures (exit 1).
#include <regex>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "cli_test_support.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using covopt::cli::testing::TempDir;
using Catch::Matchers::Contains;

void CheckRefused(const std::vector<std::string>& args, const std::vector<std::string>& mentions) {
  const CliRun run = Run(args);
  std::string command;
  for (const std::string& a : args) command += a + " ";
  INFO("covopt " << command << "\nstdout: " << run.out << "\nstderr: " << run.err);
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK(run.err.find('\n') == run.err.size() - 1);  // one line
  CHECK_THAT(run.err, !Contains("nan") && !Contains("inf)"));
  for (const std::string& m : mentions) CHECK_THAT(run.err, Contains(m));
}

void CheckFinite(const std::vector<std::string>& args) {
  const CliRun run = Run(args);
  std::string command;
  for (const std::string& a : args) command += a + " ";
  INFO("covopt " << command << "\nstdout: " << run.out << "\nstderr: " << run.err);
  CHECK(run.exit_code == 0);
  // No NaN or infinity printed as a number (a word such as "infinite" is fine).
  static const std::regex kNotFinite(R"(\b-?(nan|inf|infinity)\b)", std::regex::icase);
  CHECK_FALSE(std::regex_search(covopt::cli::testing::WithoutProvenance(run.out), kNotFinite));
}

}  // namespace

TEST_CASE("a denormal robot radius is exit 2 in speed-limit and simulate, flag or file", "[floors]") {
  const std::string radius = "robot.radius must be in [0.0001, 100] m, or flat (infinite) (got 5e-324)";
  CheckRefused({"speed-limit", "--robot-mass", "10kg", "--robot-radius", "5e-324m", "--covering-thickness", "0"},
               {radius, "--robot-radius"});
  CheckRefused({"simulate", "--robot-radius", "5e-324m", "--covering-thickness", "0"}, {radius});
  CheckRefused({"simulate", "--robot-radius", "2.3e-308m"}, {"robot.radius", "(got 2.3e-308)"});
  const TempDir dir;
  const auto scene = dir.Write("tiny.toml", "[robot]\nradius = \"5e-324m\"\n[covering]\nthickness = 0\n");
  CheckRefused({"simulate", "--scene", scene.string()}, {radius, "tiny.toml"});
}

TEST_CASE("a reaction delay, a torso, a scalp and a covering below their floors are exit 2", "[floors]") {
  CheckRefused({"simulate", "--reaction-delay", "1e-300s", "--braking", "1e4m/s2"},
               {"robot.reaction_delay must be 0 (brake at contact) or in [1e-06, 10] s (got 1e-300)"});
  CheckRefused({"simulate", "--torso-mass", "5e-324kg", "--neck-stiffness", "1e4N/m"},
               {"head.torso_mass must be in [0.001, 1e+06] kg", "(got 5e-324)"});
  CheckRefused({"simulate", "--covering-thickness", "0.05mm"},
               {"covering.thickness must be 0 (no covering) or in [0.0001, 1] m (got 5e-05)"});
  CheckRefused({"simulate", "--scalp-thickness", "1um"}, {"scalp.thickness must be in [0.0001, 1] m"});
  CheckRefused({"simulate", "--robot-mass", "0.5g"}, {"robot.mass must be in [0.001, 1e+06] kg"});
  CheckRefused({"simulate", "--covering-modulus", "5e-324Pa"}, {"covering.modulus must be in [1000, 1e+13] Pa"});
  CheckRefused({"simulate", "--laceration-limit", "5e-324Pa"}, {"--laceration-limit must be in [1000, 1e+13] Pa"});
  CheckRefused({"speed-limit", "--contusion-limit", "1e-300J/m2"}, {"--contusion-limit must be in [1, 1e+13] J/m2"});
}

TEST_CASE("a tiny contact area or a denormal crush strength is exit 2, never an inf ratio", "[floors]") {
  CheckRefused({"simulate", "--body-region", "chest", "--covering-thickness", "0", "--contact-area", "1e-300m2"},
               {"--contact-area must be in [1 mm², 1 m²]"});
  const TempDir dir;
  const auto catalog = dir.Write("weak.toml", R"([[material]]
name = "weak foam"
family = "foam"
youngs_modulus_Pa = "1 MPa"
modulus_basis = "compressive"
source = "test"
compressive_strength_Pa = "5e-324 Pa"
strength_method = "test"
strength_source = "test"
)");
  CheckRefused({"simulate", "--catalog", catalog.string(), "--material", "weak foam", "--covering-thickness", "10mm"},
               {"weak.toml:7:27", "material 'weak foam'", "compressive_strength_Pa must be in [1000, 1e+12] Pa",
                "(got 5e-324)"});
}

TEST_CASE("at the floors the command line answers with finite numbers", "[floors]") {
  CheckFinite({"simulate", "--robot-radius", "0.1mm", "--covering-thickness", "0", "--json"});
  CheckFinite({"speed-limit", "--robot-mass", "10kg", "--robot-radius", "0.1mm", "--covering-thickness", "0"});
  CheckFinite({"simulate", "--reaction-delay", "0.001ms", "--braking", "1e4m/s2", "--json"});
  CheckFinite({"simulate", "--torso-mass", "1g", "--neck-stiffness", "1e9N/m", "--json"});
  CheckFinite({"simulate", "--body-region", "chest", "--covering-thickness", "0", "--contact-area", "1mm2"});
}
