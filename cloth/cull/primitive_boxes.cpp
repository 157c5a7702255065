#include "primitive_boxes.hpp"

namespace ccd::cloth {

void vertex_boxes(std::span<const Vec3> x0, std::span<const Vec3> x1, double inflate, std::vector<Aabb>& out) {
  out.resize(x0.size());
  for (std::size_t i = 0; i < x0.size(); ++i) out[i] = swept_point_box(x0[i], x1[i], inflate);
}

}  // namespace ccd::cloth
