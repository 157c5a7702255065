#include <ccd/motion/trajectory.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace ccd {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// First s in (0, limit] with x + v s + a s^2/2 == wall while moving towards the wall
// (dir = +1: the wall is above, the velocity at s must be > 0; dir = -1: below).
double first_wall_hit(double x, double v, double a, double wall, int dir, double limit) {
  const double c = x - wall;  // a/2 s^2 + v s + c = 0
  double roots[2];
  int n = 0;
  if (a == 0.0) {
    if (v != 0.0) roots[n++] = -c / v;
  } else {
    const double A = 0.5 * a;
    const double disc = v * v - 4.0 * A * c;
    if (disc >= 0.0) {
      const double q = -0.5 * (v + std::copysign(std::sqrt(disc), v));
      if (q != 0.0) {
        roots[n++] = q / A;
        roots[n++] = c / q;
      } else {
        roots[n++] = 0.0;  // v == 0 and c == 0
      }
    }
  }
  double best = kInf;
  for (int i = 0; i < n; ++i) {
    const double s = roots[i];
    if (!(s > 0.0) || s > limit) continue;
    if (dir * (v + a * s) > 0.0) best = std::min(best, s);
  }
  return best;
}

}  // namespace

Aabb Piece::centre_bounds(double u0, double u1) const {
  Aabb box{position(u0), position(u0)};
  const Vec3 e = position(u1);
  box.lo = box.lo.cwiseMin(e);
  box.hi = box.hi.cwiseMax(e);
  for (int k = 0; k < 3; ++k) {
    if (a[k] == 0.0) continue;
    const double s = -v[k] / a[k];  // vertex of this axis' parabola
    const double t = t0 + s;
    if (t > u0 && t < u1) {
      const double x = p[k] + v[k] * s + 0.5 * a[k] * s * s;
      box.lo[k] = std::min(box.lo[k], x);
      box.hi[k] = std::max(box.hi[k], x);
    }
  }
  return box;
}

Trajectories::Trajectories(const Scene& scene, const TrajectoryOptions& options)
    : horizon_(scene.horizon) {
  const std::size_t n = scene.bodies.size();
  radius_.reserve(n);
  first_.reserve(n + 1);
  pieces_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Body& b = scene.bodies[i];
    radius_.push_back(b.radius);
    const std::size_t start = pieces_.size();
    Vec3 p = b.position;
    Vec3 v = b.velocity;
    Vec3 own = b.acceleration;
    std::size_t next_change = 0;
    double t = 0.0;
    while (true) {
      const double t_change = next_change < b.acceleration_changes.size()
                                  ? b.acceleration_changes[next_change].t
                                  : horizon_;
      Vec3 a = own + scene.gravity;
      double s_end = t_change - t;
      int wall_axis = -1;
      int wall_dir = 0;
      if (scene.box) {
        for (int k = 0; k < 3; ++k) {
          const double lo = scene.box->min[k] + b.radius;
          const double hi = scene.box->max[k] - b.radius;
          // Resting contact: on the wall, not moving, pushed into it.
          if ((p[k] <= lo && v[k] == 0.0 && a[k] < 0.0) || (p[k] >= hi && v[k] == 0.0 && a[k] > 0.0))
            a[k] = 0.0;
          // Starting on a wall while moving into it: reflect at once.
          if ((p[k] <= lo && v[k] < 0.0) || (p[k] >= hi && v[k] > 0.0)) v[k] = -v[k];
        }
        for (int k = 0; k < 3; ++k) {
          const double lo = scene.box->min[k] + b.radius;
          const double hi = scene.box->max[k] - b.radius;
          const double s_hi = first_wall_hit(p[k], v[k], a[k], hi, +1, s_end);
          if (s_hi < s_end) { s_end = s_hi; wall_axis = k; wall_dir = +1; }
          const double s_lo = first_wall_hit(p[k], v[k], a[k], lo, -1, s_end);
          if (s_lo < s_end) { s_end = s_lo; wall_axis = k; wall_dir = -1; }
        }
      }
      Piece piece{t, t + s_end, p, v, a};
      if (wall_axis < 0) piece.t1 = t_change;  // exact break time, no rounding drift
      pieces_.push_back(piece);
      if (pieces_.size() - start > options.max_pieces_per_body)
        throw TooManyPieces(i, options.max_pieces_per_body);
      const double t_next = piece.t1;
      p = piece.position(t_next);
      v = piece.velocity(t_next);
      if (wall_axis >= 0) {
        p[wall_axis] = wall_dir > 0 ? scene.box->max[wall_axis] - b.radius
                                    : scene.box->min[wall_axis] + b.radius;
        v[wall_axis] = -v[wall_axis];
      } else if (next_change < b.acceleration_changes.size()) {
        own = b.acceleration_changes[next_change].acceleration;
        ++next_change;
      } else {
        break;  // reached the horizon
      }
      if (scene.box) {  // keep the centre inside despite rounding
        for (int k = 0; k < 3; ++k)
          p[k] = std::clamp(p[k], scene.box->min[k] + b.radius, scene.box->max[k] - b.radius);
      }
      t = t_next;
      if (t >= horizon_) break;
    }
    first_.push_back(static_cast<std::uint32_t>(pieces_.size()));
  }
}

const Piece& Trajectories::piece_at(std::size_t body, double t) const {
  const auto ps = pieces(body);
  // First piece whose end is > t; the last piece if none.
  auto it = std::upper_bound(ps.begin(), ps.end(), t, [](double x, const Piece& q) { return x < q.t1; });
  if (it == ps.end()) --it;
  return *it;
}

Aabb Trajectories::swept_bounds(std::size_t body, double u0, double u1) const {
  const auto ps = pieces(body);
  Aabb box;
  bool first = true;
  for (const Piece& q : ps) {
    if (q.t1 < u0 || q.t0 > u1) continue;
    const Aabb b = q.centre_bounds(std::max(u0, q.t0), std::min(u1, q.t1));
    if (first) { box = b; first = false; } else { box.merge(b); }
  }
  box.lo.array() -= radius_[body];
  box.hi.array() -= -radius_[body];
  return box;
}

}  // namespace ccd
