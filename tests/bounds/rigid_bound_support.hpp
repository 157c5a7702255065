#pragma once
// Rigid steps for the orientation-aware bound tests (frame_aabb, obb, obb_sat): a scene of
// shaped bodies with its exact motion and spin, the context a bound gets, and the overlap
// oracle at one time (the certified GJK distance, ccd/queries/convex_distance.hpp).
#include <bounds/bound.hpp>
#include <bounds/registry.hpp>
#include <ccd/broad_phase/registry.hpp>
#include <ccd/motion/state_cursor.hpp>
#include <pipeline/step_pipeline.hpp>
#include <generators/registry.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/queries/convex_distance.hpp>
#include <ccd/scene/scene.hpp>
#include <ccd/shape/shape.hpp>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <set>
#include <string>
#include <random>
#include <utility>
#include <vector>

namespace ccd::test {

class RigidStep {
 public:
  explicit RigidStep(Scene s) : scene(std::move(s)), traj(scene), rigid(scene, traj) {}
  RigidStep(const RigidStep&) = delete;
  RigidStep& operator=(const RigidStep&) = delete;

  /// What a bound of knowledge k gets for the step [t0, t1] (t1 ignored for Instant).
  StepContext context(Knowledge k, double t0, double t1) {
    start.resize(traj.size());
    for (std::size_t i = 0; i < start.size(); ++i)
      start[i] = {traj.position(i, t0), traj.velocity(i, t0), traj.radius(i)};
    StepContext c;
    c.t0 = t0;
    c.t1 = k == Knowledge::Instant ? t0 : t1;
    c.start = start;
    c.exact = k == Knowledge::Exact ? &traj : nullptr;
    c.acceleration_bound = scene.max_acceleration();
    c.walls = scene.box;
    c.motion = &rigid;
    return c;
  }

  ConvexDistance distance(std::uint32_t a, std::uint32_t b, double t) const {
    const Pose pa = rigid.pose(a, t);
    const Pose pb = rigid.pose(b, t);
    return convex_distance(rigid.proxy(a), {pa.centre, pa.rotation}, rigid.proxy(b), {pb.centre, pb.rotation});
  }
  /// The closed shapes may touch at t: their distance is not certified positive.
  bool may_touch(std::uint32_t a, std::uint32_t b, double t) const {
    return distance(a, b, t).status != ConvexDistance::Status::Separated;
  }

  Scene scene;
  Trajectories traj;
  RigidMotion rigid;
  std::vector<BodyState> start;
};

inline Body body_at(const Vec3& p, const Vec3& v = Vec3::Zero(), double radius = 0.0) {
  Body b;
  b.position = p;
  b.velocity = v;
  b.radius = radius;
  return b;
}

inline RigidBody shaped(std::int32_t shape, const Quat& q = Quat::Identity(), const Vec3& omega = Vec3::Zero()) {
  RigidBody r;
  r.shape = shape;
  r.orientation = q;
  r.angular_velocity = omega;
  return r;
}

/// Orientations whose matrices are exact: the identity, half turns about the axes, and
/// the turns by 120 degrees about the diagonals (which permute the axes).
inline std::vector<Quat> exact_orientations() {
  return {Quat(1, 0, 0, 0),        Quat(0, 1, 0, 0),       Quat(0, 0, 1, 0),        Quat(0, 0, 0, 1),
          Quat(0.5, 0.5, 0.5, 0.5), Quat(0.5, -0.5, -0.5, -0.5), Quat(0.5, 0.5, -0.5, 0.5), Quat(-0.5, 0.5, 0.5, 0.5)};
}

/// The shapes the tests use: a crate, a stick, a plate, a rock (dyadic sizes and points).
inline void add_test_shapes(Scene& s) {
  s.shapes.push_back(make_box_shape(Vec3(0.5, 0.25, 0.125), "crate"));
  s.shapes.push_back(make_capsule_shape(1.0, 0.0625, "stick"));
  s.shapes.push_back(make_box_shape(Vec3(0.75, 0.5, 0.03125), "plate"));
  s.shapes.push_back(make_hull_shape(
      {{0.5, 0, 0}, {0, 0.5, 0}, {0, 0, 0.25}, {-0.25, -0.125, -0.125}, {0, -0.25, 0.125}}, "rock"));
}

}  // namespace ccd::test

