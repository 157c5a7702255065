#include <ccd/broad_phase/static_index.hpp>

#include <algorithm>
#include <stdexcept>

namespace ccd {

Aabb polygon_box(const StaticPolygon& polygon) {
  if (polygon.vertices.empty()) throw std::invalid_argument("polygon_box: a polygon without vertices");
  Aabb b{polygon.vertices[0], polygon.vertices[0]};
  for (const Vec3& v : polygon.vertices) {
    b.lo = b.lo.cwiseMin(v);
    b.hi = b.hi.cwiseMax(v);
  }
  return b;
}

StaticIndex::StaticIndex(std::span<const Aabb> boxes, std::size_t leaf_size) : boxes_(boxes.begin(), boxes.end()) {
  if (leaf_size < 1) throw std::invalid_argument("StaticIndex: leaf_size must be >= 1");
  order_.resize(boxes_.size());
  for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<std::uint32_t>(i);
  if (!boxes_.empty()) {
    nodes_.reserve(2 * (boxes_.size() / leaf_size + 1));
    build(0, static_cast<std::uint32_t>(boxes_.size()), leaf_size);
  }
}

StaticIndex StaticIndex::from_polygons(std::span<const StaticPolygon> polygons, std::size_t leaf_size) {
  std::vector<Aabb> boxes;
  boxes.reserve(polygons.size());
  for (const StaticPolygon& p : polygons) boxes.push_back(polygon_box(p));
  return StaticIndex(boxes, leaf_size);
}

std::uint32_t StaticIndex::build(std::uint32_t begin, std::uint32_t end, std::size_t leaf_size) {
  const auto self = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back({});
  Aabb box = boxes_[order_[begin]];
  Aabb centres{box.lo + box.hi, box.lo + box.hi};  // twice the centres: exact comparisons
  for (std::uint32_t i = begin; i < end; ++i) {
    const Aabb& b = boxes_[order_[i]];
    box.merge(b);
    const Vec3 c = b.lo + b.hi;
    centres.lo = centres.lo.cwiseMin(c);
    centres.hi = centres.hi.cwiseMax(c);
  }
  if (end - begin <= leaf_size || centres.lo == centres.hi) {
    nodes_[self] = {box, begin, end - begin};
    return self;
  }
  int axis = 0;
  (centres.hi - centres.lo).maxCoeff(&axis);
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](std::uint32_t a, std::uint32_t b) {
                     const double ca = boxes_[a].lo[axis] + boxes_[a].hi[axis];
                     const double cb = boxes_[b].lo[axis] + boxes_[b].hi[axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  build(begin, mid, leaf_size);
  const std::uint32_t right = build(mid, end, leaf_size);
  nodes_[self] = {box, right, 0};
  return self;
}

std::uint64_t StaticIndex::query(const Aabb& q, std::vector<std::uint32_t>& out) const {
  if (nodes_.empty()) return 0;
  std::uint64_t tests = 0;
  const std::size_t first_out = out.size();
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    ++tests;
    if (!n.box.overlaps(q)) continue;
    if (n.count > 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        ++tests;
        if (boxes_[order_[i]].overlaps(q)) out.push_back(order_[i]);
      }
      continue;
    }
    const auto self = static_cast<std::uint32_t>(&n - nodes_.data());
    stack[top++] = n.first;    // right child
    stack[top++] = self + 1;   // left child
  }
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first_out), out.end());
  return tests;
}

std::uint64_t StaticIndex::find_pairs(std::span<const Aabb> moving, std::vector<StaticPair>& out) const {
  out.clear();
  std::uint64_t tests = 0;
  thread_local std::vector<std::uint32_t> hits;
  for (std::size_t b = 0; b < moving.size(); ++b) {
    hits.clear();
    tests += query(moving[b], hits);
    for (const std::uint32_t p : hits) out.push_back({static_cast<std::uint32_t>(b), p});
  }
  return tests;
}

}  // namespace ccd
