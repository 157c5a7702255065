#pragma once
// Ground-truth events indexed by pair, for matching what a method confirms against
// the exact contact intervals.
//
// The events are ordered by (pair, enter); each pair's run of events is found through an
// open-addressing hash table keyed by the ordered pair (a << 32 | b): a power-of-two table
// at most half full, Fibonacci hashing, linear probing. A lookup is O(1) expected, with no
// search over the events (the runner looks a pair up at every confirmed contact).
#include <ccd/truth/ground_truth.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace ccdlab {

class TruthIndex {
 public:
  explicit TruthIndex(std::vector<ccd::ContactEvent> events);
  const std::vector<ccd::ContactEvent>& events() const { return events_; }
  /// Indices (into events()) of the events of the pair (a, b) as stored (the pair (b, a)
  /// is another key), sorted by enter; empty when the pair has none.
  std::span<const std::uint32_t> of_pair(std::uint32_t a, std::uint32_t b) const;

 private:
  struct Slot {
    std::uint64_t key = 0;
    std::uint32_t begin = 0;  // first entry of order_
    std::uint32_t count = 0;  // 0: an empty slot
  };
  std::vector<ccd::ContactEvent> events_;
  std::vector<std::uint32_t> order_;  // event indices sorted by (pair, enter)
  std::vector<Slot> table_;           // size a power of two (or 0 when there are no events)
  int shift_ = 64;                    // 64 - log2(table size)
};

}  // namespace ccdlab
