#pragma once
// `sweep`: sort and sweep with a frame-coherent sort, one sweep axis. Exact (comparisons
// only): reports the same pairs as `brute`. Unlike `sap` (ccd/broad_phase/sap.hpp, the
// I-COLLIDE sweep and prune with endpoint lists and a persistent pair set), it keeps no
// pairs between frames: every frame re-sweeps the kept order.
//
// State kept between frames: the body order sorted by box start (lo) on the sweep axis.
// Each frame:
//  1. re-read the starts in the kept order and restore sorted order by insertion sort,
//     counting swaps (counters() "swaps"; O(n + swaps) for coherent motion);
//  2. sweep the sorted order: body i against the following bodies j while
//     lo_j <= hi_i on the sweep axis, then the two other axes. Every x-overlapping pair
//     {i, j} is met exactly once, from the one of the two that comes first.
// Only starts are sorted, so there is no start/end tie rule to get wrong: "lo_j <= hi_i"
// makes touching boxes overlap, and equal starts may be in either order. Its cost grows
// with the pairs overlapping on the sweep axis (~n^2 * 4 / L on the peer scene), `sap`'s
// with the swaps; docs/broad_phases.md compares them.
//
// Rebuild (stats().rebuilt): on the first call, when the body count changes, and when the
// insertion sort exceeds its swap budget (coherence lost, e.g. a complete reversal of
// the order): then the order is re-sorted from scratch with std::sort (O(n log n)) and the
// sweep axis is re-chosen as the one of largest centre variance (Welford's update, exact
// enough far from the origin). Boxes must be finite with lo <= hi.
#include <ccd/broad_phase/broad_phase.hpp>

#include <array>

namespace ccd {

struct SortSweepOptions {
  /// Swap budget per body per frame before the insertion sort gives up and the order is
  /// rebuilt: budget = kSwapsPerBody * n + 64.
  static constexpr std::uint64_t kSwapsPerBody = 32;
  std::uint64_t swaps_per_body = kSwapsPerBody;
};

class SortAndSweep final : public BroadPhase {
 public:
  explicit SortAndSweep(SortSweepOptions options = {}) : options_(options) {}
  void find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out) override;
  BroadPhaseStats stats() const override { return stats_; }
  /// {"swaps": insertion-sort swaps of the last call}.
  std::span<const Counter> counters() const override { return counters_; }
  /// Insertion-sort swaps of the last call (the "swaps" counter).
  std::uint64_t swaps() const { return counters_[0].value; }
  /// The current sweep axis (0, 1, 2).
  int axis() const { return axis_; }

 private:
  void rebuild(std::span<const Aabb> boxes);
  bool insertion_sort(std::uint64_t budget);

  SortSweepOptions options_;
  int axis_ = 0;
  std::vector<std::uint32_t> order_;  // body ids sorted by start
  std::vector<double> start_;         // lo on the sweep axis, in order
  std::vector<double> end_;           // hi on the sweep axis, in order
  std::vector<double> lo1_, hi1_, lo2_, hi2_;  // the two other axes, in order
  BroadPhaseStats stats_;
  std::uint64_t swaps_ = 0;  // this call's swaps so far
  std::array<Counter, 1> counters_{{{"swaps", 0}}};
};

}  // namespace ccd
