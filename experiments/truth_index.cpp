#include "truth_index.hpp"

#include <algorithm>
#include <bit>
#include <numeric>

namespace ccdlab {
namespace {
std::uint64_t key(std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; }
// Fibonacci hashing: the top bits of key * 2^64 / golden ratio.
std::size_t slot_of(std::uint64_t k, int shift) {
  return shift >= 64 ? 0 : static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> shift);
}
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
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < order_.size(); ++i)
    pairs += i == 0 || key(events_[order_[i]].a, events_[order_[i]].b) !=
                           key(events_[order_[i - 1]].a, events_[order_[i - 1]].b);
  if (pairs == 0) return;
  const std::size_t size = std::bit_ceil(2 * pairs);
  shift_ = 64 - std::countr_zero(size);
  table_.assign(size, Slot{});
  const std::size_t mask = size - 1;
  for (std::size_t i = 0; i < order_.size();) {
    const std::uint64_t k = key(events_[order_[i]].a, events_[order_[i]].b);
    std::size_t j = i + 1;
    while (j < order_.size() && key(events_[order_[j]].a, events_[order_[j]].b) == k) ++j;
    std::size_t s = slot_of(k, shift_);
    while (table_[s].count != 0) s = (s + 1) & mask;
    table_[s] = {k, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j - i)};
    i = j;
  }
}

std::span<const std::uint32_t> TruthIndex::of_pair(std::uint32_t a, std::uint32_t b) const {
  if (table_.empty()) return {};
  const std::uint64_t k = key(a, b);
  const std::size_t mask = table_.size() - 1;
  for (std::size_t s = slot_of(k, shift_);; s = (s + 1) & mask) {
    const Slot& slot = table_[s];
    if (slot.count == 0) return {};
    if (slot.key == k) return {order_.data() + slot.begin, slot.count};
  }
}

}  // namespace ccdlab
