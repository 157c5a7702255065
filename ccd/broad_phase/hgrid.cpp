#include <ccd/broad_phase/hgrid.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace ccd {

void HierarchicalGrid::find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out) {
  verlet_.find_pairs(boxes, out, stats_,
                     [this](std::span<const Aabb> fat, std::vector<BodyPair>& found) { find_all(fat, found); });
}

void HierarchicalGrid::find_all(std::span<const Aabb> boxes, std::vector<BodyPair>& out) {
  out.clear();
  stats_ = {};
  stats_.rebuilt = true;
  const std::size_t n = boxes.size();
  if (n < 2) return;
  constexpr double inf = std::numeric_limits<double>::infinity();
  constexpr double grow = 1 + detail::kCellSlack;
  std::array<double, 3> lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  double ext = 0.0;
  extent_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Aabb& b = boxes[i];
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], b.lo[a]);
      hi[a] = std::max(hi[a], b.lo[a]);
    }
    extent_[i] = std::max({b.hi.x() - b.lo.x(), b.hi.y() - b.lo.y(), b.hi.z() - b.lo.z()}) * grow;
    ext = std::max(ext, extent_[i]);
  }
  const std::array<double, 3> span{hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
  const double top = detail::admissible_cell(ext, span);
  // Finest admissible level: admissible_cell would not have to enlarge its cell.
  int h_max = 0;
  while (h_max < 60) {
    const double s = std::ldexp(top, -(h_max + 1));
    if (detail::admissible_cell(s, span) != s) break;
    ++h_max;
  }
  // Per body: the finest level whose cell holds its (grown) extent.
  halvings_.resize(n);
  std::array<std::uint32_t, 64> count{};
  for (std::size_t i = 0; i < n; ++i) {
    const double e = extent_[i];
    int h = h_max;
    if (e > 0) {
      h = std::clamp(std::ilogb(top) - std::ilogb(e), 0, h_max);
      while (h > 0 && std::ldexp(top, -h) < e) --h;
      while (h < h_max && std::ldexp(top, -(h + 1)) >= e) ++h;
    }
    halvings_[i] = static_cast<std::uint8_t>(h);
    ++count[h];
  }
  // Engine levels: the non-empty ones, finest (largest h) first.
  std::array<std::uint8_t, 64> index{};
  cell_.clear();
  for (int h = h_max; h >= 0; --h) {
    if (count[h] == 0) continue;
    index[h] = static_cast<std::uint8_t>(cell_.size());
    cell_.push_back(std::ldexp(top, -h));
  }
  for (std::size_t i = 0; i < n; ++i) halvings_[i] = index[halvings_[i]];
  cells_.build(boxes, halvings_, cell_, lo, span);
  stats_.box_tests = cells_.find_pairs(out);
}

}  // namespace ccd
