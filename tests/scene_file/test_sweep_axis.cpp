// The library's reader of a swept quantity, NAME=SPEC: the values a spec expands to, and its
// refusals as std::invalid_argument naming the input (the CLI maps them to exit 2).
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "covopt/core/sweep.hpp"
#include "covopt/scene_file/sweep_axis.hpp"

using covopt::scene_file::CheckGridSize;
using covopt::scene_file::ParseSweepAxis;

TEST_CASE("sweep axis: ranges and values expand in order, in SI", "[sweep_axis]") {
  const covopt::TypedSweepAxis axis = ParseSweepAxis("covering-thickness=0..50mm:6, 75mm", "--x");
  REQUIRE(axis.field != nullptr);
  CHECK(axis.field->dotted_name() == "covering.thickness");
  CHECK(axis.name == "covering-thickness");
  REQUIRE(axis.values.size() == 7);
  for (std::size_t i = 0; i < 6; ++i) CHECK(axis.values[i] == Approx(0.01 * static_cast<double>(i)).margin(1e-15));
  CHECK(axis.values.back() == 0.075);
  REQUIRE(axis.parts.size() == 2);
  CHECK(axis.parts[0].range);
  CHECK_FALSE(axis.parts[1].range);
  CHECK_FALSE(axis.log);

  const covopt::TypedSweepAxis log_axis = ParseSweepAxis("robot.mass=1kg..100kg:log:3,fixed", "--y");
  REQUIRE(log_axis.values.size() == 4);
  CHECK(log_axis.values[1] == Approx(10.0));
  CHECK(std::isinf(log_axis.values[3]));
  CHECK(log_axis.log);  // every finite value is above 0
}

TEST_CASE("sweep axis: bad specs are refused naming the input, the problem and the text", "[sweep_axis]") {
  CHECK_THROWS_WITH(ParseSweepAxis("speeed=1..2", "--x"),
                    Catch::StartsWith("--x: unknown quantity 'speeed'") && Catch::Contains("(got 'speeed=1..2')"));
  CHECK_THROWS_WITH(ParseSweepAxis("speed", "--x"), Catch::Contains("expected NAME=LO..HI"));
  CHECK_THROWS_WITH(ParseSweepAxis("speed=2..1", "--x"), Catch::Contains("lower end is above the upper end"));
  CHECK_THROWS_WITH(ParseSweepAxis("speed=1..1", "--x"), Catch::Contains("low end must be below"));
  CHECK_THROWS_WITH(ParseSweepAxis("speed=1..2:1", "--x"), Catch::Contains("count after ':' must be in 2..100000"));
  CHECK_THROWS_WITH(ParseSweepAxis("speed=0..2:log", "--x"), Catch::Contains("low end above 0"));
  CHECK_THROWS_WITH(ParseSweepAxis("speed=1,,2", "--x"), Catch::Contains("empty value in the list"));
  CHECK_THROWS_WITH(ParseSweepAxis("speed=2kg", "--x"), Catch::Contains("in 'speed=2kg'"));
  CHECK_THROWS_AS(ParseSweepAxis("speed=1..2:100001", "--x"), std::invalid_argument);
  const covopt::TypedSweepAxis big = ParseSweepAxis("speed=1..2:2000", "--x");
  const covopt::TypedSweepAxis wide = ParseSweepAxis("robot-mass=1..2:1000", "--y");
  CHECK_THROWS_AS(CheckGridSize(big, &wide), std::invalid_argument);
  CHECK_NOTHROW(CheckGridSize(big, nullptr));
}
