#pragma once
// Progress on stderr for long runs: on a terminal a redrawn bar with the time left
// (`[#########.....]  45%  12/27 jobs  1m20s left  aabb/sap dt=0.01`); otherwise one plain
// line per finished job with the same counts and estimate; nothing when quiet.
// Thread-safe. The estimate is the mean time per finished job times the jobs left.
// An observer, when given, is told the jobs done and their total as they finish, quiet or
// not (Python's ccdlab.run(progress=...)).
#include <chrono>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>

namespace ccdlab {

class Progress {
 public:
  /// observer(done, total): jobs finished of the total, called once when the jobs start
  /// (done 0) and after each job, from the thread that ran it, under the progress lock.
  using Observer = std::function<void(std::size_t done, std::size_t total)>;
  Progress(std::size_t total, bool quiet, Observer observer = {});
  /// Announces a phase that is not counted in jobs (e.g. "computing ground truth").
  void phase(const std::string& what);
  /// Part of an uncounted phase: `done` of `total` units of `what` (e.g. candidate pairs
  /// of the ground truth). On a terminal a bar with the time left since the first call
  /// of this phase; otherwise a line at most every 10 s.
  void advance(const std::string& what, std::size_t done, std::size_t total);
  /// The jobs start now (the time left is estimated from here).
  void start_jobs();
  /// One job finished; `label` says which.
  void done(const std::string& label);
  /// Ends the bar's line.
  void finish();

  /// "1h02m", "3m05s", "42s" (rounded up to a second).
  static std::string duration(double seconds);

 private:
  using Clock = std::chrono::steady_clock;
  void draw(std::size_t done, std::size_t total, const std::string& unit, double seconds_left,
            const std::string& label);

  std::mutex mutex_;
  std::size_t total_;
  std::size_t done_ = 0;
  bool quiet_;
  bool tty_;
  Observer observer_;
  bool bar_open_ = false;  // a bar line is on screen, not yet ended
  Clock::time_point start_ = Clock::now();
  std::string phase_;  // the fractional phase being drawn
  Clock::time_point phase_start_{};
  Clock::time_point last_line_{};
};

}  // namespace ccdlab
