#include <ccd/broad_phase/broad_phase.hpp>

namespace ccd {

void BroadPhase::update(std::span<const Aabb> boxes, std::span<const std::uint32_t> moved,
                        std::vector<BodyPair>& out) {
  out.clear();
  const std::size_t n = boxes.size();
  if (moved.empty()) return;
  std::vector<char> is_moved(n, 0);
  for (const std::uint32_t m : moved) is_moved[m] = 1;
  if (moved.size() * 4 >= n) {
    std::vector<BodyPair> all;
    find_pairs(boxes, all);
    for (const BodyPair& p : all)
      if (is_moved[p.a] || is_moved[p.b]) out.push_back(p);
    return;
  }
  for (const std::uint32_t m : moved) {
    const Aabb& box = boxes[m];
    for (std::uint32_t j = 0; j < n; ++j) {
      // A pair of two moved bodies is written once, from its smaller index.
      if (j == m || (is_moved[j] && j < m) || !box.overlaps(boxes[j])) continue;
      out.push_back(m < j ? BodyPair{m, j} : BodyPair{j, m});
    }
  }
}

}  // namespace ccd
