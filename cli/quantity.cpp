#include "quantity.hpp"

#include <stdexcept>

#include "errors.hpp"

namespace covopt::cli {

double ParseQuantityToInputError::operator()(std::string_view text, const QuantitySpec& spec,
                                              std::string_view name) const {
  try {
    return covopt::ParseQuantity(text, spec, name);
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
}

}  // namespace covopt::cli
