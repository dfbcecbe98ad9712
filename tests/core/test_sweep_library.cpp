// covopt::Sweep, the streamed sweep, called directly: rows reach the consumer in grid order
// (x slowest), one per point, in blocks; each row agrees bit for bit with SolveExact on the
// same scene, whatever the number of threads or the block size; invalid scenes are rows
// carrying the library's message; the summary is the count of the rows; the limits and the
// safety factor of the spec judge the ratios; a consumer that throws stops the sweep and
// its exception reaches the caller; bad specs name the field, the value and what is allowed.
// The scene-field table by name is checked here too, since the sweep's axes use it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "test_helpers.hpp"

using namespace covopt;
using Catch::Matchers::Contains;

namespace {

/// A copy of the rows as the consumer saw them, and the sizes of the blocks.
struct Collected {
  std::vector<SweepRow> rows;
  std::vector<std::size_t> block_sizes;
};

SweepResult Collect(const SweepSpec& spec, const SweepOptions& options, Collected& out) {
  return Sweep(spec, options, [&](std::span<const SweepRow> rows) {
    out.block_sizes.push_back(rows.size());
    out.rows.insert(out.rows.end(), rows.begin(), rows.end());
  });
}

/// Speed 0.5..3 m/s (11 values) against covering thickness 0..40 mm (9 values).
SweepSpec SpeedThicknessSpec() {
  SweepSpec spec;
  for (int i = 0; i <= 10; ++i) spec.x.values.push_back(0.5 + 0.25 * i);
  spec.x.quantity = "speed";
  SweepAxis thickness{"covering-thickness", {}};
  for (int j = 0; j <= 8; ++j) thickness.values.push_back(0.005 * j);
  spec.y = thickness;
  return spec;
}

bool SameRow(const SweepRow& a, const SweepRow& b) {
  return a.index == b.index && a.valid == b.valid && a.error == b.error &&
         a.peaks.max_penetration_m == b.peaks.max_penetration_m &&
         a.peaks.peak_force_N == b.peaks.peak_force_N &&
         a.peaks.max_tensile_stress_Pa == b.peaks.max_tensile_stress_Pa &&
         a.peaks.max_energy_density_J_per_m2 == b.peaks.max_energy_density_J_per_m2 &&
         a.contact_duration_s == b.contact_duration_s && a.worst_ratio == b.worst_ratio &&
         a.compression_ratio == b.compression_ratio && a.warnings.size() == b.warnings.size();
}

}  // namespace

TEST_CASE("the scene fields are found by name and by dotted name, and set the scene",
          "[sweep-library]") {
  REQUIRE(SceneFields().size() == 21);
  for (const SceneField& field : SceneFields()) {
    INFO(field.name);
    CHECK(FindSceneField(field.name) == &field);
    CHECK(FindSceneField(field.dotted_name()) == &field);
    Scene scene;
    field.field(scene) = 0.123;
    CHECK(field.value(scene) == 0.123);
  }
  CHECK(FindSceneField("robot-mass")->dotted_name() == "robot.mass");
  CHECK(FindSceneField("speed")->dotted_name() == "robot.speed");
  CHECK(FindSceneField("robot-mass")->spec.allow_fixed);
  CHECK(FindSceneField("robot-radius")->spec.allow_flat);
  CHECK(FindSceneField("mass") == nullptr);
  CHECK(FindSceneField("robot.") == nullptr);
  CHECK(FindSceneField("") == nullptr);
  CHECK_THAT(SceneFieldNames(), Contains("robot-mass, speed, robot-radius"));
}

