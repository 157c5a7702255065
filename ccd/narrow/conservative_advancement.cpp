#include <ccd/narrow/conservative_advancement.hpp>

#include <ccd/motion/rigid_motion.hpp>
#include <ccd/queries/convex_distance.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ccd {
namespace {

// The advancement from time t (see the header): a lower bound on the time to the first
// contact after t, given that the gap of the posed shapes along the unit direction n
// (from A to B) is at least `gap` > 0 at t. Two bounds on the rate at which that gap
// shrinks, both valid, each giving a time; the larger time is kept:
//  - mu, the pair's point-speed bound (every point of A and B together), and the same
//    along n: n.v_A - n.v_B (extremes at the trajectory pieces' ends, n.v being linear on
//    each) plus |n x omega| R per body (a point at r from the centre moves at
//    omega x r, and n.(omega x r) = r.(n x omega) <= |n x omega| R);
//  - when both bodies keep one spin over the rest of the step, the same with the supports
//    of the posed shapes: r.(n x omega_A) is at most h_A(u_A) + r_A |u_A| at t, u_A =
//    n x omega_A, h_A the support of A's posed core, and grows no faster than
//    |u_A| |omega_A| rho_A, rho_A = max |core point| (the point turns about omega at
//    |omega_A|); same for B with u_B = omega_B x n. The rate is then at most c0 + c1 s
//    after s seconds, and the gap cannot close before c0 s + c1 s^2 / 2 = gap.
// Every dot product, norm and the root are within a few ulps of the magnitudes summed in
// `scale`: rates are rounded up by 64 ulps of it and times down.
// One body over a step [t0, t1]: its trajectory piece and spin piece when one of each
// covers the whole step (then poses need no search), and what the advancement needs of its
// shape, computed once per query.
struct BodyStep {
  const RigidMotion* m = nullptr;
  std::uint32_t body = 0;
  ConvexProxy proxy;
  const Piece* piece = nullptr;              ///< covers [t0, t1], or null
  const RotationPiece* spin = nullptr;       ///< covers [t0, t1], or null
  bool turning = false;                      ///< some spin over the step
  Mat3 still{Mat3::Identity()};              ///< the rotation when not turning
  double omega = 0.0;                        ///< |omega| of `spin`
  Vec3 axis{Vec3::Zero()};                   ///< omega / |omega| of `spin`
  /// max distance of a core point from the spin axis through the centre (rounded up);
  /// max |core point| when the spin changes in the step
  double rho = 0.0;
  double radius = 0.0;                       ///< enclosing radius
  double reach = 0.0;                        ///< max |core point| (rounded up)

  /// A convex shape at rest with the identity pose at the origin (a static polygon).
  explicit BodyStep(const ConvexProxy& fixed) : proxy(fixed) {
    double rho2 = 0.0;
    for (const Vec3& q : proxy.points) rho2 = std::max(rho2, q.squaredNorm());
    rho = std::sqrt(rho2);
    reach = rho * (1.0 + 4.0 * std::numeric_limits<double>::epsilon());
    radius = reach + proxy.radius;
  }

  BodyStep(const RigidMotion& motion, std::uint32_t b, double t0, double t1) : m(&motion), body(b), proxy(motion.proxy(b)) {
    radius = motion.enclosing_radius(b);
    for (const Piece& q : motion.centres().pieces(b))
      if (q.t0 <= t0 && q.t1 >= t1) piece = &q;
    if (!motion.rotations().empty()) {
      int covering = 0;
      for (const RotationPiece& p : motion.rotations().pieces(b)) {
        if (p.t1 < t0 || p.t0 > t1) continue;
        ++covering;
        turning = turning || !p.omega.isZero(0.0);
        spin = &p;
      }
      // The spin shortcuts below need a constant omega over the step (not a free tumble).
      if (covering != 1 || !spin->constant_spin()) spin = nullptr;
    }
    if (!turning) still = motion.pose(b, t0).rotation;
    double rho2 = 0.0;
    for (const Vec3& q : proxy.points) rho2 = std::max(rho2, q.squaredNorm());
    rho = std::sqrt(rho2);
    reach = rho * (1.0 + 4.0 * std::numeric_limits<double>::epsilon());
    if (spin && turning) {
      omega = spin->omega.norm();
      axis = spin->omega / omega;
      // The spin axis in the body frame is fixed while the body turns about it: q0^-1 axis.
      // |q x axis| has no cancellation; the axis itself is within a few ulps.
      const Vec3 body_axis = spin->q0.conjugate() * axis;
      double perp = 0.0;
      for (const Vec3& q : proxy.points) perp = std::max(perp, q.cross(body_axis).norm());
      const double eps = std::numeric_limits<double>::epsilon();
      rho = std::min(rho, perp * (1.0 + 16.0 * eps) + 16.0 * eps * rho);
    }
  }

