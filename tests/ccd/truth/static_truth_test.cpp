#include <ccd/truth/static_truth.hpp>

#include <ccd/truth/pair_contact.hpp>
#include <tests/ccd/scene/body_builder.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

namespace ccd_truth_static_truth_test {

using ccd::ContactInterval;
using ccd::Scene;
using ccd::StaticEvent;
using ccd::Trajectories;
using ccd::Vec3;
using ccd::test::body;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// An axis-aligned rectangle [x0, x1] x [y0, y1] in the plane z = z0.
ccd::StaticPolygon floor_rect(double x0, double x1, double y0, double y1, double z0) {
  return ccd::polygon_from_vertices({Vec3(x0, y0, z0), Vec3(x1, y0, z0), Vec3(x1, y1, z0), Vec3(x0, y1, z0)});
}

Scene boxed(double horizon, Vec3 lo, Vec3 hi) {
  Scene s;
  s.horizon = horizon;
  s.box = ccd::WallBox{lo, hi};
  return s;
}

}  // namespace

TEST_CASE("static truth: constructed scenes with exact answers", "[truth][scenery]") {
  SECTION("touching a floor polygon exactly at the wall reflection: one touch at t = 2") {
    // The floor wall z = 0 and a polygon on it: the ball (r = 1/2) falls from z = 5/2 at
    // speed 1, reflects at z = 1/2 at t = 2, exactly r from the polygon, and rises.
    Scene s = boxed(4.0, Vec3(-4, -4, 0), Vec3(4, 4, 8));
    s.bodies = {body(0.5, {0, 0, 2.5}, {0, 0, -1})};
    s.scenery = {floor_rect(-2, 2, -2, 2, 0)};
    const auto ev = ccd::compute_static_truth(Trajectories(s), s.scenery, 1);
    REQUIRE(ev.size() == 1);
    CHECK(ev[0] == StaticEvent{0, 0, 2.0, 2.0});
  }
  SECTION("rolling on a floor polygon across reflections from the side walls: one event") {
    // Centre exactly r above the polygon, bouncing between x = -3.5 and 3.5: the pieces
    // break at every reflection, the contact continues: [0, horizon].
    Scene s = boxed(20.0, Vec3(-4, -4, 0), Vec3(4, 4, 8));
    s.bodies = {body(0.5, {0, 0, 0.5}, {2, 0, 0})};
    s.scenery = {floor_rect(-4, 4, -4, 4, 0)};
    const Trajectories t(s);
    REQUIRE(t.pieces(0).size() > 3);
    const auto ev = ccd::compute_static_truth(t, s.scenery, 1);
    REQUIRE(ev.size() == 1);
    CHECK(ev[0] == StaticEvent{0, 0, 0.0, 20.0});
  }
  SECTION("bouncing under gravity on a floor polygon: a touch at every reflection") {
    // g = -1, dropped from z = 5/2 (2 above the reflection plane z = 1/2): falls for 2 s,
    // period 4 s: touches at t = 2 and 6 within the horizon 7.
    Scene s = boxed(7.0, Vec3(-4, -4, 0), Vec3(4, 4, 8));
    s.gravity = Vec3(0, 0, -1);
    s.bodies = {body(0.5, {0, 0, 2.5})};
    s.scenery = {floor_rect(-2, 2, -2, 2, 0)};
    const auto ev = ccd::compute_static_truth(Trajectories(s), s.scenery, 1);
    REQUIRE(ev.size() == 2);
    CHECK(ev[0].enter == ev[0].exit);
    CHECK(ev[0].enter == Approx(2.0).margin(16 * kEps * 7));
    CHECK(ev[1].enter == ev[1].exit);
    CHECK(ev[1].enter == Approx(6.0).margin(16 * kEps * 7));
  }
  SECTION("an acceleration change: at rest until t = 1, then falling through a polygon") {
    // z = 2 - (t - 1)^2 after t = 1 (own acceleration -2): |z| <= r = 1 on [2, 1 + sqrt 3].
    Scene s;
    s.horizon = 3.0;
    s.bodies = {body(1.0, {0.5, 0.5, 2})};
    s.bodies[0].acceleration_changes = {{1.0, Vec3(0, 0, -2)}};
    s.scenery = {floor_rect(-2, 2, -2, 2, 0)};
    const auto ev = ccd::compute_static_truth(Trajectories(s), s.scenery, 1);
    REQUIRE(ev.size() == 1);
    CHECK(ev[0].enter == Approx(2.0).margin(16 * kEps * 3));
    CHECK(ev[0].exit == Approx(1.0 + std::sqrt(3.0)).margin(1e-14));
  }
  SECTION("two polygons, two bodies, far from the origin: events sorted by (enter, body, polygon)") {
    const double F = 1073741824.0;  // 2^30
    Scene s;
    s.horizon = 4.0;
    s.bodies = {body(0.5, {F + 1, F + 1, 2}, {0, 0, -1}), body(0.5, {F + 1, F + 1, -2}, {0, 0, 1})};
    s.scenery = {floor_rect(F, F + 2, F, F + 2, 0), floor_rect(F, F + 2, F, F + 2, 1)};
    const auto ev = ccd::compute_static_truth(Trajectories(s), s.scenery, 2);
    // Body 0 meets z = 1 on [0.5, 1.5] and z = 0 on [1.5, 2.5]; body 1 meets z = 0 on
    // [1.5, 2.5] and z = 1 on [2.5, 3.5].
    REQUIRE(ev.size() == 4);
    CHECK(ev[0] == StaticEvent{0, 1, 0.5, 1.5});
    CHECK(ev[1] == StaticEvent{0, 0, 1.5, 2.5});
    CHECK(ev[2] == StaticEvent{1, 0, 1.5, 2.5});
    CHECK(ev[3] == StaticEvent{1, 1, 2.5, 3.5});
    CHECK(std::is_sorted(ev.begin(), ev.end(), ccd::static_event_order));
  }
}

