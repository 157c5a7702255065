#include <ccd/broad_phase/brute_force.hpp>

namespace ccd {

void BruteForce::find_pairs(std::span<const Aabb> boxes, std::vector<BodyPair>& out) {
  out.clear();
  const std::size_t n = boxes.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (boxes[i].overlaps(boxes[j]))
        out.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
  stats_ = {};
  stats_.box_tests = n < 2 ? 0 : n * (n - 1) / 2;
  stats_.rebuilt = true;
}

}  // namespace ccd