  Pose pose(double t) const {
    Pose p;
    if (!m) return p;  // at rest
    p.centre = piece ? piece->position(t) : m->centres().position(body, t);
    if (!turning) {
      p.rotation = still;
    } else if (spin) {  // RotationPiece::orientation with |omega| and the axis kept
      const double half = 0.5 * omega * (t - spin->t0);
      const double c = std::cos(half), s = std::sin(half);
      const Quat step(c, s * axis.x(), s * axis.y(), s * axis.z());
      p.rotation = (step * spin->q0).normalized().toRotationMatrix();
    } else {
      p.rotation = m->rotations().orientation(body, t).toRotationMatrix();
    }
    return p;
  }

  /// Bound on the distance between the evaluated and the exact position of any point at t
  /// (metres): the orientation's evaluation error (free spin) times the reach.
  double pose_error(double t) const {
    return !m || spin || !turning ? 0.0 : m->rotations().orientation_error(body, t) * (reach + proxy.radius);
  }

  /// The spin over the step (zero when not turning); only with `spin` or not `turning`.
  Vec3 spin_vector() const { return turning ? spin->omega : Vec3::Zero(); }

  // max |v| of the centre over [u0, u1] (|v| is convex and v linear on each piece).
  double max_speed(double u0, double u1) const {
    if (!m) return 0.0;
    if (piece && piece->a.isZero(0.0)) return piece->v.norm();
    double x = 0.0;
    for (const Piece& q : m->centres().pieces(body)) {
      if (q.t1 < u0 || q.t0 > u1) continue;
      x = std::max({x, q.velocity(std::max(u0, q.t0)).norm(), q.velocity(std::min(u1, q.t1)).norm()});
    }
    return x;
  }

