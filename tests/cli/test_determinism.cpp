// Determinism (issue 6): the same command prints bit-identical JSON on repeated runs, and
// `covopt optimize` prints the same JSON on 1 and on 2 threads. The only keys that may differ
// are wall-clock times ("seconds", anywhere in the document): they are replaced by 0 before
// the texts are compared. Everything else, every digit of every number, must match.
#include <string>
#include <string_view>
#include <vector>

#include <catch2/catch.hpp>

#include "cli_test_support.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;

/// The JSON text with every "seconds": <number> set to 0 (wall time is run-dependent).
/// (A plain scan: std::regex trips GCC 12's -Wmaybe-uninitialized under ASan.)
std::string WithoutWallTime(const std::string& json) {
  static const std::string key = "\"seconds\": ";
  std::string out;
  std::size_t from = 0;
  for (std::size_t at; (at = json.find(key, from)) != std::string::npos;) {
    out.append(json, from, at + key.size() - from);
    std::size_t end = at + key.size();
    while (end < json.size() && std::string_view("0123456789.eE+-").find(json[end]) != std::string_view::npos) {
      ++end;
    }
    out += (end > at + key.size()) ? "0" : "";
    from = end;
  }
  out.append(json, from, std::string::npos);
  return out;
}

std::string JsonOf(std::vector<std::string> args) {
  const CliRun run = Run(args);
  INFO("stderr: " << run.err);
  REQUIRE(run.exit_code == 0);
  REQUIRE(run.out.size() > 2);
  REQUIRE(run.out.front() == '{');
  // The bytes before the provenance block, the last key: the run's own command line and date.
  const std::size_t provenance = run.out.rfind(",\n  \"provenance\": {");
  REQUIRE(provenance != std::string::npos);
  return run.out.substr(0, provenance) + "\n}\n";
}

}  // namespace

TEST_CASE("simulate --json is bit-identical on repeated runs", "[determinism]") {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"simulate", "--json"},
        std::vector<std::string>{"simulate", "--json", "--speed", "3.7m/s", "--covering-thickness", "4mm"},
        std::vector<std::string>{"simulate", "--json", "--method", "cvode"},
        std::vector<std::string>{"simulate", "--json", "--method", "cvode", "--cvode-method", "bdf"}}) {
    const std::string first = JsonOf(args);
    const std::string second = JsonOf(args);
    CHECK(WithoutWallTime(first) == WithoutWallTime(second));
  }
}

TEST_CASE("optimize --json is bit-identical on repeated runs and on 1, 2 or all (0) threads",
          "[determinism]") {
  const std::vector<std::vector<std::string>> commands = {
      {"optimize", "--json"},
      {"optimize", "--json", "--thickness", "10mm"},
      {"optimize", "--json", "--speed", "1.3m/s", "--safety-factor", "1.5", "--family", "foam"},
      {"optimize", "--json", "--global", "isres", "--seed", "7", "--max-thickness", "30mm"},
  };
  for (const std::vector<std::string>& base : commands) {
    std::vector<std::string> one = base, two = base, every = base;
    one.insert(one.end(), {"--threads", "1"});
    two.insert(two.end(), {"--threads", "2"});
    every.insert(every.end(), {"--threads", "0"});  // 0 = all cores, as simulate and sweep take it
    const std::string plain = WithoutWallTime(JsonOf(base));
    const std::string again = WithoutWallTime(JsonOf(base));
    const std::string single = WithoutWallTime(JsonOf(one));
    const std::string dual = WithoutWallTime(JsonOf(two));
    const std::string dual_again = WithoutWallTime(JsonOf(two));
    CHECK(plain == again);
    CHECK(plain == single);  // the default is one thread
    CHECK(single == dual);
    CHECK(dual == dual_again);
    CHECK(WithoutWallTime(JsonOf(every)) == single);
    // The comparison is not vacuous: the documents hold the answer.
    CHECK(plain.find("\"candidates\"") != std::string::npos);
    CHECK(plain.find("\"youngs_modulus_Pa\"") != std::string::npos);
  }
}

TEST_CASE("only wall time is masked before comparing", "[determinism]") {
  // The mask must not hide anything but the "seconds" values.
  CHECK(WithoutWallTime(R"({"seconds": 0.0123, "evaluations": 5554})") ==
        R"({"seconds": 0, "evaluations": 5554})");
  CHECK(WithoutWallTime(R"({"seconds": 1.5e-05, "x": 1.5e-05})") == R"({"seconds": 0, "x": 1.5e-05})");
  CHECK(WithoutWallTime(R"({"max_seconds": 2})") == R"({"max_seconds": 2})");
}

TEST_CASE("sweep --csv - is bit-identical on repeated runs and on 1 or 2 threads",
          "[determinism]") {
  // covopt sweep prints CSV, not JSON, and has no wall-time column: compared as is.
  const std::vector<std::string> axes = {"sweep", "--csv", "-", "--x",
                                         "covering-modulus=1MPa..300MPa:log:9", "--y",
                                         "speed=0.5m/s..4m/s:7"};
  auto csv = [](std::vector<std::string> args) {
    const CliRun run = Run(args);
    INFO("stderr: " << run.err);
    REQUIRE(run.exit_code == 0);
    REQUIRE(run.out.size() > 100);
    return run.out;
  };
  auto one = axes, two = axes;
  one.insert(one.end(), {"--threads", "1"});
  two.insert(two.end(), {"--threads", "2"});
  const std::string a = csv(one);
  CHECK(a == csv(one));
  CHECK(a == csv(two));
  CHECK(csv(two) == csv(two));
}
