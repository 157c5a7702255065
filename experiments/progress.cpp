#include "progress.hpp"

#include <cmath>
#include <cstdio>
#include <unistd.h>
#include <utility>

namespace ccdlab {

Progress::Progress(std::size_t total, bool quiet, Observer observer)
    : total_(total), quiet_(quiet), tty_(::isatty(2) != 0), observer_(std::move(observer)) {}

std::string Progress::duration(double seconds) {
  const auto s = static_cast<long long>(std::ceil(std::max(0.0, seconds)));
  char text[32];
  if (s >= 3600) std::snprintf(text, sizeof text, "%lldh%02lldm", s / 3600, s % 3600 / 60);
  else if (s >= 60) std::snprintf(text, sizeof text, "%lldm%02llds", s / 60, s % 60);
  else std::snprintf(text, sizeof text, "%llds", s);
  return text;
}

void Progress::phase(const std::string& what) {
  if (quiet_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (bar_open_) std::fprintf(stderr, "\n");
  bar_open_ = false;
  std::fprintf(stderr, "ccdlab: %s\n", what.c_str());
}

void Progress::draw(std::size_t done, std::size_t total, const std::string& unit, double seconds_left,
                    const std::string& label) {
  const std::string left = done >= total ? std::string("done") : duration(seconds_left) + " left";
  if (tty_) {
    constexpr int width = 30;
    const int filled = total ? static_cast<int>(width * done / total) : width;
    std::fprintf(stderr, "\r[%.*s%*s] %3zu%%  %zu/%zu %s  %s  %-36.36s", filled, "##############################",
                 width - filled, "", total ? 100 * done / total : 100, done, total, unit.c_str(), left.c_str(),
                 label.c_str());
    bar_open_ = true;
  } else {
    std::fprintf(stderr, "ccdlab: [%zu/%zu %s, %s] %s\n", done, total, unit.c_str(), left.c_str(), label.c_str());
  }
  std::fflush(stderr);
}

void Progress::advance(const std::string& what, std::size_t done, std::size_t total) {
  if (quiet_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  const auto now = Clock::now();
  if (what != phase_) {
    phase_ = what;
    phase_start_ = last_line_ = now;
    if (!tty_) return;  // plain lines: the first one after 10 s
  }
  if (!tty_ && now - last_line_ < std::chrono::seconds(10) && done < total) return;
  last_line_ = now;
  const double elapsed = std::chrono::duration<double>(now - phase_start_).count();
  const double left = done ? elapsed / double(done) * double(total - done) : 0.0;
  draw(done, total, what, left, "");
  if (done >= total && tty_) {
    std::fprintf(stderr, "\n");
    bar_open_ = false;
  }
}

void Progress::done(const std::string& label) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++done_;
  if (observer_) observer_(done_, total_);
  if (quiet_) return;
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  const double left = elapsed / double(done_) * double(total_ - std::min(done_, total_));
  draw(done_, total_, "jobs", left, label);
}

void Progress::start_jobs() {
  std::lock_guard<std::mutex> lock(mutex_);
  start_ = Clock::now();
  if (observer_) observer_(done_, total_);
}

void Progress::finish() {
  if (quiet_ || !tty_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (bar_open_) std::fprintf(stderr, "\n");
  bar_open_ = false;
}

}  // namespace ccdlab
