#include <ccd/broad_phase/grid.hpp>

#include <algorithm>
#include <limits>

namespace ccd {

void UniformGrid::find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out) {
  out.clear();
  stats_ = {};
  stats_.rebuilt = true;
  if (boxes.size() < 2) return;
  constexpr double inf = std::numeric_limits<double>::infinity();
  double lo0 = inf, lo1 = inf, lo2 = inf, hi0 = -inf, hi1 = -inf, hi2 = -inf, ext = 0.0;
  for (const Aabb& b : boxes) {
    lo0 = std::min(lo0, b.lo.x());
    lo1 = std::min(lo1, b.lo.y());
    lo2 = std::min(lo2, b.lo.z());
    hi0 = std::max(hi0, b.lo.x());
    hi1 = std::max(hi1, b.lo.y());
    hi2 = std::max(hi2, b.lo.z());
    ext = std::max({ext, b.hi.x() - b.lo.x(), b.hi.y() - b.lo.y(), b.hi.z() - b.lo.z()});
  }
  const std::array<double, 3> origin{lo0, lo1, lo2};
  const std::array<double, 3> span{hi0 - lo0, hi1 - lo1, hi2 - lo2};
  cell_ = detail::admissible_cell(std::max(ext, options_.cell_size) * (1 + detail::kCellSlack), span);
  const double cell[1] = {cell_};
  cells_.build(boxes, {}, cell, origin, span);
  stats_.box_tests = cells_.find_pairs(out);
}

}  // namespace ccd
