#pragma once
// The contact function of two spheres on one quadratic piece each, evaluated in
// double-double with a certified error bound: the one definition of "touching" shared by
// the ground truth, the runner's sample test, the sphere-sphere query and the benchmarks.
//
// f(t) = |c_b(t) - c_a(t)|^2 - (r_a + r_b)^2 (units: length^2; contact is f <= 0,
// closed). Positions come from the exact double-double piece states
// (ccd/motion/trajectory.hpp: Piece + PieceLow), the offset t - t0 is formed exactly, and
// r_a + r_b is formed exactly, so the only rounding is that of the double-double
// operations themselves (bounded below) plus the model's own error near an inexact
// reflection time (PieceLow::edge_error). docs/truth.md derives the bound:
//   e_x   = 32 u^2 (|p| + |v| |s| + |a| s^2 / 2) + start_error + velocity_error |s|
//           per coordinate and body, u = 2^-53 (the last two carried from earlier breaks),
//   e_d   = sqrt(3) (e_x,a + e_x,b) + 4 u^2 |d| + edge errors       (error of d = c_b - c_a)
//   error = 2 |d| e_d + e_d^2 + 16 u^2 (|d|^2 + R^2) + 4 u^2 |f|   (error of f)
// The band therefore scales with the squared unit roundoff and the data's magnitudes,
// about 1e-32 relative, not with the motion's length over the radius.
#include <ccd/motion/trajectory.hpp>
#include <ccd/queries/certified_sublevel_set.hpp>
#include <ccd/queries/polynomial_roots.hpp>

namespace ccd {

/// Largest |p| + |v| |s| + |a| s^2 / 2 over the coordinates of piece q at time t
/// (s = t - t0): the size of the numbers a position evaluation adds.
double piece_magnitude(const Piece& q, double t);

/// A bound on the error of piece q's double-double position at t (exact_position), per
/// coordinate (metres): 32 u^2 times piece_magnitude plus the errors carried from earlier
/// breaks and, near an inexact reflection, the model's edge error.
double position_error(const Piece& q, const PieceLow& low, double t);

/// Two pieces (one per body) evaluated together.
class PairMotion {
 public:
  PairMotion(const Piece& qa, const PieceLow& la, double ra, const Piece& qb, const PieceLow& lb, double rb);
  /// f(t) rounded to double and a certified bound on |f - f_exact| (both length^2).
  ContactValue value(double t) const;
  /// f'(t) = 2 d . d' (double-double evaluation, rounded).
  double slope(double t) const;
  /// An upper bound of |f''(t)| = 2 |d'|^2 + 2 d . (a_b - a_a) (double evaluation, padded).
  double curvature_bound(double t) const;
  /// Every maximal interval of [c0, c1] (both pieces defined there) on which the bodies
  /// touch, times absolute; empty at once when certainly_apart. Critical points of f are
  /// located on the double-precision polynomial and polished on the sign of the
  /// double-double f' to adjacent doubles;
  /// f is then monotone between them. With B the error bound at such a point (plus
  /// |f''| (2 ulp)^2 at an interior critical point: the time quantisation), the point is
  /// out of contact when f > B; a local minimum with |f| <= B whose neighbouring points
  /// are out is a tangency [t, t] (endpoints of the piece included); otherwise in
  /// contact. Interval ends are the last doubles with f <= its error bound (in_contact).
  SublevelSet contact_set(double c0, double c1) const;
  /// A cheap double-precision filter: true only when f > 0 on all of [c0, c1] with a wide
  /// margin (128 eps (M + R)(M + R + P), M the relative motion's extent, P the largest
  /// coordinate magnitude), so that contact_set would return nothing. False means "solve".
  bool certainly_apart(double c0, double c1) const;
  /// Relative acceleration exactly zero: f is a quadratic in t.
  bool shared_acceleration() const { return shared_acceleration_; }

 private:
  /// The double-precision relative motion at c0, its approximate monotone split (times
  /// relative to c0) and the filter's verdict.
  struct DoubleSplit {
    Vec3 D0, Dv, Da;
    double R = 0.0;
    MonotoneSplit split;
    bool apart = false;
  };
  DoubleSplit double_split(double c0, double c1) const;

  const Piece* qa_;
  const Piece* qb_;
  const PieceLow* la_;
  const PieceLow* lb_;
  Dd radius_sum_;
  bool shared_acceleration_;
};

}  // namespace ccd
