#pragma once
// `sap`: sweep and prune with frame coherence and a persistent pair set, as in I-COLLIDE
// (Cohen, Lin, Manocha, Ponamgi 1995) and Bullet's btAxisSweep3. Exact (comparisons
// only): reports the same pairs as `brute` (closed boxes: touching counts).
//
// State kept between frames, per axis x, y, z: the list of the 2n box endpoints (value,
// body, is_end), sorted by the key (value, is_end): at equal values starts come before
// ends, so a start precedes an end of another body exactly when lo <= hi, and "start of
// a before end of b and start of b before end of a" is the closed-interval overlap. Plus
// the set of overlapping pairs (ccd/broad_phase/pair_set.hpp).
//
// Each frame, per axis: re-read the endpoint values in the kept order and restore the
// order by insertion sort with the same key, counting swaps (counters() "swaps", all three
// axes; O(n + swaps)). Insertion sort swaps exactly the endpoint pairs whose order
// changed since the last frame, once each; among them:
//  - a start moving left past another body's end: the pair starts to overlap on this
//    axis; its boxes (this frame's, all three axes) are tested and the pair is added to
//    the set if they overlap (stats().box_tests counts these tests);
//  - an end moving left past another body's start: the pair stops overlapping on this
//    axis; it is removed from the set (if present).
// This holds whatever the axis order and whatever happens on the other axes: a pair that
// overlaps in both frames has no start/end swap on any axis; one that starts to overlap
// has a start/end swap on an axis where it did not overlap, and its box test (on this
// frame's boxes) passes; one that stops overlapping has an end/start swap and no box
// test can pass for it. All three axes are sorted (not one or two plus box tests): the
// swaps of every axis are needed to see every pair that begins or ends overlapping.
// Output: the set's members (a < b), in no particular order.
//
// Rebuild (stats().rebuilt): on the first call, when the body count changes, and when
// the swaps of a frame exceed the budget (coherence lost, e.g. a complete reversal):
// the endpoints are sorted with std::sort (O(n log n)) and the pair set is refilled from
// the uniform grid (`grid`, O(n + pairs); a one-axis sweep would meet ~n^(5/3) pairs that
// overlap on that axis alone in a uniform 3D scene).
// Steady state allocates nothing (the pair set grows only when the pairs outgrow it).
// Boxes must be finite with lo <= hi.
#include <ccd/broad_phase/broad_phase.hpp>
#include <ccd/broad_phase/grid.hpp>
#include <ccd/broad_phase/pair_set.hpp>

#include <array>

namespace ccd {

struct SapOptions {
  /// Swap budget per frame (all three axes together) before the insertion sorts give up
  /// and the structure is rebuilt: swaps_per_endpoint * 6n * bit_width(2n) + 64, i.e. a
  /// multiple of the O(n log n) cost of a rebuild. A complete reversal of the order on
  /// one axis ((2n)^2 / 2 swaps) exceeds it from n ~ 100.
  static constexpr std::uint64_t kSwapsPerEndpoint = 2;
  std::uint64_t swaps_per_endpoint = kSwapsPerEndpoint;
};

class SweepAndPrune final : public BroadPhase {
 public:
  explicit SweepAndPrune(SapOptions options = {}) : options_(options) {}
  void find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out) override;
  BroadPhaseStats stats() const override { return stats_; }
  /// {"swaps": insertion-sort swaps of the last call}.
  std::span<const Counter> counters() const override { return counters_; }
  /// Insertion-sort swaps of the last call (the "swaps" counter).
  std::uint64_t swaps() const { return counters_[0].value; }

 private:
  struct Endpoint {
    double value = 0;
    std::uint32_t id = 0;  // 2 * body + is_end
  };
  void load_bounds(std::span<const Aabb> boxes);
  void rebuild(std::span<const Aabb> boxes);
  /// Insertion sort of one axis with pair updates; false when `budget` is exceeded.
  bool update_axis(int axis, std::span<const Aabb> boxes, std::uint64_t budget);

  SapOptions options_;
  bool built_ = false;
  std::array<std::vector<Endpoint>, 3> endpoints_;  // per axis, sorted by (value, is_end)
  std::array<std::vector<double>, 3> bounds_;       // per axis: [2i] = lo_i, [2i + 1] = hi_i
  UniformGrid grid_{GridOptions{.reuse = 0}};       // rebuild: fills the pair set (a plain grid pass)
  std::vector<BodyPair> fill_;                      // rebuild: the grid's pairs
  std::vector<std::uint32_t> degree_;               // per body: its pairs in the set
  PairSet pairs_;
  BroadPhaseStats stats_;
  std::uint64_t swaps_ = 0;  // this call's swaps so far
  std::array<Counter, 1> counters_{{{"swaps", 0}}};
};

}  // namespace ccd
