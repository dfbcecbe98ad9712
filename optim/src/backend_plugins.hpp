#pragma once
// Private: the entry points of the solver plugins (libcovopt_nlopt.so, libcovopt_ipopt.so, built
// from nlopt_backend.cpp and ipopt_backend.cpp) and the signature the loader expects of them.
// Each runs its solver on `problem` and fills `result`, the backend's name excepted; it returns
// false when the solver refused the problem before starting (then `result` is complete), true
// when the caller is to finish the result (internal::FinishResult and the time taken).
// The plugins call covopt code only through the Problem's virtual functions and header code:
// the program's copy of covopt::optim exports no symbol to them.
#include <span>

#include "covopt/optim/backends.hpp"

#define COVOPT_PLUGIN_ENTRY extern "C" __attribute__((visibility("default")))

namespace covopt::optim::internal {

using NloptEntry = bool(const Problem& problem, std::span<const double> x0, const NloptOptions& options,
                        SolveResult& result);
using IpoptEntry = bool(const Problem& problem, std::span<const double> x0, const IpoptOptions& options,
                        SolveResult& result);
/// The entry points' names carry the interface's version (v1): a plugin built for another
/// interface has no such entry, and the loader says so instead of calling it.
inline constexpr const char* kNloptEntryName = "covopt_nlopt_solve_v1";
inline constexpr const char* kIpoptEntryName = "covopt_ipopt_solve_v1";

}  // namespace covopt::optim::internal