namespace ccd::test {

/// Pairs (2k, 2k + 1) of shaped bodies (and balls) in exact orientations, placed so that
/// their world boxes touch on x (and on y for a second group: parallel edges), overlap by
/// 1/16, or are 1/64 apart; every position is `offset` plus a dyadic number.
inline Scene dyadic_pairs(const Vec3& offset) {
  Scene s;
  s.horizon = 1.0;
  add_test_shapes(s);
  const std::vector<Quat> qs = exact_orientations();
  const auto world_box = [&](std::int32_t shape, const Quat& q) {
    if (shape < 0) return Aabb::around(Vec3::Zero(), 0.25);
    const Mat3 r = q.toRotationMatrix();
    const Shape& sh = s.shapes[static_cast<std::size_t>(shape)];
    Aabb b{r * sh.points[0], r * sh.points[0]};
    for (const Vec3& p : sh.points) b.merge({r * p, r * p});
    const double rad = sh.proxy().radius;
    b.lo.array() -= rad;
    b.hi.array() += rad;
    return b;
  };
  int k = 0;
  for (std::int32_t sa = -1; sa < 4; ++sa) {
    for (std::int32_t sb = -1; sb < 4; ++sb) {
      for (const double shift : {0.0, -0.0625, 0.015625}) {
        for (const bool edge : {false, true}) {
          const Quat qa = qs[static_cast<std::size_t>(k) % qs.size()];
          const Quat qb = qs[static_cast<std::size_t>(3 * k + 1) % qs.size()];
          const Aabb ba = world_box(sa, qa), bb = world_box(sb, qb);
          const Vec3 ca = offset + Vec3(0, 8.0 * k, 0);
          Vec3 d(ba.hi.x() - bb.lo.x() + shift, 0, 0);
          if (edge) d.y() = ba.hi.y() - bb.lo.y() + shift;
          const Vec3 cb = ca + d;
          if (sa < 0) s.add_rigid_body(body_at(ca, Vec3::Zero(), 0.25), RigidBody{});
          else s.add_rigid_body(body_at(ca), shaped(sa, qa));
          if (sb < 0) s.add_rigid_body(body_at(cb, Vec3::Zero(), 0.25), RigidBody{});
          else s.add_rigid_body(body_at(cb), shaped(sb, qb));
          ++k;
        }
      }
    }
  }
  return s;
}

/// `n` pairs (2k, 2k + 1) of random shapes (or balls) in random orientations, their
/// centres 3/4 apart at most on each axis about `offset`: about half of them touch.
template <class Rng>
Scene random_pairs(Rng& rng, int n, const Vec3& offset) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> pick(-1, 3);
  Scene s;
  s.horizon = 1.0;
  add_test_shapes(s);
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < 2; ++i) {
      const int shape = pick(rng);
      const Vec3 c = offset + Vec3(0, 16.0 * k, 0) + (i == 0 ? Vec3::Zero() : Vec3(0.75 * u(rng), 0.75 * u(rng), 0.75 * u(rng)));
      Quat q(u(rng), u(rng), u(rng), u(rng));
      if (q.norm() < 1e-3) q = Quat::Identity();
      q.normalize();
      if (shape < 0) s.add_rigid_body(body_at(c, Vec3::Zero(), 0.25), RigidBody{});
      else s.add_rigid_body(body_at(c), shaped(shape, q));
    }
  }
  return s;
}

/// For an instant bound: over `scene`'s pairs (2k, 2k + 1) at t = 0, the number of pairs
/// that may touch and the number of those the bound misses (box or test); also counts
/// pairs certified apart that the bound rejects.
struct PairCheck {
  long touching = 0, missed = 0, apart = 0, rejected_apart = 0;
};

