#pragma once
// The earliest possible contact time of two bodies from speed bounds alone, for bounds
// whose shapes carry no timing (swept_aabb, capsule, enclosing_sphere: their pair test
// says whether, this says from when).
//
// Body i was at centre p_i at the start w_i of its window and moves at speed <= s_i in it
// (wall reflections keep the speed). For t >= c = max(w_a, w_b):
//   |p_a(t) - p_b(t)| >= |p_a - p_b| - s_a (t - w_a) - s_b (t - w_b),
// so contact (distance <= R = r_a + r_b) needs
//   t >= t* = (|p_a - p_b| - R + s_a w_a + s_b w_b) / (s_a + s_b),
// and the earliest possible contact is max(c, t*) (c when both bodies rest and touch;
// never when both rest apart: +infinity). Rounding: the gap is reduced by the rounding
// slack of the positions' magnitude (bounds/rounding.hpp) and t* by 8 ulps of the times
// involved, so the answer is never later than the exact one. The caller clamps it to its
// window; it is a lower bound, not a test (an answer past the window's end means the pair
// cannot touch in it).
#include <bounds/rounding.hpp>
#include <ccd/geometry/vec3.hpp>
#include <ccd/motion/trajectory.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ccd {

struct SpeedBall {
  Vec3 centre{Vec3::Zero()};  ///< the centre at the window's start
  double t0 = 0.0;            ///< the window's start
  double speed = 0.0;         ///< bound on |velocity| over the window
  double radius = 0.0;
};

/// The largest speed of `body` over [t0, t1] from its exact pieces, walking from piece
/// k = Trajectories::piece_index(body, t0) (a state cursor's): |v| is convex along a piece
/// (v is linear), so each piece's largest speed is at one of its ends in the window;
/// widened by 8 ulps.
inline double max_speed_from(const Trajectories& motion, std::size_t body, std::size_t k, double t0, double t1) {
  double s = 0.0;
  const auto pieces = motion.pieces(body);
  for (const Piece* q = pieces.data() + k; q != pieces.data() + pieces.size() && q->t0 <= t1; ++q) {
    const double u0 = std::max(t0, q->t0);
    const double u1 = std::min(t1, q->t1);
    if (u1 < u0) continue;
    s = std::max({s, q->velocity(u0).norm(), q->velocity(u1).norm()});
  }
  return s * (1.0 + 8.0 * std::numeric_limits<double>::epsilon());
}

/// max_speed_from with the piece at t0 searched.
inline double max_speed(const Trajectories& motion, std::size_t body, double t0, double t1) {
  return max_speed_from(motion, body, motion.piece_index(body, t0), t0, t1);
}

inline double speed_earliest(const SpeedBall& a, const SpeedBall& b) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const double c = std::max(a.t0, b.t0);
  const double slack = rounding_slack(a.centre.cwiseAbs().maxCoeff() + b.centre.cwiseAbs().maxCoeff() + a.radius +
                                      b.radius);
  const double gap = (a.centre - b.centre).norm() - (a.radius + b.radius) - slack;
  if (!(gap > 0.0)) return c;
  const double s = a.speed + b.speed;
  if (!(s > 0.0)) return std::numeric_limits<double>::infinity();
  const double t = (gap + a.speed * a.t0 + b.speed * b.t0) / s;
  const double widened = t - 8.0 * eps * (std::abs(t) + std::abs(a.t0) + std::abs(b.t0));
  return std::max(c, widened);
}

/// The earliest possible contact of a body with a static set at `distance` from the body's
/// centre at the start of its window (the set does not move, distance is 1-Lipschitz):
/// t0 + (distance - r - slack) / speed, with the same roundings as speed_earliest; t0 when
/// the gap is not positive, +infinity for a resting body apart from the set.
inline double speed_earliest_static(const SpeedBall& a, double distance, double slack) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const double gap = distance - a.radius - slack;
  if (!(gap > 0.0)) return a.t0;
  if (!(a.speed > 0.0)) return std::numeric_limits<double>::infinity();
  const double t = a.t0 + gap / a.speed;
  return std::max(a.t0, t - 8.0 * eps * (std::abs(t) + std::abs(a.t0)));
}

}  // namespace ccd
