#pragma once
// Overlap of an axis-aligned box (closed) with a static convex polygon (closed), by
// separating axes. For a box and a planar convex polygon the candidate axes are the three
// coordinate axes, the polygon's normal, and the cross products of each coordinate axis
// with each polygon edge (3 + 1 + 3 m axes for m edges); the two convex sets are disjoint
// exactly when their projections on one of these axes are disjoint.
//
// Units: the scene's (metres). Projections are taken relative to the box's centre. The
// box's projected half-width is widened by `slack` (a length, >= 0) times the axis' length,
// so the test answers "the box grown by `slack` on every side meets the polygon" up to
// rounding; callers pass a slack that covers their rounding (bounds/rounding.hpp) and the
// few ulps of the projections (|coordinates| x 8 eps). Touching sets overlap.
// Axes with a zero length (an edge parallel to a coordinate axis, its cross product) are
// skipped. Guarantee: conservative (never Disjoint for sets that meet) when `slack` covers
// the projections' rounding; an empty box (lo > hi on some axis) is Disjoint.
#include <ccd/geometry/aabb.hpp>
#include <ccd/scene/scenery.hpp>

namespace ccd {

/// True when the box grown by `slack` meets the polygon (see the header comment).
bool aabb_polygon_overlap(const Aabb& box, const StaticPolygon& polygon, double slack);

/// A slack covering the rounding of aabb_polygon_overlap's projections for this pair:
/// 16 eps times the largest coordinate magnitude of the box and the polygon.
double aabb_polygon_rounding(const Aabb& box, const StaticPolygon& polygon);

}  // namespace ccd
