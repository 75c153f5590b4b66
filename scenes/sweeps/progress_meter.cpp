#include "scenes/sweeps/progress_meter.h"

#include <cmath>

#include <unistd.h>

namespace railjoint {

namespace {

// A terminal is redrawn often; a log gets a line now and then, not thousands.
constexpr auto kTerminalPeriod = std::chrono::milliseconds(200);
constexpr auto kLogPeriod = std::chrono::seconds(10);
constexpr int kBarWidth = 30;

}  // namespace

std::string duration_text(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  char text[32];
  const long long s = std::llround(seconds);
  if (s < 60) {
    std::snprintf(text, sizeof text, "%lld s", s);
  } else if (s < 3600) {
    std::snprintf(text, sizeof text, "%lld:%02lld", s / 60, s % 60);
  } else {
    std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", s / 3600, (s / 60) % 60, s % 60);
  }
  return text;
}

ProgressMeter::ProgressMeter(std::string label, std::uint64_t total, bool enabled)
    : label_(std::move(label)), total_(total), enabled_(enabled), terminal_(isatty(fileno(stderr)) == 1),
      start_(std::chrono::steady_clock::now()), last_line_(start_) {
  if (enabled_) thread_ = std::thread([this] { loop(); });
}

ProgressMeter::~ProgressMeter() {
  if (!enabled_) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
  show(true);
}

void ProgressMeter::loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, kTerminalPeriod, [this] { return stop_; })) {
    const auto now = std::chrono::steady_clock::now();
    if (terminal_ || now - last_line_ >= kLogPeriod) {
      last_line_ = now;
      show(false);
    }
  }
}

void ProgressMeter::show(bool final) {
  const std::uint64_t done = this->done();
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed : 0.0;
  const double fraction = total_ > 0 ? static_cast<double>(done) / static_cast<double>(total_) : 1.0;
  const std::string left = final ? "in " + duration_text(elapsed)
                                 : (rate > 0 ? duration_text(static_cast<double>(total_ - done) / rate) + " left" : "");
  char rate_text[32];
  std::snprintf(rate_text, sizeof rate_text, rate >= 100 ? "%.0f" : "%.3g", rate);
  if (terminal_) {
    std::string bar(kBarWidth, ' ');
    const int filled = static_cast<int>(fraction * kBarWidth);
    for (int i = 0; i < filled && i < kBarWidth; ++i) bar[static_cast<std::size_t>(i)] = '#';
    std::fprintf(stderr, "\r%s [%s] %llu/%llu %3.0f %%  %s cases/s  %s\033[K%s", label_.c_str(), bar.c_str(),
                 static_cast<unsigned long long>(done), static_cast<unsigned long long>(total_), 100.0 * fraction,
                 rate_text, left.c_str(), final ? "\n" : "");
  } else {
    std::fprintf(stderr, "%s: %llu/%llu cases (%.1f %%), %s cases/s, %s\n", label_.c_str(),
                 static_cast<unsigned long long>(done), static_cast<unsigned long long>(total_), 100.0 * fraction,
                 rate_text, left.c_str());
  }
  std::fflush(stderr);
}

}  // namespace railjoint
