#pragma once
// Closest point of a static convex polygon (ccd/scene/scenery.hpp: the closed convex set,
// face and boundary) to a point x.
//
// Units: the scene's (metres). Method: with n the polygon's unit normal and vertices v_i in
// order (counter-clockwise seen from n), x projects inside the face when every edge
// function ((v_{i+1} - v_i) x (x - v_i)) . n is >= 0; the distance is then the height
// |n . (x - v_0)| and the closest point the projection. Otherwise the closest point lies on the boundary:
// the nearest of the edges' closest points (point-segment, clamped). Coordinates are taken
// relative to v_0, so a polygon far from the origin loses no digits to its position.
// Accuracy: the distance is within a few ulps of max(|x - v_0|, the polygon's extent) of the
// exact one (an inside test that rounds the wrong way near an edge picks the edge, whose
// distance then differs from the plane's by as little as the rounding). Callers that need
// a conservative decision add a slack of that size (bounds/rounding.hpp).
// Degenerate input (fewer than 3 vertices, a zero normal) is not checked: scene_io rejects
// such polygons; with a zero normal the inside test fails and the boundary distance is
// returned. No "no contact" case: a polygon always has a closest point.
#include <ccd/geometry/vec3.hpp>
#include <ccd/scene/scenery.hpp>

namespace ccd {

struct PointPolygonResult {
  enum class Feature : std::uint8_t {
    Face,  ///< x projects inside the polygon: the closest point is the projection
    Edge,  ///< the closest point lies on edge `edge` (from vertex edge to edge + 1), ends included
  };
  Feature feature = Feature::Face;
  std::uint32_t edge = 0;         ///< Edge: index of the edge's first vertex
  Vec3 closest{Vec3::Zero()};     ///< the closest point of the polygon
  double distance_squared = 0.0;  ///< |x - closest|^2
};

PointPolygonResult point_polygon_closest(const Vec3& x, const StaticPolygon& polygon);

/// Whether x projects (along the normal) into the closed polygon: every edge function >= 0.
bool projects_inside(const Vec3& x, const StaticPolygon& polygon);

}  // namespace ccd
