#include <ccd/broad_phase/variance_axis.hpp>

namespace ccd {

int largest_variance_axis(std::span<const Aabb> boxes) {
  double mean[3] = {0, 0, 0}, m2[3] = {0, 0, 0};
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      const double c = 0.5 * boxes[i].lo[a] + 0.5 * boxes[i].hi[a];
      const double d = c - mean[a];
      mean[a] += d / static_cast<double>(i + 1);
      m2[a] += d * (c - mean[a]);
    }
  }
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (m2[a] > m2[axis]) axis = a;
  return axis;
}

}  // namespace ccd
