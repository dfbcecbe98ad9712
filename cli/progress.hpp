#pragma once
/// @file progress.hpp
/// The CLI's one progress bar, for the long commands (sweep, workprecision, the sampling of
/// simulate/optimize/speed-limit). The library reports progress through callbacks
/// (SweepSpec::progress, InjuryProbabilityOptions::progress, ...); this draws it on stderr,
/// and only when `err` is std::cerr (tests' streams stay clean):
///   - stderr a terminal: a bar redrawn in place, "sweep [########      ]  40 % 400/1000",
///     cleared when the bar is destroyed;
///   - stderr not a terminal (a log, a pipe): nothing, or, with
///     ProgressBarOptions::lines_when_not_terminal, once the run has taken 5 s one line per
///     10 % step, "covopt: sampling 30 % done, 41 s elapsed, about 96 s left", so that a
///     long `--samples 1e10` run in a batch job says how far it is.
/// COVOPT_PROGRESS=bar, lines (lines from the start, however short the run) or none forces
/// a style where lines are allowed; none silences every bar.

#include <chrono>
#include <cstddef>
#include <functional>
#include <ostream>
#include <string>

namespace covopt::cli {

/// How a ProgressBar shows itself.
struct ProgressBarOptions {
  /// False: never drawn (--no-progress).
  bool enabled = true;
  /// On a stderr that is not a terminal, print a line per 10 % step instead of nothing.
  bool lines_when_not_terminal = false;
  /// The bar is drawn only once the run has taken this long (short runs stay quiet).
  std::chrono::milliseconds delay{0};
};

/// A progress bar on stderr (see the file comment). Not thread-safe: callers report progress
/// from one thread at a time (the library's callbacks do).
class ProgressBar {
 public:
  /// @param label what runs: "sweep", "sampling", "designing", "workprecision".
  ProgressBar(std::ostream& err, std::string label, ProgressBarOptions options = {});
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// `done` of `total` steps; the bar shows the percentage and the counts.
  void Update(std::size_t done, std::size_t total);
  /// A fraction in [0, 1] done.
  void Update(double fraction);
  /// Update(fraction) as a callback (InjuryProbabilityOptions::progress takes it); empty when
  /// the bar is not shown, so the library skips the calls.
  std::function<void(double)> Callback();
  /// Clears a drawn bar (the destructor does too).
  void Finish();
  bool enabled() const noexcept { return enabled_; }

 private:
  using Clock = std::chrono::steady_clock;
  void Draw(double fraction, const std::string& counts);
  void PrintLine(double fraction);

  std::ostream& err_;
  std::string label_;
  ProgressBarOptions options_;
  bool enabled_ = false;
  bool lines_ = false;         // one line per 10 % instead of a bar
  bool lines_forced_ = false;  // COVOPT_PROGRESS=lines: from the start
  bool drawn_ = false;
  int last_step_ = -1;         // the last percent drawn (bar) or tenth printed (lines)
  std::string last_counts_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_draw_ = start_;
};

}  // namespace covopt::cli