  // Extremes of n.v over [u0, u1] (n.v is linear on each trajectory piece); adds the
  // magnitudes to `scale`.
  void velocity_along(const Vec3& n, double u0, double u1, double& lo, double& hi, double& scale) const {
    auto use = [&](const Vec3& v) {
      const double x = n.dot(v);
      lo = std::min(lo, x);
      hi = std::max(hi, x);
      scale += v.cwiseAbs().sum();
    };
    if (!m) return use(Vec3::Zero());
    if (piece && piece->a.isZero(0.0)) return use(piece->v);
    for (const Piece& q : m->centres().pieces(body)) {
      if (q.t1 < u0 || q.t0 > u1) continue;
      use(q.velocity(std::max(u0, q.t0)));
      use(q.velocity(std::min(u1, q.t1)));
    }
  }
};

// The spin's share of the gap's shrinking rate for one body (sign +1: A, u = n x omega;
// -1: B, u = omega x n): `global` = max |u| R over the spins in [u0, u1]; when one spin
// covers the step, c0 = h(u) + r |u| at the pose and c1 = |u| |omega| rho.
struct SpinTerm {
  bool single = false;
  double c0 = 0.0, c1 = 0.0, global = 0.0, scale = 0.0;
};

SpinTerm spin_term(const BodyStep& x, const Pose& pose, const Vec3& n, double sign, double u0, double u1) {
  SpinTerm s;
  if (!x.turning) {
    s.single = true;
    return s;
  }
  if (!x.spin) {
    for (const RotationPiece& p : x.m->rotations().pieces(x.body))
      if (p.t1 >= u0 && p.t0 <= u1)
        s.global = std::max(s.global, p.constant_spin() ? n.cross(p.omega).norm() : p.max_rate());
    s.global *= x.radius;
    s.scale = s.global;
    return s;
  }
  s.single = true;
  const Vec3 u = sign * n.cross(x.spin->omega);
  const double un = u.norm();
  s.global = un * x.radius;
  s.scale = s.global;
  if (un == 0.0) return s;
  const Vec3 local = pose.rotation.transpose() * u;
  s.c0 = x.proxy.points[x.proxy.support_index(local)].dot(local) + x.proxy.radius * un;
  s.c1 = un * x.omega * x.rho;
  s.scale += un * (x.rho + x.proxy.radius);
  return s;
}

// The first s >= 0 with c0 s + c1 s^2 / 2 = gap (c1 >= 0), rounded down; inf if none.
double time_to_close(double c0, double c1, double gap) {
  const double eps = std::numeric_limits<double>::epsilon();
  if (c1 == 0.0) return c0 > 0.0 ? gap / c0 * (1.0 - 4.0 * eps) : std::numeric_limits<double>::infinity();
  const double root = std::sqrt(c0 * c0 + 2.0 * c1 * gap);
  return (c0 >= 0.0 ? 2.0 * gap / (c0 + root) : (root - c0) / c1) * (1.0 - 16.0 * eps);
}

// The relative bound, in the body frame of `f` (both bodies keeping one spin over the
// rest of the step): there f's core is still, and a point r (body frame of `o`, posed
// offset R_o r) of o's core moves at
//   |v_o - v_f + (omega_o - omega_f) x R_o r - omega_f x (c_o - c_f)|
//     <= V + |omega_o - omega_f| R_o + |omega_f x dc(t)| + |omega_f| V s
// after s seconds, V = max |v_f| + max |v_o| over the step, dc = c_o - c_f (which moves
// by at most V s). The distance of the cores (the gap plus the radii) is 1-Lipschitz in
// the displacement of o's core, so the gap cannot close before c0 s + c1 s^2 / 2 = gap
// with c0 = V + |omega_o - omega_f| R_o + |omega_f x dc(t)|, c1 = |omega_f| V. For a body
// spinning against a small one this is the speed of the small one's points about the
// spin axis, not of the spinning body's far end.
double relative_advance(const BodyStep& f, const BodyStep& o, const Pose& pf, const Pose& po, double gap, double u0,
                        double u1) {
  const double eps = std::numeric_limits<double>::epsilon();
  const Vec3 wf = f.spin_vector(), wo = o.spin_vector();
  const double speed = f.max_speed(u0, u1) + o.max_speed(u0, u1);
  const Vec3 dc = po.centre - pf.centre;
  const double wfn = wf.norm();
  const double c0 = speed + (wo - wf).norm() * o.reach + wf.cross(dc).norm();
  const double scale = speed + (wo.norm() + wfn) * o.reach + wfn * dc.norm();
  return time_to_close(c0 + 64.0 * eps * scale, wfn * speed * (1.0 + 64.0 * eps), gap);
}

double advance(const BodyStep& a, const BodyStep& b, const Pose& pa, const Pose& pb, const Vec3& n, double gap,
               double mu, double u0, double u1) {
  const double inf = std::numeric_limits<double>::infinity();
  const double eps = std::numeric_limits<double>::epsilon();
  double a_lo = inf, a_hi = -inf, b_lo = inf, b_hi = -inf, scale = 0.0;
  a.velocity_along(n, u0, u1, a_lo, a_hi, scale);
  b.velocity_along(n, u0, u1, b_lo, b_hi, scale);
  const SpinTerm sa = spin_term(a, pa, n, 1.0, u0, u1), sb = spin_term(b, pb, n, -1.0, u0, u1);
  const double linear = a_hi - b_lo;
  scale += sa.scale + sb.scale;
  const double allowance = 64.0 * eps * scale;
  auto time_at_rate = [&](double rate) { return rate > 0.0 ? gap / rate * (1.0 - 4.0 * eps) : inf; };
  double best = time_at_rate(std::min(mu, linear + sa.global + sb.global + allowance));
  if (sa.single && sb.single) {
    const double c0 = linear + sa.c0 + sb.c0 + allowance;
    const double c1 = (sa.c1 + sb.c1) * (1.0 + 64.0 * eps);
    double s2 = 0.0;
    if (c1 == 0.0) {
      s2 = time_at_rate(c0);
    } else {
      const double root = std::sqrt(c0 * c0 + 2.0 * c1 * gap);
      s2 = (c0 >= 0.0 ? 2.0 * gap / (c0 + root) : (root - c0) / c1) * (1.0 - 16.0 * eps);
    }
    best = std::max(best, s2);
    best = std::max({best, relative_advance(a, b, pa, pb, gap, u0, u1), relative_advance(b, a, pb, pa, gap, u0, u1)});
  }
  return best;
}

}  // namespace

ContactResult conservative_advancement(const NarrowInput& in, std::uint32_t a, std::uint32_t b) {
  return conservative_advancement(in, a, b, AdvancementOptions{});
}