inline PairCheck check_pairs(Bound& bound, RigidStep& st) {
  std::vector<Aabb> boxes;
  bound.prepare(st.context(Knowledge::Instant, 0.0, 0.0), boxes);
  PairCheck c;
  for (std::uint32_t a = 0; a + 1 < st.traj.size(); a += 2) {
    const bool reported = boxes[a].overlaps(boxes[a + 1]) && bound.test(a, a + 1).possible();
    const ConvexDistance d = st.distance(a, a + 1, 0.0);
    if (d.status != ConvexDistance::Status::Separated) {
      ++c.touching;
      if (!reported) ++c.missed;
    } else {
      ++c.apart;
      if (!reported) ++c.rejected_apart;
    }
  }
  return c;
}

/// Sections "dyadic pairs" (dyadic_pairs at `offset`: exact orientations make the boxes
/// exact, so a dyadic gap of 1/64 is seen) and "random pairs" (4000 random_pairs from
/// `seed`): the instant bound misses no pair that may touch, and both kinds of pair occur
/// often enough for that to mean something.
inline void check_every_touching_pair(Bound& bound, const Vec3& offset, std::uint64_t seed) {
  SECTION("dyadic pairs") {
    RigidStep st(dyadic_pairs(offset));
    const PairCheck c = check_pairs(bound, st);
    CHECK(c.missed == 0);
    CHECK(c.touching >= 50);
    CHECK(c.rejected_apart >= 50);
  }
  SECTION("random pairs") {
    std::mt19937_64 rng(seed);
    RigidStep st(random_pairs(rng, 4000, offset));
    const PairCheck c = check_pairs(bound, st);
    CHECK(c.missed == 0);
    CHECK(c.touching >= 1000);
    CHECK(c.rejected_apart >= 200);
  }
}

}  // namespace ccd::test

namespace ccd::test {

/// Runs the instant bound `name` through the step pipeline (brute-force broad phase) on
/// generated sticks, plates, crates and rocks mixed with balls, at 9 samples over [0, 1]:
/// every pair that may touch at the sample is among the pairs the bound lets through.
inline void check_pipeline_superset(const std::string& name) {
  long touching = 0, missed = 0;
  for (const char* generator : {"sticks", "plates", "crates", "rocks"}) {
    INFO(generator);
    const Scene scene = ccdlab::generate_scene(
        generator, nlohmann::json{{"bodies", 120}, {"seed", 3}, {"fraction", 0.15}, {"speed_max", 4.0},
                                  {"spin_max", 20.0}, {"spheres", 0.25}, {"elongation", 8.0}});
    RigidStep st(scene);
    StepPipeline pipeline(parse_bound(name).make(), Knowledge::Instant, parse_broad_phase("brute").make());
    StepResult step;
    for (int k = 0; k <= 8; ++k) {
      const double t = k / 8.0;
      pipeline.run(st.context(Knowledge::Instant, t, t), step);
      const std::set<BodyPair> passed(step.bodies.passed.begin(), step.bodies.passed.end());
      CHECK(step.bodies.passed.size() <= step.bodies.candidates.size());
      const auto n = static_cast<std::uint32_t>(st.traj.size());
      for (std::uint32_t a = 0; a < n; ++a) {
        for (std::uint32_t b = a + 1; b < n; ++b) {
          const double R = st.traj.radius(a) + st.traj.radius(b);
          if ((st.start[a].position - st.start[b].position).squaredNorm() > R * R) continue;
          if (!st.may_touch(a, b, t)) continue;
          ++touching;
          if (!passed.count({a, b}) && ++missed <= 3) FAIL_CHECK(name << " drops touching pair " << a << ", " << b << " at t = " << t);
        }
      }
    }
  }
  CHECK(missed == 0);
  CHECK(touching >= 10);
}

}  // namespace ccd::test