TEST_CASE("static truth: windows, threads and dense sampling agree", "[truth][scenery]") {
  // Random balls under gravity in a walled box with a few tilted polygons. Three checks:
  // the events do not depend on the thread count; body_polygon_intervals on a window
  // equals the whole-horizon events clipped to it; and at dense samples, a centre deeper
  // than 1e-9 inside some polygon's r-neighbourhood is inside an event, and one farther
  // than 1e-9 outside is in none (sampled distance by definition, in long double).
  std::mt19937_64 rng(1414);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Scene s = boxed(4.0, Vec3(-4, -4, -4), Vec3(4, 4, 4));
  s.gravity = Vec3(0, 0, -2);
  for (int i = 0; i < 12; ++i)
    s.bodies.push_back(body(0.25 + 0.25 * (u(rng) + 1.0), {3 * u(rng), 3 * u(rng), 3 * u(rng)},
                            {4 * u(rng), 4 * u(rng), 4 * u(rng)}));
  s.scenery = {ccd::polygon_from_vertices({Vec3(-3, -3, -2), Vec3(3, -3, -1), Vec3(3, 3, -1), Vec3(-3, 3, -2)}),
               ccd::polygon_from_vertices({Vec3(0, -1, 0), Vec3(1, 0, 1), Vec3(0, 1, 2), Vec3(-1, 0, 1)}),
               ccd::polygon_from_vertices({Vec3(-2, 2, 2), Vec3(2, 2, 2), Vec3(0, 2, 3.5)})};
  const Trajectories t(s);
  const auto ev = ccd::compute_static_truth(t, s.scenery, 1);
  CHECK(ev == ccd::compute_static_truth(t, s.scenery, 3));
  CHECK(ev.size() >= 6);
  for (std::uint32_t b = 0; b < s.bodies.size(); ++b)
    for (std::uint32_t j = 0; j < s.scenery.size(); ++j) {
      std::vector<ContactInterval> win;
      ccd::body_polygon_intervals(t, b, s.scenery[j], 1.0, 3.0, win);
      std::vector<ContactInterval> expected;
      for (const StaticEvent& e : ev)
        if (e.body == b && e.polygon == j && e.exit >= 1.0 && e.enter <= 3.0)
          expected.push_back({std::max(e.enter, 1.0), std::min(e.exit, 3.0)});
      CHECK(win == expected);
    }
  auto distance = [](const Vec3& x, const ccd::StaticPolygon& poly) {
    using L = long double;
    const std::size_t n = poly.vertices.size();
    bool inside = true;
    L best = std::numeric_limits<L>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3& a = poly.vertices[i];
      const Vec3 e = poly.vertices[(i + 1) % n] - a;
      if (poly.normal.cross(e).dot(x - a) < 0) inside = false;
      L w[3], ee[3];
      for (int k = 0; k < 3; ++k) w[k] = L(x[k]) - a[k], ee[k] = e[k];
      const L lam = std::clamp((w[0] * ee[0] + w[1] * ee[1] + w[2] * ee[2]) /
                                   (ee[0] * ee[0] + ee[1] * ee[1] + ee[2] * ee[2]), L(0), L(1));
      L d2 = 0;
      for (int k = 0; k < 3; ++k) d2 += (w[k] - lam * ee[k]) * (w[k] - lam * ee[k]);
      best = std::min(best, std::sqrt(d2));
    }
    if (inside) {
      L h = 0;
      for (int k = 0; k < 3; ++k) h += L(poly.normal[k]) * (L(x[k]) - poly.vertices[0][k]);
      best = std::min(best, std::fabs(h));
    }
    return static_cast<double>(best);
  };
  int deep = 0;
  for (std::uint32_t b = 0; b < s.bodies.size(); ++b)
    for (int k = 0; k <= 2000; ++k) {
      const double time = 4.0 * k / 2000;
      const Vec3 x = t.position(b, time);
      for (std::uint32_t j = 0; j < s.scenery.size(); ++j) {
        const double d = distance(x, s.scenery[j]);
        const bool in = std::any_of(ev.begin(), ev.end(), [&](const StaticEvent& e) {
          return e.body == b && e.polygon == j && e.enter <= time && time <= e.exit;
        });
        if (d < t.radius(b) - 1e-9) {
          ++deep;
          CHECK(in);
        }
        if (d > t.radius(b) + 1e-9) CHECK_FALSE(in);
      }
    }
  CHECK(deep > 100);
}

}  // namespace ccd_truth_static_truth_test
