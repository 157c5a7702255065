#pragma once
// `brute`: every unordered pair tested with Aabb::overlaps (closed intervals, touching
// counts). O(n^2); the reference every other broad phase is tested against. Exact (no
// arithmetic, comparisons only); no state between frames; N = 0 or 1 gives no pairs.
#include <ccd/broad_phase/broad_phase.hpp>

namespace ccd {

class BruteForce final : public BroadPhase {
 public:
  void find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out) override;
  BroadPhaseStats stats() const override { return stats_; }

 private:
  BroadPhaseStats stats_;
};

}  // namespace ccd
