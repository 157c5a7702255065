#include <bounds/volume.hpp>

#include <ccd/queries/point_segment.hpp>

#include <algorithm>

namespace ccd {

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
