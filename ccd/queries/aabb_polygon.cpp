#include <ccd/queries/aabb_polygon.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ccd {
namespace {

// Disjoint on axis L: the polygon's projection (relative to the centre c) lies outside
// [-w, w], w = sum_k |L_k| e_k + slack |L|.
bool separated(const Vec3& L, const Vec3& e, const std::vector<Vec3>& rel, double slack) {
  const double len = L.norm();
  if (!(len > 0.0)) return false;
  const double w = std::abs(L.x()) * e.x() + std::abs(L.y()) * e.y() + std::abs(L.z()) * e.z() + slack * len;
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const Vec3& p : rel) {
    const double d = p.dot(L);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  return lo > w || hi < -w;
}

}  // namespace

double aabb_polygon_rounding(const Aabb& box, const StaticPolygon& polygon) {
  double m = std::max(box.lo.cwiseAbs().maxCoeff(), box.hi.cwiseAbs().maxCoeff());
  for (const Vec3& v : polygon.vertices) m = std::max(m, v.cwiseAbs().maxCoeff());
  return 16.0 * std::numeric_limits<double>::epsilon() * m;
}

bool aabb_polygon_overlap(const Aabb& box, const StaticPolygon& polygon, double slack) {
  if (!(box.lo.array() <= box.hi.array()).all()) return false;
  const auto& v = polygon.vertices;
  if (v.empty()) return false;
  // The coordinate axes: the polygon's box against the grown box.
  for (int k = 0; k < 3; ++k) {
    double lo = v[0][k], hi = v[0][k];
    for (const Vec3& p : v) {
      lo = std::min(lo, p[k]);
      hi = std::max(hi, p[k]);
    }
    if (lo > box.hi[k] + slack || hi < box.lo[k] - slack) return false;
  }
  const Vec3 c = (box.lo + box.hi) * 0.5;
  // Half-extents, rounded up so that [c - e, c + e] contains the box.
  const Vec3 e = ((box.hi - box.lo) * 0.5).cwiseMax((box.hi - c).cwiseMax(c - box.lo));
  thread_local std::vector<Vec3> rel;
  rel.clear();
  for (const Vec3& p : v) rel.push_back(p - c);
  if (separated(polygon.normal, e, rel, slack)) return false;
  const std::size_t m = v.size();
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3 d = v[(i + 1) % m] - v[i];
    for (int k = 0; k < 3; ++k) {
      const Vec3 L = Vec3::Unit(k).cross(d);
      if (separated(L, e, rel, slack)) return false;
    }
  }
  return true;
}

}  // namespace ccd
