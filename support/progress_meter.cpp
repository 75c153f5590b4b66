#include "support/progress_meter.h"

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

namespace {

struct ProgressFigures {
  double fraction;
  std::string rate;  // cases a second
  std::string left;  // "12 s left", or "in 3 s" when final
};

ProgressFigures progress_figures(std::uint64_t done, std::uint64_t total, double elapsed_s, bool final) {
  const double rate = elapsed_s > 0 ? static_cast<double>(done) / elapsed_s : 0.0;
  char rate_text[32];
  std::snprintf(rate_text, sizeof rate_text, rate >= 100 ? "%.0f" : "%.3g", rate);
  return {total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 1.0, rate_text,
          final ? "in " + duration_text(elapsed_s)
                : (rate > 0 ? duration_text(static_cast<double>(total - done) / rate) + " left" : "")};
}

bool stderr_is_terminal() { return isatty(fileno(stderr)) == 1; }

}  // namespace

ProgressMeter::ProgressMeter(std::string label, std::uint64_t total, bool enabled)
    : label_(std::move(label)), total_(total), enabled_(enabled), terminal_(stderr_is_terminal()),
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


std::string progress_bar_text(const std::string& label, std::uint64_t done, std::uint64_t total, double elapsed_s,
                              bool final) {
  const ProgressFigures figures = progress_figures(done, total, elapsed_s, final);
  std::string bar(kBarWidth, ' ');
  const int filled = static_cast<int>(figures.fraction * kBarWidth);
  for (int i = 0; i < filled && i < kBarWidth; ++i) bar[static_cast<std::size_t>(i)] = '#';
  char line[512];
  std::snprintf(line, sizeof line, "%s [%s] %llu/%llu %3.0f %%  %s cases/s  %s", label.c_str(), bar.c_str(),
                static_cast<unsigned long long>(done), static_cast<unsigned long long>(total),
                100.0 * figures.fraction, figures.rate.c_str(), figures.left.c_str());
  return line;
}

void ProgressMeter::show(bool final) {
  const std::uint64_t done = this->done();
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (terminal_) {
    std::fprintf(stderr, "\r%s\033[K%s", progress_bar_text(label_, done, total_, elapsed, final).c_str(),
                 final ? "\n" : "");
  } else {
    const ProgressFigures figures = progress_figures(done, total_, elapsed, final);
    std::fprintf(stderr, "%s: %llu/%llu cases (%.1f %%), %s cases/s, %s\n", label_.c_str(),
                 static_cast<unsigned long long>(done), static_cast<unsigned long long>(total_),
                 100.0 * figures.fraction, figures.rate.c_str(), figures.left.c_str());
  }
  std::fflush(stderr);
}

void show_progress(std::size_t i, std::size_t n, const std::string& label) {
  if (stderr_is_terminal()) {
    // \033[K clears what a longer previous label left on the line.
    std::fprintf(stderr, "\r[%zu/%zu] %s\033[K", i + 1, n, label.c_str());
  } else {
    std::fprintf(stderr, "[%zu/%zu] %s\n", i + 1, n, label.c_str());
  }
  std::fflush(stderr);
}

void end_progress() {
  if (stderr_is_terminal()) std::fprintf(stderr, "\r\033[K");
}

}  // namespace railjoint