TEST_CASE("a sweep delivers one row per point in grid order, x varying slowest",
          "[sweep-library]") {
  const SweepSpec spec = SpeedThicknessSpec();
  SweepOptions options;
  options.block_rows = 7;  // blocks that do not divide the grid
  options.threads = 2;
  Collected got;
  const SweepResult result = Collect(spec, options, got);
  REQUIRE(got.rows.size() == 99);
  CHECK(result.rows == 99);
  CHECK(result.x_values == 11);
  CHECK(result.y_values == 9);
  for (std::size_t i = 0; i < got.rows.size(); ++i) {
    const SweepRow& row = got.rows[i];
    INFO("row " << i);
    CHECK(row.index == i);
    CHECK(row.ix == i / 9);
    CHECK(row.iy == i % 9);
    CHECK(row.x == spec.x.values[i / 9]);
    CHECK(row.y == spec.y->values[i % 9]);
  }
  // Blocks of block_rows rows, the last one shorter.
  REQUIRE(got.block_sizes.size() == 15);
  for (std::size_t b = 0; b + 1 < got.block_sizes.size(); ++b) CHECK(got.block_sizes[b] == 7);
  CHECK(got.block_sizes.back() == 99 - 14 * 7);
}

TEST_CASE("each sweep row is SolveExact on its scene, judged against the spec's limits",
          "[sweep-library]") {
  SweepSpec spec = SpeedThicknessSpec();
  spec.limits.laceration_tensile_stress_Pa = 0.8e6;
  spec.limits.contusion_energy_density_J_per_m2 = 30000.0;
  spec.safety_factor = 1.5;
  spec.scene.robot.mass_kg = 5.0;
  Collected got;
  Collect(spec, {}, got);
  REQUIRE(got.rows.size() == 99);
  for (const SweepRow& row : got.rows) {
    INFO("speed " << row.x << ", thickness " << row.y);
    Scene scene = spec.scene;
    scene.robot.speed_m_per_s = row.x;
    scene.covering.thickness_m = row.y;
    const ImpactResult direct = SolveExact(ImpactModel::FromScene(scene));
    REQUIRE(row.valid);
    CHECK(row.peaks.peak_force_N == direct.peaks.peak_force_N);
    CHECK(row.peaks.max_energy_density_J_per_m2 == direct.peaks.max_energy_density_J_per_m2);
    CHECK(row.peaks.fully_compressed == direct.peaks.fully_compressed);
    CHECK(row.contact_duration_s == direct.contact_duration_s);
    CHECK(row.time_of_max_compression_s == direct.time_of_max_compression_s);
    CHECK(row.rebound_speed_m_per_s == row.x);
    // Ratios are value / limit; verdicts use the derated limits.
    const double laceration = direct.peaks.max_tensile_stress_Pa / 0.8e6;
    const double contusion = direct.peaks.max_energy_density_J_per_m2 / 30000.0;
    CHECK(row.assessment.laceration.ratio == laceration);
    CHECK(row.assessment.contusion.ratio == contusion);
    CHECK(row.assessment.laceration.safe == (1.5 * laceration <= 1.0));
    CHECK(row.assessment.contusion.safe == (1.5 * contusion <= 1.0));
    CHECK(row.worst_ratio == std::max(laceration, contusion));
    // The covering's travel ratio crosses 1 where it bottoms out; the bare robot has none. The
    // safety factor reserves travel too: 1.5 × the ratio <= 1.
    CHECK(row.compression_ratio == direct.peaks.covering_compression_ratio());
    if (row.covered) CHECK((row.compression_ratio > 1.0) == direct.peaks.fully_compressed);
    if (!row.covered) CHECK(row.compression_ratio == 0.0);
    CHECK(row.covered == (row.y > 0.0));
    CHECK(row.admissible ==
          (row.assessment.safe() &&
           !(row.covered && (direct.peaks.fully_compressed || 1.5 * row.compression_ratio > 1.0))));
    REQUIRE(row.warnings.size() == direct.warnings.size());
    for (std::size_t w = 0; w < row.warnings.size(); ++w) {
      CHECK(row.warnings[w].code == direct.warnings[w].code);
      CHECK(row.warnings[w].message == direct.warnings[w].message);
    }
  }
}

