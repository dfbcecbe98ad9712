// String forms of the scene enums.
#include "covopt/core/scene.hpp"

namespace covopt {

std::string_view ToString(ThresholdReading reading) noexcept {
  switch (reading) {
    case ThresholdReading::kCumulative: return "cumulative";
    case ThresholdReading::kLiteral: return "literal";
  }
  return "unknown";
}

}  // namespace covopt
