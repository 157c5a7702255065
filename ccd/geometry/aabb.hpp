#pragma once
// Axis-aligned bounding box as closed intervals [lo, hi] per axis. Boxes that touch
// (lo == hi of the other on some axis) overlap: every broad phase uses this rule.
#include <ccd/geometry/vec3.hpp>

namespace ccd {

struct Aabb {
  Vec3 lo{Vec3::Zero()};
  Vec3 hi{Vec3::Zero()};

  /// Box around a sphere of radius r centred at c.
  static Aabb around(const Vec3& c, double r) { return {c.array() - r, c.array() + r}; }

  /// Smallest box containing this one and `o`.
  void merge(const Aabb& o) {
    lo = lo.cwiseMin(o.lo);
    hi = hi.cwiseMax(o.hi);
  }
  /// Closed-interval overlap on all three axes (touching counts).
  bool overlaps(const Aabb& o) const {
    return lo.x() <= o.hi.x() && o.lo.x() <= hi.x() && lo.y() <= o.hi.y() && o.lo.y() <= hi.y() &&
           lo.z() <= o.hi.z() && o.lo.z() <= hi.z();
  }
};

}  // namespace ccd
