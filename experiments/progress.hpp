#pragma once
// Progress on stderr for long runs: a redrawn bar when stderr is a terminal, one plain
// line per finished job otherwise, nothing when quiet. Thread-safe.
#include <cstddef>
#include <mutex>
#include <string>

namespace ccdlab {

class Progress {
 public:
  Progress(std::size_t total, bool quiet);
  /// Announces a phase that is not counted in jobs (e.g. "computing ground truth").
  void phase(const std::string& what);
  /// One job finished; `label` says which.
  void done(const std::string& label);
  /// Ends the bar's line.
  void finish();

 private:
  std::mutex mutex_;
  std::size_t total_;
  std::size_t done_ = 0;
  bool quiet_;
  bool tty_;
};

}  // namespace ccdlab
