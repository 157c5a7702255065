#include <ccd/broad_phase/cell_hash.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ccd::detail {
namespace {

constexpr double kIndexLimit = 0x1p20;

std::int32_t cell_index(double x, double origin, double inverse) {
  const double c = std::floor((x - origin) * inverse);
  if (!(c >= -kIndexLimit)) return -static_cast<std::int32_t>(kIndexLimit);  // also NaN-safe
  if (c > kIndexLimit - 1.0) return static_cast<std::int32_t>(kIndexLimit - 1.0);
  return static_cast<std::int32_t>(c);
}

}  // namespace

std::uint64_t CellHash::key(std::int32_t x, std::int32_t y, std::int32_t z) {
  const auto biased = [](std::int32_t v) { return static_cast<std::uint64_t>(v + (1 << 20)); };  // 21 bits
  return biased(x) | (biased(y) << 21) | (biased(z) << 42);
}

CellHash::Range CellHash::range_of(const Aabb& box) const {
  Range r;
  std::uint64_t cells = 1;
  for (int k = 0; k < 3; ++k) {
    r.lo[k] = cell_index(box.lo[k], origin_[k], inverse_);
    r.hi[k] = cell_index(box.hi[k], origin_[k], inverse_);
    cells *= static_cast<std::uint64_t>(r.hi[k] - r.lo[k] + 1);
  }
  r.big = cells > kMaxCellsPerBox;
  return r;
}

void CellHash::insert(std::uint32_t i, const Range& r) {
  if (r.big) {
    big_.push_back(i);
    return;
  }
  for (std::int32_t z = r.lo[2]; z <= r.hi[2]; ++z)
    for (std::int32_t y = r.lo[1]; y <= r.hi[1]; ++y)
      for (std::int32_t x = r.lo[0]; x <= r.hi[0]; ++x) cells_[key(x, y, z)].push_back(i);
}

void CellHash::remove(std::uint32_t i, const Range& r) {
  const auto drop = [i](std::vector<std::uint32_t>& list) {
    const auto it = std::find(list.begin(), list.end(), i);
    if (it == list.end()) return;
    *it = list.back();
    list.pop_back();
  };
  if (r.big) {
    drop(big_);
    return;
  }
  for (std::int32_t z = r.lo[2]; z <= r.hi[2]; ++z)
    for (std::int32_t y = r.lo[1]; y <= r.hi[1]; ++y)
      for (std::int32_t x = r.lo[0]; x <= r.hi[0]; ++x) {
        const auto it = cells_.find(key(x, y, z));
        if (it != cells_.end()) drop(it->second);  // an emptied cell keeps its list (no allocation churn)
      }
}

void CellHash::build(std::span<const Aabb> boxes, double cell) {
  cell_ = cell;
  inverse_ = 1.0 / cell;
  constexpr double inf = std::numeric_limits<double>::infinity();
  origin_[0] = origin_[1] = origin_[2] = inf;
  for (const Aabb& b : boxes)
    for (int k = 0; k < 3; ++k) origin_[k] = std::min(origin_[k], b.lo[k]);
  if (boxes.empty()) origin_[0] = origin_[1] = origin_[2] = 0.0;
  cells_.clear();
  cells_.reserve(2 * boxes.size());
  big_.clear();
  ranges_.resize(boxes.size());
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    ranges_[i] = range_of(boxes[i]);
    insert(i, ranges_[i]);
  }
}

void CellHash::move(std::uint32_t i, const Aabb& box) {
  const Range r = range_of(box);
  const Range& old = ranges_[i];
  if (r.big == old.big && std::equal(r.lo, r.lo + 3, old.lo) && std::equal(r.hi, r.hi + 3, old.hi)) return;
  remove(i, old);
  insert(i, r);
  ranges_[i] = r;
}

}  // namespace ccd::detail
