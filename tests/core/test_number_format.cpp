// The one number formatter (covopt/core/number_format.hpp): byte-identical to the printf
// conversions it replaced, and the shortest form reads back exactly.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "covopt/core/number_format.hpp"

namespace {

std::string Printf(const char* format, double value) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

std::vector<double> Values() {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> values = {0.0,  -0.0, 1.0,    0.5,   0.018, 1e-5,    123456.5, 0.00015, 2.5,   0.125, 9.9995,
                                99.95, 0.05, 1e-8,  1.5e-8, 0.999999, 9.9999995, 1e16, 5e-324, 1e300, kInf, -kInf,
                                std::numeric_limits<double>::quiet_NaN(), 0.1 + 0.2, 2.76e7, 18e-3};
  std::mt19937_64 random(23);
  std::uniform_real_distribution<double> exponent(-20.0, 20.0), mantissa(-10.0, 10.0);
  for (int i = 0; i < 20000; ++i) values.push_back(mantissa(random) * std::pow(10.0, exponent(random)));
  return values;
}

}  // namespace

TEST_CASE("FormatSignificant, FormatFixed and FormatScientific print as printf does", "[format]") {
  for (const double v : Values()) {
    CHECK(covopt::FormatSignificant(v) == Printf("%g", v));
    CHECK(covopt::FormatSignificant(v, 3) == Printf("%.3g", v));
    CHECK(covopt::FormatSignificant(v, 4) == Printf("%.4g", v));
    CHECK(covopt::FormatSignificant(v, 12) == Printf("%.12g", v));
    CHECK(covopt::FormatSignificant(v, 17) == Printf("%.17g", v));
    CHECK(covopt::FormatScientific(v, 0) == Printf("%.0e", v));
    if (std::abs(v) < 1e100) {
      CHECK(covopt::FormatFixed(v, 1) == Printf("%.1f", v));
      CHECK(covopt::FormatFixed(v, 2) == Printf("%.2f", v));
    }
  }
  CHECK(covopt::FormatFixed(1e300, 0).size() == 301);  // no buffer to overflow
}

TEST_CASE("FormatShortest reads back exactly", "[format]") {
  CHECK(covopt::FormatShortest(0.1 + 0.2) == "0.30000000000000004");
  CHECK(covopt::FormatShortest(18e-3) == "0.018");
  CHECK(covopt::FormatShortest(1e-5) == "1e-05");
  CHECK(covopt::FormatShortest(2.76e7) == "27600000");
  CHECK(covopt::FormatShortest(std::numeric_limits<double>::infinity()) == "inf");
  CHECK(covopt::FormatShortest(-std::numeric_limits<double>::infinity()) == "-inf");
  CHECK(covopt::FormatShortest(-std::numeric_limits<double>::quiet_NaN()) == "nan");
  for (const double v : Values()) {
    if (std::isfinite(v)) CHECK(std::strtod(covopt::FormatShortest(v).c_str(), nullptr) == v);
  }
}
