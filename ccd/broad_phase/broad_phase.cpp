#include <ccd/broad_phase/broad_phase.hpp>

#include <algorithm>

namespace ccd {

void BroadPhase::update(std::span<const Aabb> boxes, std::span<const std::uint32_t> moved,
                        std::vector<BodyPair>& out) {
  out.clear();
  const std::size_t n = boxes.size();
  if (moved.empty()) return;
  if (moved.size() * 4 >= n) {
    std::vector<char> is_moved(n, 0);
    for (const std::uint32_t m : moved) is_moved[m] = 1;
    std::vector<BodyPair> all;
    find_pairs(boxes, all);
    for (const BodyPair& p : all)
      if (is_moved[p.a] || is_moved[p.b]) out.push_back(p);
    return;
  }
  for (std::size_t k = 0; k < moved.size(); ++k) {
    const std::uint32_t m = moved[k];
    const Aabb& box = boxes[m];
    const double lo = box.lo.x(), hi = box.hi.x();
    for (std::uint32_t j = 0; j < n; ++j) {
      const Aabb& other = boxes[j];
      if (other.lo.x() > hi || other.hi.x() < lo || j == m || !box.overlaps(other)) continue;
      // A pair of two moved bodies is written once, from the first of them in `moved`.
      if (std::find(moved.begin(), moved.begin() + static_cast<std::ptrdiff_t>(k), j) !=
          moved.begin() + static_cast<std::ptrdiff_t>(k))
        continue;
      out.push_back(m < j ? BodyPair{m, j} : BodyPair{j, m});
    }
  }
}

}  // namespace ccd
