// covopt::SolveExactGrid: a list of scenes on the exact path, on any number of threads, each
// point the same as SolveExact's (moved from tests/cli/test_sweep.cpp: a core test).

#include <algorithm>
#include <cstddef>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/core/exact.hpp>
#include <covopt/core/grid.hpp>
#include <covopt/core/impact_model.hpp>

using Catch::Matchers::Contains;

TEST_CASE("SolveExactGrid matches SolveExact point by point on any number of threads", "[sweep]") {
  std::vector<covopt::Scene> scenes;
  for (int i = 0; i < 300; ++i) {
    covopt::Scene s;
    s.robot.speed_m_per_s = 0.1 + 0.02 * i;
    s.covering.thickness_m = (i % 7) * 0.004;
    if (i % 50 == 0) s.head.radius_m = 0.001;  // smaller than the scalp: invalid
    scenes.push_back(s);
  }
  std::vector<std::size_t> progress;
  covopt::GridOptions options;
  options.threads = 1;
  options.progress = [&](std::size_t done, std::size_t total) {
    CHECK(total == scenes.size());
    progress.push_back(done);
  };
  const auto serial = covopt::SolveExactGrid(scenes, options);
  REQUIRE(!progress.empty());
  CHECK(progress.back() == scenes.size());
  CHECK(std::is_sorted(progress.begin(), progress.end()));
  options.threads = 4;
  options.progress = nullptr;
  const auto parallel = covopt::SolveExactGrid(scenes, options);
  REQUIRE(serial.size() == scenes.size());
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    INFO("point " << i);
    REQUIRE(serial[i].valid() == (i % 50 != 0));
    REQUIRE(parallel[i].valid() == serial[i].valid());
    if (!serial[i].valid()) {
      CHECK_THAT(serial[i].error, Contains("head.radius"));
      CHECK(parallel[i].error == serial[i].error);
      continue;
    }
    const auto direct = covopt::SolveExact(covopt::ImpactModel::FromScene(scenes[i]));
    CHECK(serial[i].result->peaks.peak_force_N == direct.peaks.peak_force_N);
    CHECK(parallel[i].result->peaks.max_energy_density_J_per_m2 ==
          direct.peaks.max_energy_density_J_per_m2);
    CHECK(parallel[i].result->contact_duration_s == direct.contact_duration_s);
    CHECK(parallel[i].assessment.contusion.ratio == serial[i].assessment.contusion.ratio);
  }
}
