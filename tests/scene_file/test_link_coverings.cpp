// covopt::scene_file reads link-covering files (covopt audit --link-coverings). These tests
// check that every value out of its range is refused with the file:line:column of the value
// itself (a negative thickness, a thickness between 0 and the 0.1 mm floor, a modulus below
// 1 kPa), that the Poisson range is covering.poisson's, (-1, 0.5], that a link or material name
// with a control character is refused with a one-line message that shows it escaped, and that
// every message is one line.

#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "covopt/core/physical_floors.hpp"
#include "covopt/scene_file/link_coverings.hpp"

using covopt::scene_file::LinkCoveringEntry;
using covopt::scene_file::ParseLinkCoverings;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

/// The message ParseLinkCoverings throws for `text`, or "" if it accepts it.
std::string ErrorFor(const std::string& text) {
  try {
    ParseLinkCoverings(text, "links.toml");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

/// One [[link]] table with a modulus and the given extra lines.
std::string Link(const std::string& lines) { return "[[link]]\nname = \"l2\"\nmodulus = \"0.5MPa\"\n" + lines; }

}  // namespace

TEST_CASE("link coverings: a thickness out of its range is refused at its file:line:column", "[link_coverings]") {
  // Line 4, column 13: where the value starts.
  for (const std::string value : {"\"-5mm\"", "-0.005", "\"0.05mm\"", "1e-310", "\"1.5m\""}) {
    INFO(value);
    const std::string message = ErrorFor(Link("thickness = " + value + "\n"));
    CHECK_THAT(message, StartsWith("links.toml:4:13: link 'l2' thickness must be 0 (bare) or in [0.1 mm, 1000 mm]"));
  }
  // 0 (bare) and the floor itself are accepted.
  CHECK(ParseLinkCoverings(Link("thickness = 0\n"), "x").front().thickness_m == 0.0);
  CHECK(ParseLinkCoverings(Link("thickness = \"0.1mm\"\n"), "x").front().thickness_m == covopt::kMinLayerThickness_m);
}

TEST_CASE("link coverings: the Poisson range is covering.poisson's: above -1, at most 0.5", "[link_coverings]") {
  for (const double nu : {-0.5, 0.0, 0.45, 0.5}) {
    INFO(nu);
    const auto entries = ParseLinkCoverings(Link("poisson = " + std::to_string(nu) + "\nthickness = \"5mm\"\n"), "x");
    CHECK(entries.front().poisson_ratio == nu);
  }
  for (const std::string nu : {"-1", "0.51", "-1.5"}) {
    INFO(nu);
    CHECK_THAT(ErrorFor(Link("poisson = " + nu + "\nthickness = \"5mm\"\n")),
               StartsWith("links.toml:4:11: link 'l2' poisson must be in (-1, 0.5]"));
  }
}

TEST_CASE("link coverings: a modulus below the 1 kPa floor is refused at its place", "[link_coverings]") {
  CHECK_THAT(ErrorFor("[[link]]\nname = \"l2\"\nthickness = \"5mm\"\nmodulus = \"-2MPa\"\n"),
             StartsWith("links.toml:4:11: link 'l2' modulus must be in [1 kPa"));
  CHECK_THAT(ErrorFor("[[link]]\nname = \"l2\"\nthickness = \"5mm\"\nmodulus = \"10Pa\"\n"),
             StartsWith("links.toml:4:11: link 'l2' modulus must be in [1 kPa"));
}

TEST_CASE("link coverings: a name with a control character is refused on one line, escaped", "[link_coverings]") {
  const std::string message = ErrorFor("[[link]]\nname = \"fr3\\nlink7\\r\\u001bx\"\nthickness = 0\n");
  CHECK(message.find('\n') == std::string::npos);
  CHECK_THAT(message, StartsWith("links.toml:2:8: [[link]] 1 name: a link name has no control characters"));
  CHECK_THAT(message, Contains("'fr3\\nlink7\\r\\x1bx'"));
  const std::string material = ErrorFor("[[link]]\nname = \"l\"\nmaterial = \"foam\\n30\"\nthickness = \"5mm\"\n");
  CHECK(material.find('\n') == std::string::npos);
  CHECK_THAT(material, Contains("a material name has no control characters such as a newline (got 'foam\\n30')"));
}

TEST_CASE("link coverings: every message is one line, whatever it echoes", "[link_coverings]") {
  // A quoted key with a newline, a value with one, and a source name with one.
  for (const std::string text : {"[[link]]\nname = \"l\"\n\"thick\\nness\" = 0\n",
                                 "[[link]]\nname = \"l\"\nthickness = \"5\\nmm\"\n", "\"a\\nb\" = 1\n"}) {
    INFO(text);
    const std::string message = ErrorFor(text);
    CHECK_FALSE(message.empty());
    CHECK(message.find('\n') == std::string::npos);
  }
  try {
    ParseLinkCoverings("[[link]]\nname = 3\n", "dir\nlinks.toml");
    FAIL("accepted");
  } catch (const std::invalid_argument& e) {
    CHECK_THAT(std::string(e.what()), StartsWith("dir\\nlinks.toml:1:1: [[link]] 1 needs name"));
  }
  // The place an accepted entry keeps for the callers' messages is one line too.
  const auto entries = ParseLinkCoverings("[[link]]\nname = \"l\"\nthickness = 0\n", "dir\nlinks.toml");
  CHECK(entries.front().where == "dir\\nlinks.toml:1:1");
}
