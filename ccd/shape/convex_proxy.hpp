#pragma once
// One convex representation for every shape: the convex hull of a few points, grown by a
// radius (Box2D's b2ShapeProxy). In the body frame, whose origin is the centre of mass and
// the centre of rotation. A sphere is one point (the origin) plus its radius, a capsule
// two points plus its radius, a box its 8 corners, a hull its points.
#include <ccd/geometry/vec3.hpp>

#include <cstddef>
#include <span>

namespace ccd {

struct ConvexProxy {
  std::span<const Vec3> points;  ///< at least one
  double radius = 0.0;           ///< >= 0

  /// The point of conv(points) furthest along d (the first one on ties); d need not be
  /// unit. The support point of the grown shape is this plus radius * d / |d|.
  std::size_t support_index(const Vec3& d) const {
    std::size_t best = 0;
    double best_dot = points[0].dot(d);
    for (std::size_t i = 1; i < points.size(); ++i) {
      const double x = points[i].dot(d);
      if (x > best_dot) {
        best_dot = x;
        best = i;
      }
    }
    return best;
  }
};

}  // namespace ccd