TEST_CASE("sweep rows are bit-identical for 1, 2 and 3 threads and any block size",
          "[sweep-library]") {
  const SweepSpec spec = SpeedThicknessSpec();
  Collected reference;
  SweepOptions options;
  options.threads = 1;
  Collect(spec, options, reference);
  for (const unsigned threads : {2u, 3u}) {
    for (const std::size_t block_rows : {std::size_t{1}, std::size_t{5}, std::size_t{1024}}) {
      INFO(threads << " threads, blocks of " << block_rows);
      options.threads = threads;
      options.block_rows = block_rows;
      Collected got;
      const SweepResult result = Collect(spec, options, got);
      CHECK(result.threads == std::min<std::size_t>(threads, (99 + block_rows - 1) / block_rows));
      REQUIRE(got.rows.size() == reference.rows.size());
      for (std::size_t i = 0; i < got.rows.size(); ++i) CHECK(SameRow(got.rows[i], reference.rows[i]));
    }
  }
}

TEST_CASE("invalid points of a sweep are rows naming the field, and the summary counts them",
          "[sweep-library]") {
  SweepSpec spec;
  spec.x = {"head-radius", {0.0, 0.002, 0.05, 0.0725, 0.1}};  // <= the 3 mm scalp: invalid
  spec.y = SweepAxis{"robot-mass", {2.0, kFixed}};
  Collected got;
  const SweepResult result = Collect(spec, {}, got);
  REQUIRE(got.rows.size() == 10);
  for (const SweepRow& row : got.rows) {
    INFO("head radius " << row.x);
    CHECK(row.valid == (row.x > 0.003));
    if (!row.valid) {
      CHECK_THAT(row.error, Contains("head.radius"));
      CHECK(row.peaks.peak_force_N == 0.0);
      CHECK(row.worst_ratio == 0.0);
    } else {
      CHECK(row.error.empty());
      CHECK(std::isfinite(row.worst_ratio));
    }
  }
  CHECK(std::isinf(got.rows[1].y));  // a fixed robot
  CHECK(result.status == SweepStatus::kSomeInvalid);
  CHECK(result.ok());
  CHECK(result.valid == 6);
  REQUIRE(result.first_invalid);
  CHECK(*result.first_invalid == 0);
  CHECK_THAT(result.first_invalid_error, Contains("head.radius"));
  CHECK_THAT(result.message, Contains("4 of 10 points") && Contains("head.radius"));
  CHECK_THAT(result.BriefReport(), Contains("sweep: 10 points (5 x 2)") &&
                                       Contains("6 valid, 4 invalid"));

  // Every point invalid: rows still delivered, the status says so.
  SweepSpec none;
  none.x = {"head-radius", {0.001, 0.002}};
  Collected nothing;
  const SweepResult bad = Collect(none, {}, nothing);
  CHECK(nothing.rows.size() == 2);
  CHECK(bad.status == SweepStatus::kNoneValid);
  CHECK_FALSE(bad.ok());
  CHECK_FALSE(bad.least);
}

