#include "primitive_boxes.hpp"

#include <cmath>
#include <limits>

namespace ccd::cloth {

void vertex_boxes(std::span<const Vec3> x0, std::span<const Vec3> x1, double inflate, std::vector<Aabb>& out) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  out.resize(x0.size());
  for (std::size_t i = 0; i < x0.size(); ++i) {
    Aabb& b = out[i];
    b.lo = x0[i].cwiseMin(x1[i]);
    b.hi = x0[i].cwiseMax(x1[i]);
    if (inflate > 0)
      for (int k = 0; k < 3; ++k) {
        // The rounded difference may land above the exact one: one step down makes it a
        // lower bound (and one step up an upper bound for hi).
        b.lo[k] = std::nextafter(b.lo[k] - inflate, -inf);
        b.hi[k] = std::nextafter(b.hi[k] + inflate, inf);
      }
  }
}

}  // namespace ccd::cloth
