#pragma once
// Private: the range checks of the library's inputs (a Scene, a BodyContactScene), one wording
// for all: "robot.radius must be in [0.0001, 100] m, or flat (infinite) (got 5e-324)". The
// lower ends of lengths, areas, masses, times and moduli are the physical floors
// (covopt/core/physical_floors.hpp). The messages are built out of line, only on failure:
// validation runs in every optimiser evaluation.
#include <cmath>
#include <string>

namespace covopt::internal {

/// Throws std::invalid_argument("<field> must be <requirement> (got <value>)").
[[noreturn, gnu::cold, gnu::noinline]] void RejectValue(const std::string& field, const std::string& requirement,
                                                        double value);

/// Throws for `value` outside [min, max] (min == 0: (0, max]) [unit], `zero_means` (if given)
/// admitting 0 and `infinite_word` (if given) +inf.
[[noreturn, gnu::cold, gnu::noinline]] void RejectRange(const char* field, double value, double min, double max,
                                                        const char* unit, const char* zero_means,
                                                        const char* infinite_word);

/// Finite and in [min, max] [unit] (min > 0: a floor), or +inf when `infinite_word` (e.g.
/// "flat (infinite)") names what it means. False for NaN.
inline void CheckInRange(const char* field, double value, double min, double max, const char* unit,
                         const char* infinite_word = nullptr) {
  if (value >= min && value <= max) return;  // false for NaN and +inf (max is finite)
  if (infinite_word != nullptr && std::isinf(value) && value > 0.0) return;
  RejectRange(field, value, min, max, unit, nullptr, infinite_word);
}

/// Exactly 0 (meaning `zero_means`, e.g. "no covering"), or in [min, max] [unit], or +inf when
/// `infinite_word` names it: a quantity that may be absent but, when present, has a floor.
inline void CheckZeroOrInRange(const char* field, double value, double min, double max, const char* unit,
                               const char* zero_means, const char* infinite_word = nullptr) {
  if (value == 0.0 || (value >= min && value <= max)) return;
  if (infinite_word != nullptr && std::isinf(value) && value > 0.0) return;
  RejectRange(field, value, min, max, unit, zero_means, infinite_word);
}

/// Finite and in (0, max] [unit], or +inf when `infinite_word` names it: a quantity without a
/// floor of its own (a stiffness).
inline void CheckPositive(const char* field, double value, double max, const char* unit,
                          const char* infinite_word = nullptr) {
  if (value > 0.0 && value <= max) return;
  if (infinite_word != nullptr && std::isinf(value) && value > 0.0) return;
  RejectRange(field, value, 0.0, max, unit, nullptr, infinite_word);
}

}  // namespace covopt::internal