TEST_CASE("the sweep summary is the count of its rows", "[sweep-library]") {
  SweepSpec spec;
  spec.x = {"covering-modulus", {}};
  for (int i = 0; i < 12; ++i) spec.x.values.push_back(0.3e6 * std::pow(10.0, 0.25 * i));
  spec.y = SweepAxis{"covering-thickness", {0.0, 0.002, 0.005, 0.01, 0.02, 0.04}};
  Collected got;
  SweepOptions options;
  options.block_rows = 10;
  const SweepResult result = Collect(spec, options, got);
  std::size_t safe = 0, lac = 0, con = 0, covered = 0, full = 0, admissible = 0, warned = 0;
  double least = std::numeric_limits<double>::infinity(), most = 0.0;
  for (const SweepRow& row : got.rows) {
    REQUIRE(row.valid);
    safe += row.assessment.safe();
    lac += !row.assessment.laceration.safe;
    con += !row.assessment.contusion.safe;
    covered += row.covered;
    full += row.covered && row.peaks.fully_compressed;
    admissible += row.admissible;
    warned += !row.warnings.empty();
    least = std::min(least, row.worst_ratio);
    most = std::max(most, row.worst_ratio);
  }
  CHECK(result.status == SweepStatus::kAllValid);
  CHECK(result.valid == 72);
  CHECK(result.safe == safe);
  CHECK(result.laceration_unsafe == lac);
  CHECK(result.contusion_unsafe == con);
  CHECK(result.covered == covered);
  CHECK(covered == 60);
  CHECK(result.fully_compressed == full);
  CHECK(full > 0);  // both sides of the full-compression boundary are on this grid
  CHECK(full < covered);
  CHECK(result.admissible == admissible);
  CHECK(result.warned == warned);
  REQUIRE(result.least);
  REQUIRE(result.most);
  CHECK(result.least->worst_ratio == least);
  CHECK(result.most->worst_ratio == most);
  CHECK(got.rows[result.most->index].worst_ratio == most);
  if (warned > 0) {
    REQUIRE(result.first_warned);
    CHECK(got.rows[*result.first_warned].warnings.front().message == result.first_warning.message);
  }
}

TEST_CASE("a consumer that throws stops the sweep and its exception reaches the caller",
          "[sweep-library]") {
  SweepSpec spec;
  spec.x = {"speed", {}};
  for (int i = 0; i < 2000; ++i) spec.x.values.push_back(0.1 + 0.001 * i);
  for (const unsigned threads : {1u, 2u, 4u}) {
    INFO(threads << " threads");
    SweepOptions options;
    options.threads = threads;
    options.block_rows = 16;
    std::size_t calls = 0, rows = 0;
    const auto throwing = [&](std::span<const SweepRow> block) {
      ++calls;
      rows += block.size();
      if (calls == 3) throw std::runtime_error("disk full");
    };
    CHECK_THROWS_WITH(Sweep(spec, options, throwing), "disk full");
    CHECK(calls == 3);  // nothing is delivered after the throw
    CHECK(rows == 48);

    // The progress callback may stop it too.
    options.progress = [](std::size_t delivered, std::size_t) {
      if (delivered >= 32) throw std::runtime_error("cancelled");
    };
    std::size_t delivered = 0;
    CHECK_THROWS_WITH(Sweep(spec, options, [&](std::span<const SweepRow> b) { delivered += b.size(); }),
                      "cancelled");
    CHECK(delivered == 32);
  }
}

TEST_CASE("progress reaches the total, rising, from the calling thread", "[sweep-library]") {
  const SweepSpec spec = SpeedThicknessSpec();
  SweepOptions options;
  options.block_rows = 10;
  std::vector<std::size_t> seen;
  options.progress = [&](std::size_t delivered, std::size_t total) {
    CHECK(total == 99);
    seen.push_back(delivered);
  };
  Sweep(spec, options, [](std::span<const SweepRow>) {});
  REQUIRE(seen.size() == 10);
  CHECK(std::is_sorted(seen.begin(), seen.end()));
  CHECK(seen.back() == 99);
}

