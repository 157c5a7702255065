#pragma once
// Shared generators for the bound tests: random motions valid under each knowledge, and
// constructed pairs with a known contact inside the step (constructive ground truth).
#include <bounds/bound.hpp>
#include <bounds/registry.hpp>
#include <ccd/motion/trajectory.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace ccd::test {

inline Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Vec3 x;
  do { x = Vec3(g(rng), g(rng), g(rng)); } while (x.squaredNorm() < 1e-12);
  return x.normalized();
}

/// A random vector of length <= len (uniform direction, length uniform in [0, len]).
inline Vec3 random_vec(std::mt19937_64& rng, double len) {
  return random_unit(rng) * std::uniform_real_distribution<double>(0.0, len)(rng);
}

/// One step of a scene: the exact motion and what each knowledge is given.
struct Step {
  Scene scene;
  Trajectories traj;
  /// The scene's motion over `traj`, rebuilt by each context() (a copied Step gets its own).
  mutable RigidMotion motion;
  std::vector<BodyState> start;
  double t0 = 0.0;
  double t1 = 0.0;
  double A = 0.0;

  void finish(double step_t0, double step_t1) {
    t0 = step_t0;
    t1 = step_t1;
    traj = Trajectories(scene);
    A = scene.max_acceleration();
    start.resize(scene.bodies.size());
    for (std::size_t i = 0; i < start.size(); ++i)
      start[i] = {traj.position(i, t0), traj.velocity(i, t0), traj.radius(i)};
  }
  StepContext context(Knowledge k) const {
    StepContext c;
    c.t0 = t0;
    c.t1 = k == Knowledge::Instant ? t0 : t1;
    c.start = start;
    c.exact = k == Knowledge::Exact ? &traj : nullptr;
    c.acceleration_bound = A;
    c.walls = scene.box;
    motion = RigidMotion(scene, traj);
    c.motion = &motion;
    return c;
  }
};

/// A gas of n bodies in the box [0, 10]^3 (or without walls), moving over [0, t1] with
/// accelerations |own + gravity| <= A_max that change `changes` times at random instants;
/// the step is [t0, t1].
inline Step random_gas(std::mt19937_64& rng, std::size_t n, double t0, double t1, double A_max, bool walls,
                       bool gravity, int changes) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Step st;
  Scene& s = st.scene;
  s.horizon = t1;
  if (walls) s.box = WallBox{Vec3(0, 0, 0), Vec3(10, 10, 10)};
  const double half = gravity ? 0.5 * A_max : 0.0;
  if (gravity) s.gravity = Vec3(0, -half, 0);
  for (std::size_t i = 0; i < n; ++i) {
    Body b;
    b.radius = 0.05 + 0.3 * u(rng);
    // Speeds up to 40 units/s: several wall reflections in long steps.
    b.velocity = random_vec(rng, u(rng) < 0.5 ? 4.0 : 40.0);
    b.position = Vec3(b.radius + (10 - 2 * b.radius) * u(rng), b.radius + (10 - 2 * b.radius) * u(rng),
                      b.radius + (10 - 2 * b.radius) * u(rng));
    if (u(rng) < 0.1) {  // start touching a wall
      const int k = static_cast<int>(3 * u(rng)) % 3;
      b.position[k] = u(rng) < 0.5 ? b.radius : 10 - b.radius;
    }
    b.acceleration = random_vec(rng, A_max - half);
    double t = 0.0;
    for (int c = 0; c < changes; ++c) {
      t += (t1 - t) * u(rng);  // strictly increasing inside (0, t1) almost surely
      if (!(t > 0.0 && t < t1) || (!b.acceleration_changes.empty() && t <= b.acceleration_changes.back().t)) break;
      b.acceleration_changes.push_back({t, random_vec(rng, A_max - half)});
    }
    s.bodies.push_back(b);
  }
  st.finish(t0, t1);
  return st;
}

/// Pairs (2i, 2i+1) of a constructed step with a contact at tc[i] in [t0, t1].
struct ContactBatch {
  Step step;
  std::vector<double> tc;
  std::vector<std::string> kind;
};

