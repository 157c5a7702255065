#include <ccd/broad_phase/grid.hpp>

#include <algorithm>
#include <limits>
#include <vector>

namespace ccd {

void UniformGrid::find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out) {
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

}  // namespace ccd
