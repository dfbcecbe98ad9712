#pragma once
/// @file oracle_options.hpp
/// The flags --oracle, --method, --rtol and --max-steps of the commands that judge impacts through an
/// oracle (`optimize`, `speed-limit`): which path answers (docs/model.md §10.4), the time
/// path's integrator, its relative tolerance and its step limit. One parser, so both commands take the same
/// values and refuse the same contradictions with the same messages.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/scene.hpp"
#include "covopt/optim/oracle.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// --oracle, --method, --rtol and --max-steps as typed.
struct OracleFlags {
  std::optional<std::string> oracle;  ///< --oracle auto|exact|time-path (default auto)
  std::optional<std::string> method;  ///< --method: the time path's integrator (or exact)
  std::optional<std::string> rtol;    ///< --rtol: the time path's relative tolerance [-]
  std::optional<long> max_steps;      ///< --max-steps: the time path's step limit per impact
  bool given() const noexcept { return oracle || method || rtol || max_steps; }
};

/// Adds the four options to `sub` in `group`; `judged` says what the oracle judges ("the
/// designs", "the impacts of the limit search").
void AddOracleOptions(CLI::App& sub, OracleFlags& flags, std::string_view judged, std::string_view group);

/// The oracle options the flags ask for on `scene` (read and checked: its braking and neck
/// decide what --oracle exact may answer and what auto chooses). `purpose` completes the
/// warning given when auto takes the exact path although --method or --rtol was typed: "(add
/// --oracle time-path to <purpose> on the time path)".
/// @throws InputError naming the flag, the value and what is allowed: an unknown oracle or
///         integrator, --rtol outside [1e-14, 1e-2], --max-steps < 10, --method exact with
///         --oracle time-path, --method/--rtol/--max-steps with the exact path, --oracle exact on
///         a braking or neck scene.
optim::OracleOptions ResolveOracleFlags(const OracleFlags& flags, const Scene& scene, std::string_view purpose,
                                        std::vector<std::string>& warnings);

}  // namespace covopt::cli
