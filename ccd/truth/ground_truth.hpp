#pragma once
// Exact ground truth of a scene: every maximal closed time interval in [0, horizon]
// during which the centres of bodies a < b are at most r_a + r_b apart.
//
// Algorithm (docs/truth.md):
//  1. Broad phase in space-time: the horizon is split into `windows` equal time windows;
//     in each, every body's exact swept box (its centre's path bounds over the window,
//     plus its radius and a small safety margin that covers rounding and the tangency
//     band) goes into the columns of a uniform grid on the two axes of largest spread and
//     is swept along the third axis within each column (each overlapping pair reported
//     once, by the column holding the low corner of the boxes' overlap). This is
//     conservative: a pair in contact at time t has overlapping boxes in every window
//     containing t. Windows run in parallel.
//  2. The candidate (pair, window) entries are sorted; each run of consecutive windows of
//     a pair is solved exactly by pair_contact_intervals (ccd/truth/pair_contact.hpp) on
//     that run. Runs run in parallel.
//  3. All intervals are sorted by (enter, a, b).
// Because pair_contact_intervals solves each common trajectory piece whole, whatever the
// window, the result equals compute_truth_all_pairs bit for bit, and it does not depend
// on the thread or window count.
//
// Units: seconds. Touching contacts have enter == exit. Intervals that start before 0
// start at 0; those that run past the horizon end there.
#include <ccd/motion/trajectory.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace ccd {

struct ContactEvent {
  std::uint32_t a = 0;  ///< body index, a < b
  std::uint32_t b = 0;
  double enter = 0.0;   ///< seconds, 0 <= enter <= exit <= horizon
  double exit = 0.0;
  bool operator==(const ContactEvent&) const = default;
};

struct TruthOptions {
  /// 0: one thread per hardware core (std::thread::hardware_concurrency()).
  static constexpr unsigned default_threads = 0;
  /// 0: automatic, ceil(0.5 * mean path extent / mean diameter) windows (a body's box
  /// grows by about two diameters per window; more windows cost more box work than the
  /// few candidate pairs they save, measured on gas scenes).
  static constexpr std::size_t default_windows = 0;
  /// Upper limit of the automatic window count.
  static constexpr std::size_t max_auto_windows = 64;
  unsigned threads = default_threads;
  std::size_t windows = default_windows;
  /// Called as the exact solving advances (candidate pair runs solved, of all of them),
  /// from any of the worker threads, one call at a time; may be empty.
  std::function<void(std::size_t done, std::size_t total)> progress;
};

/// Counters for the summary and for tuning.
struct TruthStats {
  std::size_t windows = 0;
  unsigned threads = 0;
  std::size_t candidate_pair_windows = 0;  ///< box overlaps found by the broad phase
  std::size_t candidate_runs = 0;          ///< (pair, consecutive windows) solved exactly
  std::size_t pairs_in_contact = 0;        ///< distinct pairs with at least one event
};

struct TruthResult {
  std::vector<ContactEvent> events;  ///< sorted by (enter, a, b)
  TruthStats stats;
};

/// Comparison used for the order of events: (enter, a, b).
bool event_order(const ContactEvent& x, const ContactEvent& y);

TruthResult compute_truth_detailed(const Trajectories& traj, const TruthOptions& options = {});

std::vector<ContactEvent> compute_truth(const Trajectories& traj, const TruthOptions& options = {});

/// Brute-force reference: pair_contact_intervals of all n(n-1)/2 pairs over the whole
/// horizon, sorted by (enter, a, b). For tests and small scenes only.
std::vector<ContactEvent> compute_truth_all_pairs(const Trajectories& traj);

}  // namespace ccd
