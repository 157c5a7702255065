#pragma once
// A run's counts for one kind of pair, summed over the run: ScheduleStats
// (pipeline/scheduler.hpp) and the runner's record (experiments/runner.hpp) keep one
// for the body pairs (`bodies`) and one for the body-polygon pairs (`scenery`).
#include <cstdint>

namespace ccd {

struct PairCounts {
  std::uint64_t candidates = 0;    ///< pairs the broad phase (static index) reported
  std::uint64_t checks = 0;        ///< the bound's tests of them (and refinements, speed re-checks)
  std::uint64_t passed = 0;        ///< of those, Possible
  std::uint64_t narrow_calls = 0;  ///< narrow-phase calls
  std::uint64_t tests_saved = 0;   ///< passed pairs the kinematic principle skipped (not solved)

  bool operator==(const PairCounts&) const = default;
};

}  // namespace ccd