/// Backs out the state at 0 of a body that is at x with velocity v at time tc, under
/// piecewise-constant accelerations acc[k] on [tau[k], tau[k+1]] (tau[0] = 0).
inline Body back_out(double radius, const Vec3& x, const Vec3& v, double tc, const std::vector<double>& tau,
                     const std::vector<Vec3>& acc) {
  Vec3 p = x;
  Vec3 w = v;
  double t = tc;
  for (int k = static_cast<int>(tau.size()) - 1; k >= 0; --k) {
    if (tau[k] >= t) continue;
    const double d = t - tau[k];
    p = p - w * d + acc[k] * (0.5 * d * d);
    w = w - acc[k] * d;
    t = tau[k];
  }
  Body b;
  b.radius = radius;
  b.position = p;
  b.velocity = w;
  b.acceleration = acc[0];
  for (std::size_t k = 1; k < tau.size(); ++k) b.acceleration_changes.push_back({tau[k], acc[k]});
  return b;
}

/// n constructed pairs touching or overlapping at tc in [0, h], no walls. Kinds: generic,
/// tangent at the step's end, grazing, parallel motion, coincident start, zero velocity,
/// far from the origin (~1e6). Accelerations |a| <= A_max change twice in the step.
inline ContactBatch contact_batch(std::mt19937_64& rng, std::size_t n, double h, double A_max) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  ContactBatch cb;
  Scene& s = cb.step.scene;
  s.horizon = h;
  static const char* kinds[] = {"generic", "tangent_at_end", "grazing", "parallel", "coincident_start",
                                "zero_velocity", "far"};
  for (std::size_t i = 0; i < n; ++i) {
    const int kind = u(rng) < 0.4 ? 0 : 1 + static_cast<int>(6 * u(rng)) % 6;
    const double ra = 0.01 + u(rng), rb = 0.01 + u(rng);
    const double R = ra + rb;
    double tc = h * u(rng);
    const Vec3 origin = kind == 6 ? Vec3(1e6, -1e6, 1e6) + random_vec(rng, 10.0) : random_vec(rng, 10.0);
    const Vec3 n_ab = random_unit(rng);
    double overlap = u(rng) < 0.5 ? 1.0 : u(rng);  // distance at tc = R * overlap
    Vec3 va = random_vec(rng, 20.0), vb = random_vec(rng, 20.0);
    std::vector<double> tau{0.0, h * u(rng), h * u(rng)};
    if (tau[1] > tau[2]) std::swap(tau[1], tau[2]);
    if (!(tau[1] > 0.0 && tau[2] > tau[1])) tau.resize(1);
    std::vector<Vec3> acc_a, acc_b;
    for (std::size_t k = 0; k < tau.size(); ++k) {
      acc_a.push_back(random_vec(rng, A_max));
      acc_b.push_back(random_vec(rng, A_max));
    }
    switch (kind) {
      case 1: tc = h; overlap = 1.0; break;                 // tangent exactly at t1
      case 2: {                                            // grazing: relative velocity tangent at tc
        overlap = 1.0;
        const Vec3 rel = va - vb;
        vb = vb + (rel.dot(n_ab)) * n_ab;  // va - vb now perpendicular to n_ab
        for (std::size_t k = 0; k < tau.size(); ++k) acc_b[k] = acc_a[k];
        break;
      }
      case 3:                                              // parallel: same motion, touching
        overlap = 1.0;
        vb = va;
        acc_b = acc_a;
        break;
      case 4: tc = 0.0; overlap = u(rng) < 0.5 ? 0.0 : overlap; break;  // coincident start
      case 5:                                              // zero velocity, zero acceleration
        va = vb = Vec3::Zero();
        for (auto& a : acc_a) a.setZero();
        for (auto& a : acc_b) a.setZero();
        break;
      default: break;
    }
    const Vec3 xa = origin;
    const Vec3 xb = origin + n_ab * (R * overlap);
    s.bodies.push_back(back_out(ra, xa, va, tc, tau, acc_a));
    s.bodies.push_back(back_out(rb, xb, vb, tc, tau, acc_b));
    cb.tc.push_back(tc);
    cb.kind.push_back(kinds[kind]);
  }
  cb.step.finish(0.0, h);
  return cb;
}

