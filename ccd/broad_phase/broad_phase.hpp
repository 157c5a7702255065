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
#include <string_view>
#include <vector>

namespace ccd {

struct BodyPair {
  std::uint32_t a = 0;  ///< smaller index
  std::uint32_t b = 0;  ///< larger index
  friend bool operator==(const BodyPair&, const BodyPair&) = default;
  friend auto operator<=>(const BodyPair&, const BodyPair&) = default;
};

/// What every broad phase can say about its last find_pairs call; a field a method does
/// not track stays 0.
struct BroadPhaseStats {
  std::uint64_t box_tests = 0;      ///< box-box overlap tests performed
  bool rebuilt = false;             ///< the structure was built from scratch this frame
};

/// A method's own count for its last find_pairs call (e.g. `sap`'s insertion-sort
/// "swaps"): the name is the key under which results files sum it over steps.
struct Counter {
  std::string_view name;
  std::uint64_t value = 0;
};

class BroadPhase {
 public:
  virtual ~BroadPhase() = default;
  /// Writes the overlapping pairs (a < b, each once, any order) into `out`, clearing it
  /// first. Boxes must be finite with lo <= hi.
  virtual void find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out) = 0;
  /// For a scheduler: the boxes of `moved` (distinct indices) changed since the last call;
  /// writes every overlapping pair with at least one moved body (a < b, each once, any
  /// order) into `out`, clearing it first. The default serves a large batch (a quarter of
  /// the bodies or more) with find_pairs, filtered, and a small one by testing each moved
  /// box against every box (linear per moved body; no structure to keep up to date).
  virtual void update(std::span<const Aabb> boxes, std::span<const std::uint32_t> moved, std::vector<BodyPair>& out);
  virtual BroadPhaseStats stats() const { return {}; }
  /// The method's own counters for the last call (none by default); names are fixed per
  /// method, so a caller may sum them by name over frames.
  virtual std::span<const Counter> counters() const { return {}; }
};

}  // namespace ccd
