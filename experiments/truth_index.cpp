#include "truth_index.hpp"

#include <algorithm>
#include <numeric>

namespace ccdlab {
namespace {
std::uint64_t key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; }
}  // namespace

TruthIndex::TruthIndex(std::vector<ccd::ContactEvent> events) : events_(std::move(events)) {
  order_.resize(events_.size());
  std::iota(order_.begin(), order_.end(), 0u);
  std::sort(order_.begin(), order_.end(), [&](std::uint32_t x, std::uint32_t y) {
    const auto& ex = events_[x];
    const auto& ey = events_[y];
    const auto kx = key(ex.a, ex.b), ky = key(ey.a, ey.b);
    return kx != ky ? kx < ky : ex.enter < ey.enter;
  });
  keys_.reserve(order_.size());
  for (std::uint32_t i : order_) keys_.push_back(key(events_[i].a, events_[i].b));
}

std::span<const std::uint32_t> TruthIndex::of_pair(std::uint32_t a, std::uint32_t b) const {
  const auto k = key(a, b);
  const auto lo = std::lower_bound(keys_.begin(), keys_.end(), k);
  const auto hi = std::upper_bound(lo, keys_.end(), k);
  return {order_.data() + (lo - keys_.begin()), static_cast<std::size_t>(hi - lo)};
}

}  // namespace ccdlab
