#include <ccd/motion/trajectory.hpp>
#include <ccd/geometry/numeric_limits.hpp>

#include <ccd/motion/piece_walk.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace ccd {
namespace {

// First s in (0, limit] with c + v s + a s^2/2 == 0 (c = x - wall, formed exactly by the
// caller) while moving towards the wall (dir = +1: the wall is above, the velocity at s
// must be > 0; dir = -1: below).
double first_wall_hit(double c, double v, double a, int dir, double limit) {
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

DdVec3 exact_position(const Piece& q, const PieceLow& low, double t) {
  const Dd s = two_sum(t, -q.t0);
  const Dd half_s2 = (s * s) * 0.5;
  DdVec3 r;
  for (int k = 0; k < 3; ++k)
    r[k] = Dd(q.p[k], low.p[k]) + Dd(q.v[k], low.v[k]) * s + Dd(q.a[k], low.a[k]) * half_s2;
  return r;
}

DdVec3 exact_velocity(const Piece& q, const PieceLow& low, double t) {
  const Dd s = two_sum(t, -q.t0);
  DdVec3 r;
  for (int k = 0; k < 3; ++k) r[k] = Dd(q.v[k], low.v[k]) + Dd(q.a[k], low.a[k]) * s;
  return r;
}

namespace {

// Height (fraction of the box extent) below which a body pushed into a wall rests on it.
constexpr double kRestFraction = 0x1p-30;

// The body's exact state at the start of a piece.
struct State {
  double t = 0.0;
  DdVec3 p, v, a;
};

// Exact time s* (relative to the state's t) at which coordinate k reaches `wall`, given
// the double approximation s0 of it: one Newton step evaluated in double-double.
Dd refine_wall_time(const State& st, int k, const Dd& wall, double s0) {
  const Dd s(s0);
  const Dd r = st.p[k] + st.v[k] * s + st.a[k] * ((s * s) * 0.5) - wall;
  const double slope = (st.v[k] + st.a[k] * s).value();
  if (slope == 0.0) return s;
  return s - Dd(r.value() / slope);
}

}  // namespace

Trajectories::Trajectories(const Scene& scene, const TrajectoryOptions& options)
    : horizon_(scene.horizon), periodic_(PeriodicBox::of(scene)) {
  const std::size_t n = scene.bodies.size();
  radius_.reserve(n);
  first_.reserve(n + 1);
  pieces_.reserve(n);
  lows_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Body& b = scene.bodies[i];
    radius_.push_back(b.radius);
    const std::size_t start = pieces_.size();
    // Wall planes min + r and max - r, exact.
    DdVec3 lo_wall, hi_wall;
    Vec3 rest_height = Vec3::Zero();
    if (scene.box) {
      for (int k = 0; k < 3; ++k) {
        if (scene.box->wraps(k)) {  // the faces themselves: the centre crossing one wraps
          lo_wall[k] = Dd(scene.box->min[k]);
          hi_wall[k] = Dd(scene.box->max[k]);
          continue;
        }
        lo_wall[k] = two_sum(scene.box->min[k], b.radius);
        hi_wall[k] = two_sum(scene.box->max[k], -b.radius);
        rest_height[k] = kRestFraction * (scene.box->max[k] - scene.box->min[k]);
      }
    }
    auto own_plus_gravity = [&](const Vec3& own) {
      DdVec3 a;
      for (int k = 0; k < 3; ++k) a[k] = two_sum(own[k], scene.gravity[k]);
      return a;
    };
    State st{0.0, DdVec3(b.position), DdVec3(b.velocity), own_plus_gravity(b.acceleration)};
    std::size_t next_change = 0;    // next acceleration change
    std::size_t next_jump = 0;      // next velocity change
    double carried_window = 0.0, carried_error = 0.0;  // from the reflection that began this piece
    double pos_error = 0.0, vel_error = 0.0;           // double-double rounding carried so far
    while (true) {
      // The next known break: an acceleration change, a velocity change (both at once
      // when their times are equal), or the horizon.
      const double t_acc = next_change < b.acceleration_changes.size() ? b.acceleration_changes[next_change].t : horizon_;
      const double t_jump = next_jump < b.velocity_changes.size() ? b.velocity_changes[next_jump].t : horizon_;
      const double t_change = std::min(t_acc, t_jump);
      DdVec3 a = st.a;
      int wall_axis = -1;
      int wall_dir = 0;
      double s_end = t_change - st.t;
      if (scene.box) {
        for (int k = 0; k < 3; ++k) {
          const double ak = a[k].value();
          const double vk = st.v[k].value();
          if (scene.box->wraps(k)) {
            // On or beyond a face while moving (or, at rest, accelerating) out through it:
            // re-enter at the opposite face at once.
            const double above = (st.p[k] - hi_wall[k]).value(), below = (st.p[k] - lo_wall[k]).value();
            if (above >= 0.0 && (vk > 0.0 || (vk == 0.0 && ak > 0.0))) st.p[k] = st.p[k] - periodic_->shift(k, 1);
            else if (below <= 0.0 && (vk < 0.0 || (vk == 0.0 && ak < 0.0))) st.p[k] = st.p[k] + periodic_->shift(k, 1);
            continue;
          }
          // Resting rule: pushed into a wall and unable to rise more than rest_height.
          for (int dir : {-1, +1}) {
            const Dd& wall = dir < 0 ? lo_wall[k] : hi_wall[k];
            if (!(dir * ak > 0.0)) continue;
            const double h = -dir * (st.p[k] - wall).value();  // height above the plane
            if (h + vk * vk / (2.0 * std::fabs(ak)) <= rest_height[k]) {
              st.p[k] = wall;
              st.v[k] = Dd(0.0);
              a[k] = Dd(0.0);
            }
          }
          // Starting on or beyond a wall plane while moving into it: reflect at once.
          const double v_now = st.v[k].value();
          if (((st.p[k] - lo_wall[k]).value() <= 0.0 && v_now < 0.0) ||
              ((st.p[k] - hi_wall[k]).value() >= 0.0 && v_now > 0.0))
            st.v[k] = -st.v[k];
        }
        for (int k = 0; k < 3; ++k) {
          const double vk = st.v[k].value(), ak = a[k].value();
          const double s_hi = first_wall_hit((st.p[k] - hi_wall[k]).value(), vk, ak, +1, s_end);
          if (s_hi < s_end) { s_end = s_hi; wall_axis = k; wall_dir = +1; }
          const double s_lo = first_wall_hit((st.p[k] - lo_wall[k]).value(), vk, ak, -1, s_end);
          if (s_lo < s_end) { s_end = s_lo; wall_axis = k; wall_dir = -1; }
        }
      }
      State here = st;
      here.a = a;
      double t_next = t_change;
      Dd t_star;  // exact reflection time (absolute)
      if (wall_axis >= 0) {
        const Dd& wall = wall_dir > 0 ? hi_wall[wall_axis] : lo_wall[wall_axis];
        const Dd s_star = refine_wall_time(here, wall_axis, wall, s_end);
        t_star = two_sum(st.t, s_star.hi) + Dd(s_star.lo);
        t_next = t_star.value();
        if (!(t_next > st.t)) t_next = std::nextafter(st.t, kInf);
        if (t_next >= t_change) {  // the exact hit lies at or after the change: the change first
          t_next = t_change;
          wall_axis = -1;
        }
      }
      Piece piece{st.t, t_next, here.p.hi(), here.v.hi(), here.a.hi()};
      PieceLow low{here.p.lo(), here.v.lo(), here.a.lo(), carried_window, carried_error, pos_error, vel_error};
      pieces_.push_back(piece);
      lows_.push_back(low);
      if (pieces_.size() - start > options.max_pieces_per_body)
        throw TooManyPieces(i, options.max_pieces_per_body);
      // The next piece starts from the body's own acceleration: the resting rule is checked afresh.
      State next{t_next, exact_position(piece, low, t_next), exact_velocity(piece, low, t_next), st.a};
      carried_window = 0.0;
      carried_error = 0.0;
      {  // Rounding of evaluating the piece at its end (and of the reflection below).
        constexpr double kU2 = kUnitRoundoff * kUnitRoundoff;
        const double S = t_next - piece.t0;
        double vmag = 0.0, pmag = 0.0;
        for (int k = 0; k < 3; ++k) {
          vmag = std::max(vmag, std::fabs(piece.v[k]) + std::fabs(piece.a[k]) * S);
          pmag = std::max(pmag, std::fabs(piece.p[k]) + std::fabs(piece.v[k]) * S + 0.5 * std::fabs(piece.a[k]) * S * S);
        }
        pos_error += vel_error * S + 64.0 * kU2 * (pmag + vmag * S);
        vel_error += 64.0 * kU2 * vmag;
      }
      if (wall_axis >= 0 && scene.box->wraps(wall_axis)) {
        // Wrap: the same motion, its position moved by one period (exact); no model error.
        const int k = wall_axis;
        next.p[k] = wall_dir > 0 ? next.p[k] - periodic_->shift(k, 1) : next.p[k] + periodic_->shift(k, 1);
      } else if (wall_axis >= 0) {
        // The branch after the reflection, extrapolated from t* back to the double t_next.
        const int k = wall_axis;
        const Dd& wall = wall_dir > 0 ? hi_wall[k] : lo_wall[k];
        const double delta = (Dd(t_next) - t_star).value();  // t_next - t*
        const Dd v_out = -exact_velocity(piece, low, t_star.hi)[k] - a[k] * Dd(t_star.lo);
        next.p[k] = wall + v_out * delta + a[k] * (0.5 * delta * delta);
        next.v[k] = v_out + a[k] * delta;
        if (delta != 0.0) {
          carried_window = 2.0 * std::fabs(delta);
          carried_error = 2.0 * std::fabs(v_out.value()) * std::fabs(delta) + std::fabs(a[k].value()) * delta * delta;
          lows_.back().edge_window = std::max(lows_.back().edge_window, carried_window);
          lows_.back().edge_error = std::max(lows_.back().edge_error, carried_error);
        }
      } else if (t_change < horizon_) {
        if (next_change < b.acceleration_changes.size() && t_acc == t_change) {
          next.a = own_plus_gravity(b.acceleration_changes[next_change].acceleration);
          ++next_change;
        }
        if (next_jump < b.velocity_changes.size() && t_jump == t_change) {
          // The velocity jumps; the position stays what the piece reached (exact, no
          // rounding of its own: the new velocity is the scene's data).
          next.v = DdVec3(b.velocity_changes[next_jump].velocity);
          ++next_jump;
        }
      } else {
        break;  // reached the horizon
      }
      st = next;
      if (st.t >= horizon_) break;
    }
    first_.push_back(static_cast<std::uint32_t>(pieces_.size()));
  }
}

void shift_piece(Piece& q, PieceLow& low, const DdVec3& shift) {
  for (int k = 0; k < 3; ++k) {
    const Dd p = Dd(q.p[k], low.p[k]) + shift[k];
    q.p[k] = p.hi;
    low.p[k] = p.lo;
  }
}

DdVec3 image_offset(const PeriodicBox& box, const ImageShift& s) {
  DdVec3 r;
  for (int k = 0; k < 3; ++k) r[k] = box.shift(k, s[static_cast<std::size_t>(k)]);
  return r;
}

void Trajectories::reset(double horizon, const std::optional<PeriodicBox>& periodic) {
  horizon_ = horizon;
  periodic_ = periodic;
  radius_.clear();
  pieces_.clear();
  lows_.clear();
  first_.assign(1, 0);
}

void Trajectories::append_body(double radius, std::span<const Piece> pieces, std::span<const PieceLow> lows,
                               std::span<const DdVec3> shifts) {
  radius_.push_back(radius);
  for (std::size_t j = 0; j < pieces.size(); ++j) {
    Piece q = pieces[j];
    PieceLow l = lows[j];
    shift_piece(q, l, shifts[j]);
    pieces_.push_back(q);
    lows_.push_back(l);
  }
  first_.push_back(static_cast<std::uint32_t>(pieces_.size()));
}

std::size_t Trajectories::piece_index(std::size_t body, double t) const {
  const auto ps = pieces(body);
  // First piece whose end is > t; the last piece if none.
  auto it = std::upper_bound(ps.begin(), ps.end(), t, [](double x, const Piece& q) { return x < q.t1; });
  if (it == ps.end()) --it;
  return static_cast<std::size_t>(it - ps.begin());
}

const Piece& Trajectories::piece_at(std::size_t body, double t) const { return pieces(body)[piece_index(body, t)]; }

Aabb Trajectories::swept_bounds(std::size_t body, double u0, double u1) const {
  return swept_bounds_from(*this, body, 0, u0, u1);  // the walk from the first piece
}

}  // namespace ccd