TEST_CASE("bad sweep specs are refused naming the field, the value and what is allowed",
          "[sweep-library]") {
  const auto nothing = [](std::span<const SweepRow>) {};
  SweepSpec spec;
  spec.x = {"foo", {1.0}};
  CHECK_THROWS_WITH(Sweep(spec, {}, nothing),
                    Contains("x.quantity: no scene quantity 'foo'; the quantities are robot-mass, speed"));
  spec.x = {"speed", {}};
  CHECK_THROWS_WITH(Sweep(spec, {}, nothing), Contains("x.values: no values for speed"));
  spec.x = {"speed", {1.0, std::nan("")}};
  CHECK_THROWS_WITH(Sweep(spec, {}, nothing), Contains("x.values[1] must be a number"));
  spec.x = {"speed", {1.0}};
  spec.y = SweepAxis{"robot.speed", {1.0}};
  CHECK_THROWS_WITH(Sweep(spec, {}, nothing), Contains("y.quantity: speed is already swept by x"));
  spec.y.reset();
  spec.safety_factor = 0.5;
  CHECK_THROWS_WITH(Sweep(spec, {}, nothing), Contains("safety_factor must be in [1, 100] (got 0.5)"));
  spec.safety_factor = 1.0;
  spec.limits.contusion_energy_density_J_per_m2 = 0.0;
  CHECK_THROWS_WITH(Sweep(spec, {}, nothing),
                    Contains("limits.contusion_energy_density_J_per_m2 must be in [1, 1e+13] J/m2"));
  spec.limits = {};
  SweepOptions options;
  options.threads = 5000;
  CHECK_THROWS_WITH(Sweep(spec, options, nothing), Contains("threads must be <= 4096 (got 5000)"));
  options = {};
  options.block_rows = 0;
  CHECK_THROWS_WITH(Sweep(spec, options, nothing), Contains("block_rows must be in 1..1000000 (got 0)"));
  CHECK_THROWS_WITH(Sweep(spec, {}, SweepConsumer{}), Contains("consumer"));
}

TEST_CASE("a sweep matches SolveExact point by point on any number of threads", "[sweep]") {
  // 150 speeds x 2 head radii, the second smaller than the scalp: invalid (was SolveExactGrid's
  // test, which Sweep replaced).
  covopt::SweepSpec spec;
  spec.x.quantity = "speed";
  for (int i = 0; i < 150; ++i) spec.x.values.push_back(0.1 + 0.02 * i);
  spec.y = covopt::SweepAxis{"head-radius", {0.08, 0.001}};
  const auto solve = [&](unsigned threads, std::vector<std::size_t>* progress) {
    covopt::SweepOptions options;
    options.threads = threads;
    options.block_rows = 64;
    if (progress) {
      options.progress = [progress](std::size_t done, std::size_t total) {
        CHECK(total == 300u);
        progress->push_back(done);
      };
    }
    std::vector<covopt::SweepRow> rows;
    covopt::Sweep(spec, options, [&](std::span<const covopt::SweepRow> block) {
      rows.insert(rows.end(), block.begin(), block.end());
    });
    return rows;
  };
  std::vector<std::size_t> progress;
  const auto serial = solve(1, &progress);
  REQUIRE(!progress.empty());
  CHECK(progress.back() == 300u);
  CHECK(std::is_sorted(progress.begin(), progress.end()));
  const auto parallel = solve(4, nullptr);
  REQUIRE(serial.size() == 300u);
  REQUIRE(parallel.size() == 300u);
  for (std::size_t i = 0; i < serial.size(); ++i) {
    INFO("point " << i);
    REQUIRE(serial[i].valid == (i % 2 == 0));
    REQUIRE(parallel[i].valid == serial[i].valid);
    if (!serial[i].valid) {
      CHECK_THAT(serial[i].error, Contains("head.radius"));
      CHECK(parallel[i].error == serial[i].error);
      continue;
    }
    covopt::Scene scene = spec.scene;
    scene.robot.speed_m_per_s = serial[i].x;
    scene.head.radius_m = serial[i].y;
    const auto direct = covopt::SolveExact(covopt::ImpactModel::FromScene(scene));
    CHECK(serial[i].peaks.peak_force_N == direct.peaks.peak_force_N);
    CHECK(parallel[i].peaks.max_energy_density_J_per_m2 == direct.peaks.max_energy_density_J_per_m2);
    CHECK(parallel[i].contact_duration_s == direct.contact_duration_s);
    CHECK(parallel[i].assessment.contusion.ratio == serial[i].assessment.contusion.ratio);
  }
}
