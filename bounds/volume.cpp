#include <bounds/volume.hpp>

#include <algorithm>

namespace ccd {
namespace {

double point_segment_distance(const Vec3& x, const Vec3& p0, const Vec3& p1) {
  const Vec3 d = p1 - p0;
  const double dd = d.squaredNorm();
  const double u = dd > 0.0 ? std::clamp((x - p0).dot(d) / dd, 0.0, 1.0) : 0.0;
  return (x - (p0 + d * u)).norm();
}

}  // namespace

Aabb Volume::hull() const {
  switch (kind) {
    case Kind::Box: return {a, b};
    case Kind::Sphere: return Aabb::around(a, radius);
    case Kind::Capsule: return {a.cwiseMin(b).array() - radius, a.cwiseMax(b).array() + radius};
    case Kind::OrientedBox: {
      const Vec3 e = axes.cwiseAbs() * b;
      return {a - e, a + e};
    }
  }
  return {a, a};
}

bool Volume::contains(const Vec3& x, double r, double tolerance) const {
  switch (kind) {
    case Kind::Box:
      return (a.array() <= x.array() - r + tolerance).all() && (x.array() + r <= b.array() + tolerance).all();
    case Kind::Sphere: return (x - a).norm() + r <= radius + tolerance;
    case Kind::Capsule: return point_segment_distance(x, a, b) + r <= radius + tolerance;
    case Kind::OrientedBox:
      return ((axes.transpose() * (x - a)).cwiseAbs().array() + r <= b.array() + tolerance).all();
  }
  return false;
}

}  // namespace ccd
