#include <ccd/broad_phase/pair_set.hpp>

#include <algorithm>
#include <bit>

namespace ccd {

void PairSet::resize_table(std::size_t capacity) {
  slots_.assign(capacity, Slot{});
  mask_ = capacity - 1;
  shift_ = 64u - static_cast<unsigned>(std::countr_zero(capacity));
  for (std::size_t i = 0; i < dense_.size(); ++i) {
    const std::uint64_t k = key(dense_[i].a, dense_[i].b);
    std::size_t s = home(k);
    while (slots_[s].key != kEmpty) s = (s + 1) & mask_;
    slots_[s] = {k, static_cast<std::uint32_t>(i)};
  }
}

void PairSet::clear(std::size_t expected) {
  dense_.clear();
  resize_table(std::bit_ceil(std::max<std::size_t>(64, 2 * expected + 2)));
}

std::size_t PairSet::find(std::uint64_t k) const {
  for (std::size_t s = home(k);; s = (s + 1) & mask_) {
    if (slots_[s].key == k) return s;
    if (slots_[s].key == kEmpty) return kNone;
  }
}

bool PairSet::insert(std::uint32_t a, std::uint32_t b) {
  const std::uint64_t k = key(a, b);
  std::size_t s = home(k);
  for (; slots_[s].key != kEmpty; s = (s + 1) & mask_)
    if (slots_[s].key == k) return false;
  if (2 * (dense_.size() + 1) > slots_.size()) {  // keep the load factor <= 1/2
    dense_.push_back({a, b});
    resize_table(2 * slots_.size());
    return true;
  }
  slots_[s] = {k, static_cast<std::uint32_t>(dense_.size())};
  dense_.push_back({a, b});
  return true;
}

bool PairSet::erase(std::uint32_t a, std::uint32_t b) {
  std::size_t s = find(key(a, b));
  if (s == kNone) return false;
  // Move the last member into the erased member's place in dense_.
  const std::uint32_t idx = slots_[s].index;
  const BodyPair last = dense_.back();
  dense_.pop_back();
  if (idx != dense_.size()) {
    dense_[idx] = last;
    slots_[find(key(last.a, last.b))].index = idx;
  }
  // Backward-shift deletion: pull later members of the probe run into the hole when
  // their home is not cyclically within (hole, slot].
  for (std::size_t j = (s + 1) & mask_; slots_[j].key != kEmpty; j = (j + 1) & mask_) {
    const std::size_t h = home(slots_[j].key);
    if (((j - h) & mask_) >= ((j - s) & mask_)) {
      slots_[s] = slots_[j];
      s = j;
    }
  }
  slots_[s] = Slot{};
  return true;
}

}  // namespace ccd
