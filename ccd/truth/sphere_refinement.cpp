#include <ccd/truth/sphere_refinement.hpp>

#include <ccd/queries/sphere_box_distance.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ccd {
namespace {

constexpr double kU = 0.5 * std::numeric_limits<double>::epsilon();

// max |centre velocity| of `body` over [u0, u1] (at the ends of each piece inside, where
// |v + a s| is largest), as RigidMotion::max_point_speed without the spin.
double max_centre_speed(const RigidMotion& m, std::uint32_t body, double u0, double u1) {
  double v = 0.0;
  for (const Piece& q : m.centres().pieces(body)) {
    if (q.t1 < u0 || q.t0 > u1) continue;
    v = std::max({v, q.velocity(std::max(u0, q.t0)).norm(), q.velocity(std::min(u1, q.t1)).norm()});
  }
  return v;
}

// An upper bound on |w x d| from the computed cross product: each component's rounding
// is at most 2u of its two products (0 where they are exact zeros).
double cross_bound(const Vec3& w, const Vec3& d) {
  const Vec3 c = w.cross(d);
  Vec3 e;
  e.x() = std::fabs(c.x()) + 2.0 * kU * (std::fabs(w.y() * d.z()) + std::fabs(w.z() * d.y()));
  e.y() = std::fabs(c.y()) + 2.0 * kU * (std::fabs(w.z() * d.x()) + std::fabs(w.x() * d.z()));
  e.z() = std::fabs(c.z()) + 2.0 * kU * (std::fabs(w.x() * d.y()) + std::fabs(w.y() * d.x()));
  return e.norm() * (1.0 + 4.0 * kU);
}

struct PairView {
  const RigidMotion& m;
  std::uint32_t s, h;
  const Piece* qs;
  const Piece* qh;
  Vec3 centre_s(double t) const { return qs ? qs->position(t) : m.centres().position(s, t); }
  Pose pose_h(double t) const {
    Pose p = m.pose(h, t);
    if (qh) p.centre = qh->position(t);
    return p;
  }

  // The bound of the header on [lo, hi], or infinity where it does not apply (a free spin).
  double lipschitz(double lo, double hi) const {
    const double inf = std::numeric_limits<double>::infinity();
    const double V = (max_centre_speed(m, s, lo, hi) + max_centre_speed(m, h, lo, hi)) * (1.0 + 8.0 * kU);
    double W = 0.0;
    if (!m.rotations().empty()) {
      const double mid = lo + 0.5 * (hi - lo);
      const double half = std::max(mid - lo, hi - mid);
      const Vec3 d = centre_s(mid) - pose_h(mid).centre;
      for (const RotationPiece& p : m.rotations().pieces(h)) {
        if (p.t1 < lo || p.t0 > hi) continue;
        if (!p.constant_spin()) return inf;
        const double w = p.omega.norm() * (1.0 + 4.0 * kU);
        W = std::max(W, (cross_bound(p.omega, d) + w * V * half) * (1.0 + 4.0 * kU));
      }
    }
    return (V + W) * (1.0 + 4.0 * kU);
  }

  BracketProbe probe(double t, const DistanceOptions& o) const {
    const Pose ph = pose_h(t);
    const ConvexProxy ball = m.proxy(s);
    const double slack = m.pose_error(s, t) + m.pose_error(h, t);
    const Vec3 cs = centre_s(t);
    if (m.kind(h) == ShapeKind::Box && ball.points.size() == 1 && ball.points[0] == Vec3::Zero()) {
      const ConvexProxy box = m.proxy(h);
      const Vec3 half = box.points.back().cwiseAbs();  // the corner (+x, +y, +z)
      return {sphere_box_distance(cs, ball.radius, {ph.centre, ph.rotation}, half), slack};
    }
    const Pose ps = m.pose(s, t);
    return {convex_distance(ball, {cs, ps.rotation}, m.proxy(h), {ph.centre, ph.rotation}, o), slack};
  }
};

}  // namespace

std::size_t refine_sphere_pair(const RigidMotion& m, std::uint32_t s, std::uint32_t h, double lo, double hi,
                               double tol, std::size_t max_evaluations, const Piece* qs, const Piece* qh,
                               std::vector<BracketEvent>& out) {
  if (!(hi >= lo)) return 0;
  const PairView view{m, s, h, qs, qh};
  const double lipschitz = m.max_point_speed(s, lo, hi) + m.max_point_speed(h, lo, hi);
  BracketSearch search([&view](double t, const DistanceOptions& o) { return view.probe(t, o); }, lipschitz, tol, 0.0,
                       max_evaluations);
  search.set_local_lipschitz([&view](double a, double b) { return view.lipschitz(a, b); });
  search.run(lo, hi);
  search.events(m.centres().horizon(), out);
  return search.evaluations();
}

}  // namespace ccd
