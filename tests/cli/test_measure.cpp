// `covopt measure` run in-process: the JSON is the library's prediction (PredictMeasurement)
// with "summary" and "input_sources", the region's pair is the default device, the text shows
// the device beside the body model, and bad input is exit 2 with one line naming the flag.
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/core/measuring_device.hpp"
#include "covopt/materials/body_regions.hpp"
#include "covopt/optim/measurement.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using nlohmann::json;

std::vector<std::string> Base() {
  return {"measure", "--body-region", "chest", "--robot-mass", "10kg", "--speed", "0.25m/s",
          "--robot-radius", "50mm", "--covering-thickness", "0", "--contact-area", "1cm2"};
}

std::vector<std::string> With(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

}  // namespace

TEST_CASE("measure --json is the library's prediction, with summary and input_sources", "[measure]") {
  const CliRun run = Run(With(Base(), {"--device-spring", "25N/mm", "--device-pad", "70ShA,7mm", "--json"}));
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const json j = json::parse(run.out);
  covopt::BodyContactScene scene;
  scene.robot_mass_kg = 10.0;
  scene.speed_m_per_s = 0.25;
  scene.robot_radius_m = 0.05;
  scene.covering.thickness_m = 0.0;
  scene.contact_area_m2 = 1e-4;
  const auto limits = covopt::materials::BodyRegionTable::BuiltIn().Limits("chest", "", covopt::ContactType::kTransient);
  const covopt::MeasuringDevice device{.spring_N_per_m = 25e3, .pad_shore_a = 70.0, .pad_thickness_m = 0.007,
                                       .pad_thickness_assumed = false, .name = "custom"};
  const covopt::optim::MeasurementPrediction p = covopt::optim::PredictMeasurement(scene, limits, device);
  CHECK(j["device"]["peak_force_N"].get<double>() == Approx(p.device.contact.peak_force_N).epsilon(1e-12));
  CHECK(j["device"]["reduced_mass_kg"].get<double>() == 10.0);
  CHECK(j["body_model"]["peak_force_N"].get<double>() == Approx(0.25 * std::sqrt(8.0 * 25e3)));
  CHECK(j["comparison"]["force_ratio"].get<double>() == Approx(p.force_ratio));
  CHECK(j["comparison"]["force_ratio"].get<double>() > 1.0);  // fixed device: mu = 10 kg > 8 kg
  CHECK(j["device"]["stiff_pad_force_N"].get<double>() == Approx(0.25 * std::sqrt(10.0 * 25e3)));
  CHECK(j["device"]["pad_thickness_assumed"] == false);
  REQUIRE(j.contains("summary"));
  CHECK(j["summary"]["command"] == "measure");
  CHECK(j["summary"]["targets"].size() == 2);
  CHECK(j.contains("input_sources"));
}

TEST_CASE("measure takes the region's pair without --device, and prints the device beside the body model",
          "[measure]") {
  const CliRun run = Run(Base());
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(run.out.find("Device       25+70: spring 25 N/mm, pad 70 Shore A") != std::string::npos);
  CHECK(run.out.find("peak force [N]") != std::string::npos);
  CHECK(run.out.find("body model") != std::string::npos);
  CHECK(run.out.find("7 mm assumed") != std::string::npos);
  const CliRun preset = Run(With(Base(), {"--device", "75+70", "--device-pad-thickness", "5mm", "--json"}));
  REQUIRE(preset.exit_code == 0);
  const json j = json::parse(preset.out);
  CHECK(j["device"]["spring_N_per_m"].get<double>() == 75e3);
  CHECK(j["device"]["pad_thickness_m"].get<double>() == Approx(0.005));
  CHECK(j["warnings"].dump().find("not the region's k_H") != std::string::npos);
}

TEST_CASE("measure refuses bad devices naming the flag", "[measure]") {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"--device-spring", "0N/mm", "--device-pad", "70ShA"}, "--device-spring"},
      {{"--device-spring", "-5N/mm", "--device-pad", "70ShA"}, "--device-spring"},
      {{"--device-spring", "25", "--device-pad", "70ShA"}, "--device-spring 25"},
      {{"--device-spring", "25N/mm", "--device-pad", "170ShA"}, "--device-pad"},
      {{"--device-spring", "25N/mm", "--device-pad", "-3ShA"}, "--device-pad"},
      {{"--device-spring", "25N/mm", "--device-pad", "70ShA,0mm"}, "--device-pad"},
      {{"--device-spring", "25N/mm", "--device-pad", "70ShA,50cm"}, "--device-pad"},
      {{"--device-spring", "25N/mm"}, "--device-pad"},
      {{"--device", "elbow"}, "--device: unknown preset 'elbow'"},
      {{"--device", "25+70", "--device-spring", "25N/mm"}, "--device"},
  };
  for (const auto& [more, named] : cases) {
    const CliRun run = Run(With(Base(), more));
    INFO(named << " -> " << run.err);
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK(run.err.find(named) != std::string::npos);
    CHECK(run.err.find('\n') == run.err.size() - 1);
  }
  CHECK(Run({"measure", "--robot-mass", "10kg"}).exit_code == 2);  // no region
  const CliRun pelvis = Run({"measure", "--body-region", "pelvis", "--covering-thickness", "0", "--contact-area", "1cm2"});
  CHECK(pelvis.exit_code == 2);
  CHECK(pelvis.err.find("no spring and pad pair stands for pelvis") != std::string::npos);
}

TEST_CASE("measure --report writes the report of its result", "[measure]") {
  const covopt::cli::testing::TempDir dir;
  const std::string file = (dir / "measure.html").string();
  const CliRun run = Run(With(Base(), {"--report", file}));
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  std::ifstream in(file);
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(html.find("<!DOCTYPE html") != std::string::npos);
  CHECK(html.find("chest (sternum), device 25+70") != std::string::npos);
  CHECK(html.find("chest (sternum), body model") != std::string::npos);
}