/// n constructed pairs in the box [0, 10]^3 where body 2i bounces off a wall (x = 10 or
/// y = 0) before touching body 2i+1 at tc. Pairs whose second body would itself reflect
/// before tc are dropped (constructed without walls).
inline ContactBatch wall_contact_batch(std::mt19937_64& rng, std::size_t n, double h, double A_max) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // First build the bouncing bodies, to read their positions after the bounce.
  Scene first;
  first.horizon = h;
  first.box = WallBox{Vec3(0, 0, 0), Vec3(10, 10, 10)};
  std::vector<double> tcs;
  for (std::size_t i = 0; i < n; ++i) {
    Body a;
    a.radius = 0.05 + 0.5 * u(rng);
    const double tw = h * (0.05 + 0.6 * u(rng));  // reach the wall at about tw
    const double speed = 1.0 + 30.0 * u(rng);
    a.position = Vec3(5, 5, 5) + random_vec(rng, 1.0);
    a.velocity = random_vec(rng, 3.0);
    if (u(rng) < 0.5) {
      a.position.x() = 10 - a.radius - speed * tw;
      a.velocity.x() = speed;
    } else {
      a.position.y() = a.radius + speed * tw;
      a.velocity.y() = -speed;
    }
    a.position = a.position.cwiseMax(Vec3::Constant(a.radius)).cwiseMin(Vec3::Constant(10 - a.radius));
    a.acceleration = random_vec(rng, A_max);
    first.bodies.push_back(a);
    tcs.push_back(u(rng) < 0.2 ? tw * (1 + 1e-9) : tw + (h - tw) * u(rng));  // right after, or later
  }
  const Trajectories ta(first);
  ContactBatch cb;
  Scene& s = cb.step.scene;
  s.horizon = h;
  s.box = first.box;
  for (std::size_t i = 0; i < n; ++i) {
    const double tc = std::min(tcs[i], h);
    const Vec3 xa = ta.position(i, tc);
    const double rb = 0.05 + 0.5 * u(rng);
    const double R = first.bodies[i].radius + rb;
    // Towards the box's centre, so the second body stays clear of the walls.
    const Vec3 dir = ((Vec3(5, 5, 5) - xa).normalized() + 0.5 * random_unit(rng)).normalized();
    const Vec3 xb = xa + dir * (R * (u(rng) < 0.5 ? 1.0 : u(rng)));
    const Body b = back_out(rb, xb, random_vec(rng, 3.0), tc, {0.0}, {random_vec(rng, A_max)});
    Scene probe;
    probe.horizon = h;
    probe.box = s.box;
    probe.bodies.push_back(b);
    bool inside = true;
    for (int k = 0; k < 3; ++k) inside = inside && b.position[k] > rb && b.position[k] < 10 - rb;
    if (!inside) continue;
    const Trajectories tb(probe);
    if (tb.pieces(0)[0].t1 < tc) continue;  // b would reflect before tc: not what was built
    s.bodies.push_back(first.bodies[i]);
    s.bodies.push_back(b);
    cb.tc.push_back(tc);
    cb.kind.emplace_back(std::string_view("after_wall_reflection"));
  }
  cb.step.finish(0.0, h);
  return cb;
}

/// The bound specs the registry-wide tests run: every entry, and parameterised ones at
/// M = 1, the default and 7 (not a power of two).
inline std::vector<std::string> bound_specs() {
  std::vector<std::string> out;
  for (const BoundInfo& b : bound_registry()) {
    out.emplace_back(b.name);
    if (!b.parameters.empty()) {  // the first option is M
      out.push_back(std::string(b.name) + ":1");
      out.push_back(std::string(b.name) + ":7");
    }
  }
  return out;
}

}  // namespace ccd::test
