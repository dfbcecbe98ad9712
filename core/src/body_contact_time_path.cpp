// Placeholder until the time path lands (branch wave4-timepath replaces this file): it
// refuses rather than answers, so no caller can take it for a result.
#include "body_contact_time_path.hpp"

#include <stdexcept>

namespace covopt::internal {

BodyContactResult SolveBodyContactTimePath(const BodyContactModel&, const SolveOptions&) {
  throw std::logic_error("the body-contact time path is not built yet");
}

}  // namespace covopt::internal
