#include "progress.hpp"

#include <cstdio>
#include <unistd.h>

namespace ccdlab {

Progress::Progress(std::size_t total, bool quiet) : total_(total), quiet_(quiet), tty_(::isatty(2) != 0) {}

void Progress::phase(const std::string& what) {
  if (quiet_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  std::fprintf(stderr, "ccdlab: %s\n", what.c_str());
}

void Progress::done(const std::string& label) {
  if (quiet_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  ++done_;
  if (tty_) {
    constexpr int width = 30;
    const int filled = total_ ? static_cast<int>(width * done_ / total_) : width;
    std::fprintf(stderr, "\r[%.*s%*s] %3zu%% %zu/%zu  %-40.40s", filled, "##############################",
                 width - filled, "", total_ ? 100 * done_ / total_ : 100, done_, total_, label.c_str());
  } else {
    std::fprintf(stderr, "ccdlab: [%zu/%zu] %s\n", done_, total_, label.c_str());
  }
  std::fflush(stderr);
}

void Progress::finish() {
  if (quiet_ || !tty_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  std::fprintf(stderr, "\n");
}

}  // namespace ccdlab
