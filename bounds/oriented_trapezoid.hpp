#pragma once
// Oriented hyper-trapezoid: a box with fixed orthonormal axes (the columns of `axes`)
// whose centre and half-widths move linearly over [t0, t1], from (c0, h0) to (c1, h1).
// The building block of `horn_sat` (the horn's trapezoids oriented along the velocity).
//
// oriented_trapezoid_overlap: separating-axis test of two such boxes (Gottschalk; ccd-math
// §5, §6): with fixed orientations each of the 15 candidate axes (3 + 3 face normals,
// 9 edge crosses) gives |p(t)| <= rad(t) with p and rad linear in t, i.e. two linear
// inequalities; the boxes overlap at t exactly when t lies in all 15 intervals. Status and
// `earliest` as for trapezoid_overlap (bounds/trapezoid.hpp).
// Conservative tolerances (never report Disjoint for boxes that touch):
// - |R_ij| + kSatParallelEpsilon (1e-9) on every rotation entry: an edge-cross axis of two
//   near-parallel edges is a near-zero vector whose test is all rounding; the epsilon
//   keeps rad > |p| there (Ericson's fix), and loosens other axes by 1e-9 of a half-width;
// - rad is widened by 16 ulps of (|T|_1 at both ends + all half-widths), the size of the
//   rounding errors of the projections;
// - crossing parameters are widened by 4 ulps (as for trapezoid_overlap).
// Both trapezoids must share [t0, t1].
#include <bounds/trapezoid.hpp>

#include <Eigen/Core>

namespace ccd {

inline constexpr double kSatParallelEpsilon = 1e-9;

struct OrientedTrapezoid {
  double t0 = 0.0;
  double t1 = 0.0;
  Eigen::Matrix3d axes{Eigen::Matrix3d::Identity()};  ///< orthonormal columns
  Vec3 c0{Vec3::Zero()};
  Vec3 c1{Vec3::Zero()};
  Vec3 h0{Vec3::Zero()};  ///< half-widths along the columns of `axes` at t0
  Vec3 h1{Vec3::Zero()};

  /// The world AABB enclosing the whole trapezoid.
  Aabb hull() const;
};

/// The world AABB of an oriented trapezoid given |axes| (entrywise) and its ends, merged
/// into [lo, hi] (start them at +inf / -inf for the hull alone): the arithmetic of
/// OrientedTrapezoid::hull, for callers that keep |axes| across trapezoids. Inline, so that a
/// caller's running hull stays in registers.
inline void merge_oriented_hull(const Eigen::Matrix3d& abs_axes, const Vec3& c0, const Vec3& c1, const Vec3& h0,
                                const Vec3& h1, Vec3& lo, Vec3& hi) {
  // Half-extent of a box along world axis k: sum_i h_i |axes(k, i)|.
  const Vec3 e0 = abs_axes * h0;
  const Vec3 e1 = abs_axes * h1;
  lo = lo.cwiseMin((c0 - e0).cwiseMin(c1 - e1));
  hi = hi.cwiseMax((c0 + e0).cwiseMax(c1 + e1));
}

/// The rotation between two frames, computed once per pair of bodies.
struct SatFrames {
  Eigen::Matrix3d a_axes;
  Eigen::Matrix3d b_axes;
  Eigen::Matrix3d r;      ///< r(i, j) = a_i . b_j
  Eigen::Matrix3d abs_r;  ///< |r(i, j)| + kSatParallelEpsilon
  SatFrames(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b);
};

/// The SAT sweep of two boxes in the frames `f` (a's axes = f.a_axes, b's = f.b_axes) over
/// the shared interval [t0, t1].
PairTest oriented_overlap(const SatFrames& f, double t0, double t1, const Vec3& ca0, const Vec3& ca1,
                                  const Vec3& ha0, const Vec3& ha1, const Vec3& cb0, const Vec3& cb1,
                                  const Vec3& hb0, const Vec3& hb1);

inline PairTest oriented_trapezoid_overlap(const OrientedTrapezoid& a, const OrientedTrapezoid& b) {
  const SatFrames f(a.axes, b.axes);
  return oriented_overlap(f, a.t0, a.t1, a.c0, a.c1, a.h0, a.h1, b.c0, b.c1, b.h0, b.h1);
}

/// An orthonormal frame whose first column is v / |v| and whose other columns are
/// perpendicular (built from the coordinate axis least aligned with v, so an axis-aligned
/// v gives the identity up to signs); the identity when v is zero or too small to
/// normalise (|v|^2 < 1e-200).
Eigen::Matrix3d velocity_frame(const Vec3& v);

}  // namespace ccd
