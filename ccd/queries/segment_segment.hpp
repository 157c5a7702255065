#pragma once
// Closest points of two segments S1(s) = p1 + s (q1 - p1), S2(t) = p2 + t (q2 - p2),
// s, t in [0, 1] (ccd-math §4). Units: the inputs' (metres). Used by the capsule bound.
//
// Method: minimise R(s, t) = |S1(s) - S2(t)|^2 over the unit square by reducing it to the
// convex function g(t) = min_s R(s, t) (Eberly's robust formulation). g' is continuous,
// non-decreasing and piecewise linear in t, with kinks where the optimal s reaches 0 or 1;
// its first zero is found by linear interpolation between the kinks, so no step divides
// by the near-zero determinant a e - b^2 of near-parallel segments.
//
// Guarantee: the returned pair lies on the segments and its distance exceeds the true
// minimum by at most a few ulps of |d2| (|d1| + |d2| + |p1 - p2|) in the squared distance.
// Degenerate-case policy:
// - zero-length segment(s) (|d|^2 <= 0, exactly): status Degenerate; a point segment has
//   parameter 0 and the other parameter is the clamped projection;
// - parallel or near-parallel (a e - b^2 <= 8 eps a e, i.e. sin^2(angle) below rounding):
//   status Parallel; the closest pair is the one with the smallest t, then its s (a
//   deterministic choice among the many minimisers of overlapping parallel segments);
// - otherwise status Unique.
// There is no "no contact" case: two segments always have a closest pair.
#include <ccd/geometry/vec3.hpp>

namespace ccd {

struct SegmentSegmentResult {
  enum class Status { Unique, Parallel, Degenerate };
  Status status = Status::Unique;
  double s = 0.0;                  ///< parameter on the first segment, in [0, 1]
  double t = 0.0;                  ///< parameter on the second segment, in [0, 1]
  Vec3 closest1{Vec3::Zero()};     ///< S1(s)
  Vec3 closest2{Vec3::Zero()};     ///< S2(t)
  double distance_squared = 0.0;   ///< |closest1 - closest2|^2
};

SegmentSegmentResult segment_segment_closest(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2);

}  // namespace ccd
