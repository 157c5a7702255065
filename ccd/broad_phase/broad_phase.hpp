#pragma once
// The broad-phase interface: given one box per body, report every unordered pair {a, b}
// whose boxes overlap as closed intervals on all three axes (touching counts), exactly
// once, with a < b. A broad phase may keep state between calls (frames), so coherent
// methods (sweep and prune) update incrementally; a call with a different body count
// rebuilds. The registry of implementations is ccd/broad_phase/registry.hpp.
#include <ccd/geometry/aabb.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace ccd {

struct BodyPair {
  std::uint32_t a = 0;  ///< smaller index
  std::uint32_t b = 0;  ///< larger index
  friend bool operator==(const BodyPair&, const BodyPair&) = default;
  friend auto operator<=>(const BodyPair&, const BodyPair&) = default;
};

/// Statistics of the last find_pairs call; fields a method does not track stay 0.
struct BroadPhaseStats {
  std::uint64_t swaps = 0;          ///< sweep and prune: insertion-sort swaps this frame
  std::uint64_t box_tests = 0;      ///< box-box overlap tests performed
  bool rebuilt = false;             ///< the structure was built from scratch this frame
};

class BroadPhase {
 public:
  virtual ~BroadPhase() = default;
  /// Writes the overlapping pairs (a < b, each once, any order) into `out`, clearing it
  /// first. Boxes must be finite with lo <= hi.
  virtual void find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out) = 0;
  virtual BroadPhaseStats stats() const { return {}; }
};

}  // namespace ccd
