#include <ccd/broad_phase/grid.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ccd {

void UniformGrid::find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out) {
  hash_current_ = false;  // the boxes may all have changed
  verlet_.find_pairs(boxes, out, stats_,
                     [this](std::span<const Aabb> fat, std::vector<BodyPair>& found) { find_all(fat, found); });
}

void UniformGrid::find_all(std::span<const Aabb> boxes, std::vector<BodyPair>& out) {
  out.clear();
  stats_ = {};
  stats_.rebuilt = true;
  if (boxes.size() < 2) return;
  constexpr double inf = std::numeric_limits<double>::infinity();
  struct Bounds {
    double lo[3] = {inf, inf, inf}, hi[3] = {-inf, -inf, -inf}, ext = 0.0;
  };
  const unsigned t = detail::threads_for(boxes.size(), std::max(1u, options_.threads));
  std::vector<Bounds> part(t);
  parallel_for(t, t, [&](std::size_t i, unsigned) {
    const std::size_t b = boxes.size() * i / t, e = boxes.size() * (i + 1) / t;
    double lo0 = inf, lo1 = inf, lo2 = inf, hi0 = -inf, hi1 = -inf, hi2 = -inf, ext = 0.0;
    for (std::size_t k = b; k < e; ++k) {
      const Aabb& box = boxes[k];
      lo0 = std::min(lo0, box.lo.x());
      lo1 = std::min(lo1, box.lo.y());
      lo2 = std::min(lo2, box.lo.z());
      hi0 = std::max(hi0, box.lo.x());
      hi1 = std::max(hi1, box.lo.y());
      hi2 = std::max(hi2, box.lo.z());
      ext = std::max({ext, box.hi.x() - box.lo.x(), box.hi.y() - box.lo.y(), box.hi.z() - box.lo.z()});
    }
    part[i] = {{lo0, lo1, lo2}, {hi0, hi1, hi2}, ext};
  });
  double lo0 = inf, lo1 = inf, lo2 = inf, hi0 = -inf, hi1 = -inf, hi2 = -inf, ext = 0.0;
  for (const Bounds& p : part) {
    lo0 = std::min(lo0, p.lo[0]);
    lo1 = std::min(lo1, p.lo[1]);
    lo2 = std::min(lo2, p.lo[2]);
    hi0 = std::max(hi0, p.hi[0]);
    hi1 = std::max(hi1, p.hi[1]);
    hi2 = std::max(hi2, p.hi[2]);
    ext = std::max(ext, p.ext);
  }
  const std::array<double, 3> origin{lo0, lo1, lo2};
  const std::array<double, 3> span{hi0 - lo0, hi1 - lo1, hi2 - lo2};
  cell_ = detail::admissible_cell(std::max(ext, options_.cell_size) * (1 + detail::kCellSlack), span);
  const double cell[1] = {cell_};
  cells_.set_threads(options_.threads);
  cells_.build(boxes, {}, cell, origin, span);
  stats_.box_tests = cells_.find_pairs(out);
}

void UniformGrid::update(std::span<const Aabb> boxes, std::span<const std::uint32_t> moved,
                         std::vector<BodyPair>& out) {
  out.clear();
  const std::size_t n = boxes.size();
  if (moved.empty()) return;
  if (hash_current_ && hash_.size() == n)  // keep the hashed grid current: O(moved)
    for (const std::uint32_t m : moved) hash_.move(m, boxes[m]);
  else
    hash_current_ = false;
  if (moved.size() * 4 >= n) {  // a large batch: one sorted pass, filtered
    find_all(boxes, all_);
    order_.assign(n, 0);
    for (const std::uint32_t m : moved) order_[m] = 1;
    for (const BodyPair& p : all_)
      if (order_[p.a] || order_[p.b]) out.push_back(p);
    for (const std::uint32_t m : moved) order_[m] = 0;
    return;
  }
  stats_ = {};
  if (!hash_current_) {
    double extent = 0.0;
    for (const Aabb& b : boxes) extent += (b.hi - b.lo).maxCoeff();
    extent = 2.0 * extent / static_cast<double>(n);  // most boxes then cover 1 to 8 cells
    hash_.build(boxes, std::isfinite(extent) && extent > 0.0 ? extent : 1.0);
    hash_current_ = true;
    stats_.rebuilt = true;
    seen_.assign(n, 0);
    order_.assign(n, 0);
    query_ = 0;
  }
  for (std::size_t k = 0; k < moved.size(); ++k) order_[moved[k]] = static_cast<std::uint32_t>(k + 1);
  for (std::size_t k = 0; k < moved.size(); ++k) {
    const std::uint32_t m = moved[k];
    if (++query_ == 0) {  // wrapped: forget the old marks
      std::fill(seen_.begin(), seen_.end(), 0);
      query_ = 1;
    }
    seen_[m] = query_;
    const Aabb& box = boxes[m];
    hash_.visit(box, [&](std::uint32_t j) {
      if (seen_[j] == query_) return;
      seen_[j] = query_;
      // A pair of two moved bodies is written once, from the first of them in `moved`.
      if (order_[j] != 0 && order_[j] <= k) return;
      ++stats_.box_tests;
      if (box.overlaps(boxes[j])) out.push_back(m < j ? BodyPair{m, j} : BodyPair{j, m});
    });
  }
  for (const std::uint32_t m : moved) order_[m] = 0;
}

}  // namespace ccd
