#pragma once
// Ground-truth events indexed by pair, for matching what a method confirms against
// the exact contact intervals.
#include <ccd/truth/ground_truth.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace ccdlab {

class TruthIndex {
 public:
  explicit TruthIndex(std::vector<ccd::ContactEvent> events);
  const std::vector<ccd::ContactEvent>& events() const { return events_; }
  /// Indices (into events()) of the pair's events, sorted by enter.
  std::span<const std::uint32_t> of_pair(std::uint32_t a, std::uint32_t b) const;

 private:
  std::vector<ccd::ContactEvent> events_;
  std::vector<std::uint64_t> keys_;     // sorted pair keys, one per entry of order_
  std::vector<std::uint32_t> order_;    // event indices sorted by (pair, enter)
};

}  // namespace ccdlab
