#include "progress_reporter.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>

namespace hullinspect::cli {

namespace {
constexpr auto kTerminalInterval = std::chrono::milliseconds(100);
constexpr auto kLogInterval = std::chrono::seconds(60);
constexpr int kBarWidth = 30;
}  // namespace

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const long s = std::lround(seconds);
  if (s >= 3600) return fmt::format("{}h{:02}m", s / 3600, (s % 3600) / 60);
  if (s >= 60) return fmt::format("{}m{:02}s", s / 60, s % 60);
  return fmt::format("{}s", s);
}

ProgressReporter::ProgressReporter(bool terminal)
    : terminal_(terminal), last_(std::chrono::steady_clock::now()) {}

std::string ProgressReporter::line(const experiment::Progress& p) const {
  const int ran = p.done - p.resumed;
  const double rate = p.elapsed > 0 ? ran / p.elapsed : 0.0;
  const std::string eta =
      p.done >= p.total ? "done" : rate > 0 ? "ETA " + format_duration((p.total - p.done) / rate) : "ETA ?";
  const double fraction = p.total > 0 ? static_cast<double>(p.done) / p.total : 1.0;
  return fmt::format("{}/{} runs ({:.1f}%), {:.1f} runs/s, {}", p.done, p.total, 100.0 * fraction,
                     rate, eta);
}

void ProgressReporter::update(const experiment::Progress& p) {
  latest_ = p;
  const auto now = std::chrono::steady_clock::now();
  if (terminal_) {
    if (drawn_ && now - last_ < kTerminalInterval && p.done < p.total) return;
    const double fraction = p.total > 0 ? static_cast<double>(p.done) / p.total : 1.0;
    const int filled = static_cast<int>(fraction * kBarWidth);
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.append(static_cast<std::size_t>(kBarWidth - filled), '.');
    std::fprintf(stderr, "\r[%s] %s\033[K", bar.c_str(), line(p).c_str());
    std::fflush(stderr);
    drawn_ = true;
    last_ = now;
  } else if (now - last_ >= kLogInterval) {
    std::fprintf(stderr, "hullinspect: %s\n", line(p).c_str());
    last_ = now;
  }
}

void ProgressReporter::finish() {
  if (terminal_) {
    if (drawn_) std::fprintf(stderr, "\n");
  } else {
    std::fprintf(stderr, "hullinspect: %s\n", line(latest_).c_str());
  }
  std::fflush(stderr);
}

}  // namespace hullinspect::cli
