// The body-static truth against an independent exact reference in rational arithmetic
// (GMP mpq_class): every body's centre is recomputed from the scene's own numbers
// (initial state, acceleration and velocity changes; no walls, so that the reference
// needs no root solving), and the squared distance to the polygon is computed by its
// definition (projection inside the face, else the nearest point of the nearest edge
// segment, clamped), exactly. For every event: in contact (up to a tolerance far below
// what one ulp of time changes) at `enter` and `exit`, strictly apart one double before
// `enter` and one double after `exit`; random instants outside every event are strictly
// apart. Constructed dyadic cases (grazing an edge or a vertex, a face touched at a wall
// reflection, rolling along a face, contacts at an acceleration or velocity change, far
// from the origin) have exact expected times.
#include <ccd/truth/static_truth.hpp>

#include <tests/ccd/scene/body_builder.hpp>
#include <tests/ccd/truth/reference_position.hpp>

#include <catch2/catch.hpp>
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace ccd_truth_static_reference_test {

using ccd::Scene;
using ccd::StaticEvent;
using ccd::Trajectories;
using ccd::Vec3;
using ccd::test::body;

namespace {

using Q = mpq_class;
using QVec = std::array<Q, 3>;

QVec q_of(const Vec3& x) { return {Q(x[0]), Q(x[1]), Q(x[2])}; }
QVec sub(const QVec& a, const QVec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Q dot(const QVec& a, const QVec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
QVec cross(const QVec& a, const QVec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Squared distance from c to the polygon (the plane through V_0 with the area normal),
// minus r^2, exactly.
Q gap_q(const QVec& c, const ccd::StaticPolygon& poly, double r) {
  const std::size_t n = poly.vertices.size();
  std::vector<QVec> v;
  for (const Vec3& x : poly.vertices) v.push_back(q_of(x));
  QVec N{0, 0, 0};
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const QVec t = cross(sub(v[i], v[0]), sub(v[i + 1], v[0]));
    for (int k = 0; k < 3; ++k) N[k] += t[k];
  }
  bool inside = true;
  for (std::size_t i = 0; i < n && inside; ++i)
    inside = dot(cross(N, sub(v[(i + 1) % n], v[i])), sub(c, v[i])) >= 0;
  const Q r2 = Q(r) * Q(r);
  if (inside) {
    const Q h = dot(N, sub(c, v[0]));
    return h * h / dot(N, N) - r2;
  }
  Q best = -1;
  for (std::size_t i = 0; i < n; ++i) {
    const QVec e = sub(v[(i + 1) % n], v[i]), w = sub(c, v[i]);
    Q u = dot(e, w) / dot(e, e);
    if (u < 0) u = 0;
    if (u > 1) u = 1;
    QVec d;
    for (int k = 0; k < 3; ++k) d[k] = w[k] - u * e[k];
    const Q d2 = dot(d, d);
    if (best < 0 || d2 < best) best = d2;
  }
  return best - r2;
}

Q gap_at(const Scene& s, std::uint32_t b, std::uint32_t j, double t) {
  return gap_q(ccd::test::reference_position<Q>(s, s.bodies[b], t), s.scenery[j], s.bodies[b].radius);
}

// Checks every event of the scene's static truth against the exact reference and
// returns the number of transversal events; samples `apart_samples` random instants.
int check_against_reference(const Scene& s, const Q& tol, int apart_samples) {
  const Trajectories traj(s);
  const auto events = ccd::compute_static_truth(traj, s.scenery, 1);
  int transversal = 0;
  for (const StaticEvent& e : events) {
    CAPTURE(e.body, e.polygon, e.enter, e.exit);
    CHECK(gap_at(s, e.body, e.polygon, e.enter) <= tol);
    CHECK(gap_at(s, e.body, e.polygon, e.exit) <= tol);
    if (e.enter > 0.0) CHECK(gap_at(s, e.body, e.polygon, std::nextafter(e.enter, -1.0)) > 0);
    if (e.exit < s.horizon) CHECK(gap_at(s, e.body, e.polygon, std::nextafter(e.exit, s.horizon + 1.0)) > 0);
    if (e.enter < e.exit) {
      CHECK(gap_at(s, e.body, e.polygon, 0.5 * (e.enter + e.exit)) <= tol);
      ++transversal;
    }
  }
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<std::uint32_t> pick_body(0, static_cast<std::uint32_t>(s.bodies.size() - 1));
  std::uniform_int_distribution<std::uint32_t> pick_polygon(0, static_cast<std::uint32_t>(s.scenery.size() - 1));
  std::uniform_real_distribution<double> when(0.0, s.horizon);
  int apart = 0;
  for (int k = 0; k < apart_samples; ++k) {
    const std::uint32_t b = pick_body(rng), j = pick_polygon(rng);
    const double t = when(rng);
    bool inside = false;
    for (const StaticEvent& e : events) inside = inside || (e.body == b && e.polygon == j && e.enter <= t && t <= e.exit);
    if (inside) continue;
    CAPTURE(b, j, t);
    CHECK(gap_at(s, b, j, t) > 0);
    ++apart;
  }
  CHECK(apart > apart_samples / 2);
  return transversal;
}

// Random triangles, parallelograms and axis-aligned rectangles around `offset`, and bodies
// aimed at them with their own accelerations, acceleration changes and velocity changes.
Scene random_scene(std::uint64_t seed, double offset, int bodies) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Scene s;
  s.horizon = 2.0;
  s.gravity = Vec3(0, 0, -9.81);
  auto point = [&](double size) { return Vec3(offset + size * u(rng), offset + size * u(rng), offset + size * u(rng)); };
  for (int i = 0; i < 6; ++i) {
    const Vec3 a = point(3.0), b = a + Vec3(u(rng), u(rng), u(rng)), c = a + Vec3(u(rng), u(rng), u(rng));
    if (i % 3 == 0) s.scenery.push_back(ccd::polygon_from_vertices({a, b, c}));
    if (i % 3 == 1) s.scenery.push_back(ccd::polygon_from_vertices({a, b, b + (c - a), c}));
    if (i % 3 == 2) {
      const double h = 0.5 + 0.25 * u(rng);
      s.scenery.push_back(ccd::polygon_from_vertices(
          {a, a + Vec3(2 * h, 0, 0), a + Vec3(2 * h, h, 0), a + Vec3(0, h, 0)}));
    }
  }
  for (int i = 0; i < bodies; ++i) {
    const ccd::StaticPolygon& target = s.scenery[static_cast<std::size_t>(i) % s.scenery.size()];
    const Vec3 p = point(4.0);
    const double arrive = 1.0 + 0.8 * u(rng);
    Vec3 aim = target.vertices[0] + 0.5 * (target.vertices[1] - target.vertices[0]) +
               0.5 * u(rng) * (target.vertices[2] - target.vertices[1]);
    const Vec3 acc(3 * u(rng), 3 * u(rng), 3 * u(rng));
    // Velocity that reaches the aim point at `arrive` under the body's acceleration and gravity.
    const Vec3 v = (aim - p) / arrive - 0.5 * arrive * (acc + s.gravity);
    ccd::Body bd = body(0.05 + 0.2 * (u(rng) + 1.0), p, v, i % 4 == 3 ? Vec3::Zero() : acc);
    if (i % 3 == 0) bd.acceleration_changes.push_back({0.8 + 0.5 * u(rng), Vec3(2 * u(rng), 2 * u(rng), 0)});
    if (i % 3 == 1) bd.velocity_changes.push_back({0.6 + 0.5 * u(rng), -0.5 * bd.velocity});
    s.bodies.push_back(bd);
  }
  return s;
}

}  // namespace

TEST_CASE("static truth: random scenes agree with an exact rational reference", "[truth][scenery][reference]") {
  const double offset = GENERATE(0.0, 1000.0, 1048576.0);
  CAPTURE(offset);
#ifdef CCDLAB_SANITIZED
  const int bodies = 24, samples = 300;
#else
  const int bodies = 60, samples = 1500;
#endif
  const Scene s = random_scene(29 + static_cast<std::uint64_t>(offset), offset, bodies);
  // Far below the change of the squared gap over one ulp of time at a transversal
  // crossing (2 r |v| ulp(t), about 1e-17 here), far above double-double rounding.
  const Q tol = Q(1e-30) * Q(offset + 10) * Q(offset + 10);
  CHECK(check_against_reference(s, tol, samples) >= bodies / 3);
}

TEST_CASE("static truth: constructed dyadic cases are exact far from the origin", "[truth][scenery][reference]") {
  const double o = GENERATE(0.0, 1048576.0);  // 2^20: every coordinate below stays a dyadic double
  CAPTURE(o);
  const Vec3 O(o, o, o);
  // The unit square [0, 1]^2 in the plane z = 0 (shifted by O).
  const ccd::StaticPolygon square = ccd::polygon_from_vertices(
      {O + Vec3(0, 0, 0), O + Vec3(1, 0, 0), O + Vec3(1, 1, 0), O + Vec3(0, 1, 0)});
  auto truth = [&](Scene s) {
    s.scenery = {square};
    return ccd::compute_static_truth(Trajectories(s), s.scenery, 1);
  };
  Scene s;
  s.horizon = 4.0;
  SECTION("grazing an edge: the centre passes exactly r = 1/4 outside the edge y = 0 at t = 1") {
    s.bodies = {body(0.25, O + Vec3(0.5, -0.25, -1), {0, 0, 1})};
    const auto ev = truth(s);
    REQUIRE(ev.size() == 1);
    CHECK(ev[0] == StaticEvent{0, 0, 1.0, 1.0});
    s.bodies[0].position[1] -= 0x1p-30;  // 2^-30 farther: a miss
    CHECK(truth(s).empty());
  }
  SECTION("grazing a vertex: offset (-3/8, -1/2) from the corner, r = 5/8, at t = 1") {
    s.bodies = {body(0.625, O + Vec3(-0.375, -0.5, -1), {0, 0, 1})};
    const auto ev = truth(s);
    REQUIRE(ev.size() == 1);
    CHECK(ev[0] == StaticEvent{0, 0, 1.0, 1.0});
  }
  SECTION("a face touched exactly at a wall reflection") {
    // The floor wall is the polygon's plane: the ball (r = 1/2) reflects at t = 3/2.
    s.box = ccd::WallBox{O + Vec3(-8, -8, 0), O + Vec3(8, 8, 8)};
    s.bodies = {body(0.5, O + Vec3(-1, 0.5, 2), {1, 0, -1})};
    const auto ev = truth(s);
    REQUIRE(ev.size() == 1);
    CHECK(ev[0] == StaticEvent{0, 0, 1.5, 1.5});
  }
  SECTION("rolling along the face: enter and exit exact at the edges x = 0 and x = 1") {
    s.bodies = {body(0.5, O + Vec3(-0.5, 0.5, 0.5), {0.5, 0, 0})};
    const auto ev = truth(s);
    REQUIRE(ev.size() == 1);
    CHECK(ev[0] == StaticEvent{0, 0, 1.0, 3.0});
  }
  SECTION("an acceleration change exactly at a tangency turns the touch into a crossing") {
    // Decelerating towards the face, the centre stops at height r = 1/2 at t = 1 (a touch);
    // from t = 1 it accelerates down at 2: z = 1/2 - (t - 1)^2, through to -1/2 at t = 2.
    ccd::Body b = body(0.5, O + Vec3(0.5, 0.5, 1), {0, 0, -1}, {0, 0, 1});
    s.bodies = {b};
    auto ev = truth(s);
    REQUIRE(ev.size() == 1);
    CHECK(ev[0] == StaticEvent{0, 0, 1.0, 1.0});
    b.acceleration_changes.push_back({1.0, Vec3(0, 0, -2)});
    s.bodies = {b};
    ev = truth(s);
    REQUIRE(ev.size() == 1);
    CHECK(ev[0] == StaticEvent{0, 0, 1.0, 2.0});
  }
  SECTION("a velocity change exactly at contact: reversed at height r, and a later crossing") {
    ccd::Body b = body(0.5, O + Vec3(0.5, 0.5, 1), {0, 0, -0.5});
    b.velocity_changes.push_back({1.0, Vec3(0, 0, 0.5)});
    b.velocity_changes.push_back({2.0, Vec3(0, 0, -1)});  // at height 1: enters at 2.5, leaves at 3.5
    s.bodies = {b};
    const auto ev = truth(s);
    REQUIRE(ev.size() == 2);
    CHECK(ev[0] == StaticEvent{0, 0, 1.0, 1.0});
    CHECK(ev[1] == StaticEvent{0, 0, 2.5, 3.5});
  }
  SECTION("the same constructions pass the exact reference (walls excepted)") {
    s.bodies = {body(0.25, O + Vec3(0.5, -0.25, -1), {0, 0, 1}), body(0.625, O + Vec3(-0.375, -0.5, -1), {0, 0, 1}),
                body(0.5, O + Vec3(-0.5, 0.5, 0.5), {0.5, 0, 0})};
    s.scenery = {square};
    check_against_reference(s, Q(Q(1e-30) * Q(o + 10) * Q(o + 10)), 200);
  }
}

}  // namespace ccd_truth_static_reference_test
