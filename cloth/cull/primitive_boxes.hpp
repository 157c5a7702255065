#pragma once
// Boxes of a mesh's primitives over one check interval: each vertex's box holds its
// positions at both ends of the interval (with linear motion, its whole path), widened on
// every side by `inflate` and rounded outwards. An edge's or a triangle's box is the union
// of its vertices' boxes, so it holds the primitive at every time of the interval (a convex
// combination of points in a convex box stays in it). With inflate = separation / 2, two
// primitives that come within the separation at some time have overlapping boxes: each
// coordinate of the two closest points differs by at most the separation.
#include <cloth/sim/cloth_mesh.hpp>
#include <ccd/geometry/aabb.hpp>

#include <cmath>
#include <limits>
#include <span>
#include <vector>

namespace ccd::cloth {

/// The box of the segment from a to b, widened by `inflate` (m, >= 0, finite) and rounded
/// outwards: the rounded difference may land above the exact one, so one step down makes
/// it a lower bound (and one step up an upper bound for hi). No widening when inflate = 0.
inline Aabb swept_point_box(const Vec3& a, const Vec3& b, double inflate) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Aabb box{a.cwiseMin(b), a.cwiseMax(b)};
  if (inflate > 0)
    for (int k = 0; k < 3; ++k) {
      box.lo[k] = std::nextafter(box.lo[k] - inflate, -inf);
      box.hi[k] = std::nextafter(box.hi[k] + inflate, inf);
    }
  return box;
}

/// Every vertex's swept box for x0 -> x1, widened by `inflate` (m, >= 0, finite).
void vertex_boxes(std::span<const Vec3> x0, std::span<const Vec3> x1, double inflate, std::vector<Aabb>& out);

inline Aabb edge_box(std::span<const Aabb> v, const std::array<std::uint32_t, 2>& e) {
  Aabb b = v[e[0]];
  b.merge(v[e[1]]);
  return b;
}

inline Aabb triangle_box(std::span<const Aabb> v, const std::array<std::uint32_t, 3>& t) {
  Aabb b = v[t[0]];
  b.merge(v[t[1]]);
  b.merge(v[t[2]]);
  return b;
}

}  // namespace ccd::cloth
