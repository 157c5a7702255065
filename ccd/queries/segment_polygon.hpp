#pragma once
// Distance from a segment S(s) = p0 + s (p1 - p0), s in [0, 1], to a static convex polygon
// (ccd/scene/scenery.hpp: the closed convex set). Used by the capsule bound's static test.
//
// Units: the scene's (metres). Method: with h0, h1 the signed heights of p0, p1 above the
// polygon's plane, the segment meets the polygon when it crosses (or touches) the plane at
// a point that projects inside (distance 0, status Crossing). Otherwise the closest pair
// is either an end point against the polygon (ccd/queries/point_polygon.hpp) or the segment
// against one of the polygon's edges (ccd/queries/segment_segment.hpp): away from the
// crossing the height is linear along the segment, so an inner point of the face can only
// be closest to an end point. Coordinates are relative to the polygon's first vertex.
// Cases: a segment parallel to the plane (h0 == h1), lying in it (h0 == h1 == 0), through
// an edge or a vertex (the edge distance is 0), a point segment (p0 == p1: the point's
// distance) all take the same path.
// Accuracy: within a few ulps of the magnitudes involved (|p0 - v_0|, |p1 - v_0|, the
// polygon's extent) of the exact distance: a crossing point that rounds just outside the
// polygon is then within rounding of an edge. Conservative callers add a slack of that
// size (bounds/rounding.hpp). No "no contact" case: the distance always exists.
#include <ccd/geometry/vec3.hpp>
#include <ccd/scene/scenery.hpp>

namespace ccd {

struct SegmentPolygonResult {
  enum class Status : std::uint8_t {
    Crossing,  ///< the segment meets the polygon's face: distance 0, `s` the crossing parameter
    Endpoint,  ///< the closest pair has an end point of the segment (s = 0 or 1)
    Edge,      ///< the closest pair lies on the segment's inside and polygon edge `edge`
  };
  Status status = Status::Endpoint;
  double s = 0.0;                 ///< parameter of the segment's closest point, in [0, 1]
  std::uint32_t edge = 0;         ///< Edge: the edge's first vertex
  double distance_squared = 0.0;  ///< squared distance of the closest pair
};

SegmentPolygonResult segment_polygon_closest(const Vec3& p0, const Vec3& p1, const StaticPolygon& polygon);

}  // namespace ccd
