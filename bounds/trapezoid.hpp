#pragma once
// Axis-aligned hyper-trapezoid: a box over a time interval [t0, t1] whose faces move
// linearly in time, from (lo0, hi0) at t0 to (lo1, hi1) at t1 (ccd-math §5). It is the
// building block of the `horn` bound: Hubbard's parabolic horn (centre p + v s, radius
// r + A s^2/2) over a sub-interval lies in the box with centre p + v s and half-width
// interpolated linearly between the radii at the ends (the chord of a convex function
// lies above it).
//
// trapezoid_overlap: exact for the two trapezoids (up to a few ulps in the interpolation
// parameter, widened outwards: conservative). On each axis, "hi_a(t) >= lo_b(t)" and
// "hi_b(t) >= lo_a(t)" are linear inequalities in t; intersecting the six half-lines with
// [t0, t1] gives the set of times at which the boxes overlap (closed: touching counts).
// The answer is a bound's PairTest (bounds/bound.hpp): non-empty: status Possible and
// `earliest` = its lower end (a time before which the two boxes are disjoint). Empty:
// status Disjoint, `earliest` = +infinity.
// Both trapezoids must share [t0, t1] (the caller's sub-intervals are the same).
#include <bounds/bound.hpp>
#include <ccd/geometry/aabb.hpp>

#include <limits>

namespace ccd {

struct Trapezoid {
  double t0 = 0.0;
  double t1 = 0.0;
  Vec3 lo0{Vec3::Zero()};
  Vec3 hi0{Vec3::Zero()};
  Vec3 lo1{Vec3::Zero()};
  Vec3 hi1{Vec3::Zero()};

  /// The box at time t in [t0, t1] (linear interpolation of the faces).
  Aabb at(double t) const {
    const double u = t1 > t0 ? (t - t0) / (t1 - t0) : 0.0;
    return {lo0 + (lo1 - lo0) * u, hi0 + (hi1 - hi0) * u};
  }
  /// The box enclosing the whole trapezoid.
  Aabb hull() const { return {lo0.cwiseMin(lo1), hi0.cwiseMax(hi1)}; }
};

namespace detail {
// Restricts [u_lo, u_hi] to where the linear function with values f0 at u = 0 and f1 at
// u = 1 is >= 0. The crossing parameter is widened by 4 ulps (conservative).
inline void clip_nonnegative(double f0, double f1, double& u_lo, double& u_hi) {
  constexpr double widen = 4.0 * std::numeric_limits<double>::epsilon();
  if (f0 >= 0.0) {
    if (f1 < 0.0) u_hi = std::min(u_hi, f0 / (f0 - f1) + widen);
  } else if (f1 >= 0.0) {
    u_lo = std::max(u_lo, f0 / (f0 - f1) - widen);
  } else {
    u_lo = 2.0;  // negative throughout: empty
  }
}
}  // namespace detail

inline PairTest trapezoid_overlap(const Trapezoid& a, const Trapezoid& b) {
  double u_lo = 0.0;
  double u_hi = 1.0;
  for (int k = 0; k < 3; ++k) {
    detail::clip_nonnegative(a.hi0[k] - b.lo0[k], a.hi1[k] - b.lo1[k], u_lo, u_hi);
    detail::clip_nonnegative(b.hi0[k] - a.lo0[k], b.hi1[k] - a.lo1[k], u_lo, u_hi);
    if (u_lo > u_hi) return {};
  }
  u_lo = std::max(u_lo, 0.0);
  return {PairTest::Status::Possible, a.t0 + u_lo * (a.t1 - a.t0)};
}

/// The part of `z` over [u0, u1] (z.t0 <= u0 <= u1 <= z.t1): faces interpolated
/// linearly, then widened outwards by the interpolation's rounding error (the error of the
/// time fraction times the faces' change, plus 4 ulps of the faces' magnitude), so the
/// result contains the exact restriction. `z` itself when [u0, u1] is its whole interval.
Trapezoid restrict_trapezoid(const Trapezoid& z, double u0, double u1);

/// The PairTest of two bodies each covered by a sequence of trapezoids (contiguous, in
/// time order: za[0..ma), zb[0..mb)) over the common part of their intervals: each
/// sub-interval between consecutive breakpoints of either sequence is tested with the
/// restricted trapezoids, in time order; Possible at the first overlap with its earliest
/// time, Disjoint when none (or when the sequences share no time). Sequences over the same
/// breakpoints take the same path as a per-piece trapezoid_overlap.
PairTest trapezoid_sequence_overlap(const Trapezoid* za, int ma, const Trapezoid* zb, int mb);

/// Writes the `m` trapezoids covering the horn of a body with state `s` at t0 over equal
/// sub-intervals of [t0, t1], acceleration bound `A`, into out[0..m). With walls, an axis of
/// a sub-interval on which the free centre may pass a wall plane (min + r, max - r) is
/// replaced by the static folded interval of the sub-interval (wall_fold.hpp): faces then
/// do not move. Every face is widened by the rounding slack. Returns true when some axis was
/// folded (the body may reflect during the step).
bool horn_trapezoids(const BodyState& s, double t0, double t1, double A, const std::optional<WallBox>& walls,
                     int m, Trapezoid* out);

}  // namespace ccd
