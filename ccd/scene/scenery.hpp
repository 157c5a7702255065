#pragma once
// Static scenery: planar, convex, two-sided polygons that never move (floors, ramps,
// obstacles). A sphere touches a polygon when the distance from its centre to the polygon
// (the closed convex set, face and boundary) is at most its radius. The scene field
// `scenery` lists polygons, and an optional mesh adds triangles numbered after them
// (docs/scenery.md); scene_io validates them (planar within a tolerance, convex, no
// repeated or collinear vertices) and fills the derived plane.
#include <ccd/geometry/vec3.hpp>

#include <vector>

namespace ccd {

struct StaticPolygon {
  /// Vertices in order around the polygon (3 or more), counter-clockwise seen from
  /// `normal`'s side.
  std::vector<Vec3> vertices;
  /// Unit normal of the polygon's plane (derived from the vertices by scene_io).
  Vec3 normal{Vec3::Zero()};
  /// The plane is { x : normal . x == offset }.
  double offset = 0.0;
};

}  // namespace ccd
