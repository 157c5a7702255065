#pragma once
// The static index: the scenery's polygon boxes (ccd/scene/scenery.hpp), built once into a
// static AABB tree and then queried with the moving bodies' boxes every step, so the
// scenery is never fed to a broad phase again and static boxes are never paired with each
// other (Box2D keeps one tree per body type for the same reason).
//
// Tree: top-down, each node's boxes split at the median of their centres along the
// longest axis of the centres' box (std::nth_element), leaves of at most `leaf_size`
// boxes; nodes stored depth-first in one array (a node's left child follows it), so a
// query walks a small explicit stack. Building is O(n log n); a query is O(log n + k) for k
// answers on well-spread scenery. The choice of a tree over a uniform grid is measured by
// benchmarks/static_index_bench.cpp (docs/scenery-methods.md quotes the medians).
// Overlap rule: closed intervals on all three axes (touching counts), as every broad phase
// (ccd/broad_phase/broad_phase.hpp); a polygon lying in an axis plane has a box of zero
// thickness and is found by boxes that touch that plane.
// Results: `query` appends the indices of every polygon whose box overlaps the query box,
// in ascending order, each once; `find_pairs` does that for every moving box.
#include <ccd/geometry/aabb.hpp>
#include <ccd/scene/scenery.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace ccd {

/// A moving body against a static polygon (indices into the bodies and the scenery).
struct StaticPair {
  std::uint32_t body = 0;
  std::uint32_t polygon = 0;
  friend bool operator==(const StaticPair&, const StaticPair&) = default;
  friend auto operator<=>(const StaticPair&, const StaticPair&) = default;
};

/// The box of a polygon: exact (the vertices' coordinate extremes; no rounding).
Aabb polygon_box(const StaticPolygon& polygon);

class StaticIndex {
 public:
  static constexpr std::size_t default_leaf_size = 4;

  StaticIndex() = default;
  /// Builds the index over `boxes` (polygon i has box i). Boxes must be finite, lo <= hi.
  explicit StaticIndex(std::span<const Aabb> boxes, std::size_t leaf_size = default_leaf_size);
  /// Builds the index over the polygons' boxes (polygon_box).
  static StaticIndex from_polygons(std::span<const StaticPolygon> polygons,
                                   std::size_t leaf_size = default_leaf_size);

  std::size_t size() const { return boxes_.size(); }
  bool empty() const { return boxes_.empty(); }
  const Aabb& box(std::uint32_t polygon) const { return boxes_[polygon]; }

  /// Appends the polygons whose boxes overlap `query`, ascending, to `out` (not cleared).
  /// Returns the number of box-box tests made (tree nodes and leaf boxes).
  std::uint64_t query(const Aabb& query, std::vector<std::uint32_t>& out) const;
  /// Every (body, polygon) pair whose boxes overlap, sorted by body then polygon; `out` is
  /// cleared first. Returns the number of box-box tests made.
  std::uint64_t find_pairs(std::span<const Aabb> moving, std::vector<StaticPair>& out) const;

 private:
  struct Node {
    Aabb box;
    std::uint32_t first = 0;  ///< leaf: first entry of order_; inner: index of the right child
    std::uint32_t count = 0;  ///< leaf: number of boxes; inner: 0 (the left child is the next node)
  };
  std::uint32_t build(std::uint32_t begin, std::uint32_t end, std::size_t leaf_size);
  std::vector<Aabb> boxes_;
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace ccd
