#pragma once
// Internal engine of `grid`'s incremental update (UniformGrid::update, the earliest
// scheduler's per-body refreshes): a hashed uniform grid kept between calls. Every body is
// listed in each cell its box overlaps, so moving a body costs the cells of its old and new
// boxes, and the candidates of a box are the bodies listed in the cells it overlaps. Not a
// broad phase itself: UniformGrid chooses the cell size, tests the candidates and removes
// duplicates (a body listed in several cells is visited once per shared cell).
//
// Why the candidates suffice. A box covers the cells c = floor((x - o) / s), x in
// [lo, hi], per axis, clamped to [-2^20, 2^20 - 1]. The computed index is a non-decreasing
// function of x (a rounded subtraction, a rounded product by a positive number, floor and
// clamp all are), so two boxes that share a point x on every axis share the cell of x:
// exact without any slack, whatever the cell size, far from the origin too (the clamp only
// merges distant cells).
// Boxes covering more than kMaxCellsPerBox cells are kept in a separate list instead
// ("big" bodies: a bullet's box over a long window), visited by every query; a query box
// that big visits every body.
#include <ccd/geometry/aabb.hpp>

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

namespace ccd::detail {

class CellHash {
 public:
  static constexpr std::uint64_t kMaxCellsPerBox = 64;

  /// Lists every box with cell size `cell` (> 0, finite) and origin at the smallest lower corner.
  void build(std::span<const Aabb> boxes, double cell);
  /// Bodies listed (the box count of the last build).
  std::size_t size() const { return ranges_.size(); }
  double cell_size() const { return cell_; }
  /// Body i's box is now `box`.
  void move(std::uint32_t i, const Aabb& box);

  /// Calls visit(j) for every body j that may overlap `box` (each body listed in a cell
  /// `box` covers, once per such cell, and every big body), or for every body when `box`
  /// itself is big.
  template <class Visit>
  void visit(const Aabb& box, Visit&& visit) const {
    const Range r = range_of(box);
    if (r.big) {
      for (std::uint32_t j = 0; j < ranges_.size(); ++j) visit(j);
      return;
    }
    for (const std::uint32_t j : big_) visit(j);
    for (std::int32_t z = r.lo[2]; z <= r.hi[2]; ++z)
      for (std::int32_t y = r.lo[1]; y <= r.hi[1]; ++y)
        for (std::int32_t x = r.lo[0]; x <= r.hi[0]; ++x) {
          const auto it = cells_.find(key(x, y, z));
          if (it == cells_.end()) continue;
          for (const std::uint32_t j : it->second) visit(j);
        }
  }

 private:
  struct Range {
    std::int32_t lo[3] = {0, 0, 0};
    std::int32_t hi[3] = {-1, -1, -1};
    bool big = false;
  };
  Range range_of(const Aabb& box) const;
  static std::uint64_t key(std::int32_t x, std::int32_t y, std::int32_t z);
  void insert(std::uint32_t i, const Range& r);
  void remove(std::uint32_t i, const Range& r);

  double cell_ = 1.0;
  double inverse_ = 1.0;
  double origin_[3] = {0.0, 0.0, 0.0};
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
  std::vector<Range> ranges_;
  std::vector<std::uint32_t> big_;
};

}  // namespace ccd::detail
