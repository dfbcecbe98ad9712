#include "range_check.hpp"

#include <stdexcept>

#include "numeric_format.hpp"

namespace covopt::internal {

void RejectValue(const std::string& field, const std::string& requirement, double value) {
  throw std::invalid_argument(field + " must be " + requirement + " (got " + FormatNumber(value) + ")");
}

void RejectRange(const char* field, double value, double min, double max, const char* unit,
                 const char* zero_means, const char* infinite_word) {
  std::string requirement;
  if (zero_means != nullptr) requirement = "0 (" + std::string(zero_means) + ") or ";
  // The bounds as printf's %g ("0.0001", "1e+06"), the value as it reads back exactly.
  requirement += (min > 0.0 ? "in [" : "in (") + FormatSignificant(min) + ", " + FormatSignificant(max) + "] " + unit;
  if (infinite_word != nullptr) requirement += ", or " + std::string(infinite_word);
  RejectValue(field, requirement, value);
}

}  // namespace covopt::internal
