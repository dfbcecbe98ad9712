#include "progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>

#include <unistd.h>

#include <fmt/format.h>

namespace covopt::cli {
namespace {

/// COVOPT_PROGRESS: "bar", "lines" or "none" forces a style; unset or anything else: auto.
std::string ProgressStyle() {
  const char* style = std::getenv("COVOPT_PROGRESS");
  return style == nullptr ? std::string() : std::string(style);
}

}  // namespace

ProgressBar::ProgressBar(std::ostream& err, std::string label, ProgressBarOptions options)
    : err_(err), label_(std::move(label)), options_(options) {
  const std::string style = ProgressStyle();
  if (!options.enabled || &err != &std::cerr || style == "none") return;  // tests' streams stay clean
  const bool terminal = ::isatty(STDERR_FILENO) == 1;
  if (options.lines_when_not_terminal) {
    lines_ = style == "lines" || (style != "bar" && !terminal);
    lines_forced_ = style == "lines";
  } else if (!terminal) {
    return;
  }
  enabled_ = true;
}

ProgressBar::~ProgressBar() { Finish(); }

void ProgressBar::Finish() {
  if (!drawn_) return;
  err_ << "\r\033[K" << std::flush;  // leave the line clean for what follows
  drawn_ = false;
}

std::function<void(double)> ProgressBar::Callback() {
  if (!enabled_) return {};
  return [this](double fraction) { Update(fraction); };
}

void ProgressBar::Update(std::size_t done, std::size_t total) {
  if (!enabled_ || total == 0) return;
  Draw(static_cast<double>(done) / static_cast<double>(total), fmt::format(" {}/{}", done, total));
}

void ProgressBar::Update(double fraction) {
  if (!enabled_) return;
  Draw(fraction, std::string());
}

void ProgressBar::Draw(double fraction, const std::string& counts) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  if (lines_) {
    PrintLine(fraction);
    return;
  }
  const auto now = Clock::now();
  if (now - start_ < options_.delay) return;
  const int percent = static_cast<int>(std::floor(100.0 * fraction));
  // Redrawn when what it shows changes, at most every 100 ms until the end.
  if (percent == last_step_ && counts == last_counts_) return;
  if (drawn_ && now - last_draw_ < std::chrono::milliseconds(100) && fraction < 1.0) return;
  last_step_ = percent;
  last_counts_ = counts;
  last_draw_ = now;
  constexpr int kWidth = 40;
  const int filled = percent * kWidth / 100;
  err_ << fmt::format("\r{} [{}{}] {:3} %{}", label_, std::string(static_cast<std::size_t>(filled), '#'),
                      std::string(static_cast<std::size_t>(kWidth - filled), ' '), percent, counts)
       << std::flush;
  drawn_ = true;
}

void ProgressBar::PrintLine(double fraction) {
  // A log, a pipe: one line at each 10 % step, once the run has taken 5 s (short runs stay
  // quiet; COVOPT_PROGRESS=lines prints them from the start), with the time elapsed and an
  // estimate of the time left.
  const int tenth = static_cast<int>(std::floor(10.0 * fraction));
  if (tenth <= last_step_ || tenth == 0) return;
  last_step_ = tenth;
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  if (!lines_forced_ && elapsed < 5.0) return;
  const double left = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  err_ << fmt::format("covopt: {} {} % done, {:.0f} s elapsed, about {:.0f} s left\n", label_, 10 * tenth,
                      elapsed, left)
       << std::flush;
}

}  // namespace covopt::cli