namespace {

// The advancement of sa against sb over the step (see the header); mu bounds the pair's
// point speeds over the step.
ContactResult advance_pair(const NarrowInput& in, const BodyStep& sa, const BodyStep& sb, double mu,
                           const AdvancementOptions& options, int* iterations) {
  const double inf = std::numeric_limits<double>::infinity();
  const double tol = options.tolerance;
  ContactResult r;
  Pose pa = sa.pose(in.t0), pb = sb.pose(in.t0);
  DistanceOptions dopt;
  dopt.tolerance = 0.25 * tol;
  ConvexDistance d = convex_distance(sa.proxy, {pa.centre, pa.rotation}, sb.proxy, {pb.centre, pb.rotation}, dopt);
  if (iterations) *iterations = 1;
  if (d.status == ConvexDistance::Status::Failed) {
    r.status = QueryStatus::Failed;
    return r;
  }
  if (in.sample || d.status == ConvexDistance::Status::Overlapping) {
    if (d.status == ConvexDistance::Status::Separated) return r;  // Miss
    r.status = QueryStatus::Overlapping;
    r.toi = in.t0;
    r.signed_distance = d.upper;
    return r;
  }
  double t = in.t0;
  for (int it = 1;; ++it) {
    if (iterations) *iterations = it;
    if (d.status == ConvexDistance::Status::Failed) {
      r.status = QueryStatus::Failed;
      return r;
    }
    // A free tumble's orientation is evaluated within a stated error: the certified gap
    // shrinks by what that error moves the two bodies' points (0 for constant spins).
    const double gap = d.lower - (sa.pose_error(t) + sb.pose_error(t));
    if (!(gap > tol) || it >= options.max_iterations) break;
    if (mu == 0.0) return r;  // nothing moves and the pair is apart: Miss
    // The gap along d.direction is at least `gap` now: no contact before t + step.
    const double step = advance(sa, sb, pa, pb, d.direction, gap, mu, t, in.t1);
    const double next = t + step;
    if (!(next <= in.t1)) return r;  // Miss: no contact in [t0, t1]
    t = next;
    pa = sa.pose(t);
    pb = sb.pose(t);
    dopt.start_direction = d.direction;  // warm start from the last separating direction
    d = convex_distance(sa.proxy, {pa.centre, pa.rotation}, sb.proxy, {pb.centre, pb.rotation}, dopt);
  }
  r.status = QueryStatus::Hit;
  r.toi = t;
  r.signed_distance = d.upper;
  r.toi_error = inf;
  if (d.status == ConvexDistance::Status::Overlapping) {
    r.toi_error = 0.0;
    return r;
  }
  if (!(d.lower <= tol)) return r;  // iteration limit: conservative, unbracketed
  auto overlapping_at = [&](double x) {
    const Pose qa = sa.pose(x), qb = sb.pose(x);
    return convex_distance(sa.proxy, {qa.centre, qa.rotation}, sb.proxy, {qb.centre, qb.rotation}, dopt).status ==
           ConvexDistance::Status::Overlapping;
  };
  // The bracket's far end: the first probe with a certified overlap, then halved.
  double h = mu > 0.0 ? tol / mu : in.t1 - t;
  double hi = inf;
  while (t + h <= in.t1 && h > 0.0) {
    if (overlapping_at(t + h)) {
      hi = t + h;
      break;
    }
    h *= 2.0;
  }
  if (hi == inf && t < in.t1 && overlapping_at(in.t1)) hi = in.t1;
  if (hi == inf) return r;  // a near miss within the tolerance (or a contact not certified)
  for (int k = 0; k < 60 && hi > t; ++k) {
    const double mid = t + 0.5 * (hi - t);
    if (mid <= t || mid >= hi) break;
    if (!overlapping_at(mid)) break;
    hi = mid;
  }
  r.toi_error = hi - t;
  return r;
}

}  // namespace

ContactResult conservative_advancement(const NarrowInput& in, std::uint32_t a, std::uint32_t b,
                                       const AdvancementOptions& options, int* iterations) {
  const RigidMotion& m = *in.motion;
  const BodyStep sa(m, a, in.t0, in.t1), sb(m, b, in.t0, in.t1);
  const double mu = m.max_point_speed(a, in.t0, in.t1) + m.max_point_speed(b, in.t0, in.t1);
  return advance_pair(in, sa, sb, mu, options, iterations);
}

ContactResult conservative_advancement_fixed(const NarrowInput& in, std::uint32_t body, const ConvexProxy& fixed,
                                             const AdvancementOptions& options, int* iterations) {
  const RigidMotion& m = *in.motion;
  const BodyStep sa(m, body, in.t0, in.t1), sb(fixed);
  return advance_pair(in, sa, sb, m.max_point_speed(body, in.t0, in.t1), options, iterations);
}

}  // namespace ccd
