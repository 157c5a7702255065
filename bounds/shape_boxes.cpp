#include <bounds/shape_boxes.hpp>

namespace ccd {

LocalBox local_box(const ConvexProxy& proxy) {
  Vec3 lo = proxy.points[0];
  Vec3 hi = proxy.points[0];
  for (const Vec3& p : proxy.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return {0.5 * (lo + hi), 0.5 * (hi - lo) + Vec3::Constant(proxy.radius)};
}

Aabb rotated_box(const ConvexProxy& proxy, const Mat3& rotation, const Vec3& centre) {
  Vec3 lo = rotation * proxy.points[0];
  Vec3 hi = lo;
  for (const Vec3& p : proxy.points) {
    const Vec3 w = rotation * p;
    lo = lo.cwiseMin(w);
    hi = hi.cwiseMax(w);
  }
  return {centre + lo - Vec3::Constant(proxy.radius), centre + hi + Vec3::Constant(proxy.radius)};
}

}  // namespace ccd
