#include <ccd/queries/sphere_sphere_contact.hpp>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

namespace ccd_queries_sphere_sphere_contact_test {

using ccd::ContactStatus;
using ccd::MovingSphere;
using ccd::Vec3;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

MovingSphere sphere(Vec3 p, Vec3 v, double r, Vec3 a = Vec3::Zero()) { return {p, v, a, r}; }

// Squared distance minus R^2 at s, in long double (reference for dense sampling).
long double f_ref(const MovingSphere& a, const MovingSphere& b, long double s) {
  long double sum = 0.0L;
  for (int k = 0; k < 3; ++k) {
    const long double d = (static_cast<long double>(b.position[k]) - a.position[k]) +
                          (static_cast<long double>(b.velocity[k]) - a.velocity[k]) * s +
                          (static_cast<long double>(b.acceleration[k]) - a.acceleration[k]) * s * s / 2.0L;
    sum += d * d;
  }
  const long double R = static_cast<long double>(a.radius) + b.radius;
  return sum - R * R;
}

}  // namespace

TEST_CASE("linear motion: hand-worked contacts", "[queries][sphere]") {
  // Unit spheres, so R = 2. Times are exact in binary unless stated.
  SECTION("head-on: centres 10 apart closing at 2: contact [4, 6]") {
    const auto a = sphere({0, 0, 0}, {1, 0, 0}, 1.0);
    const auto b = sphere({10, 0, 0}, {-1, 0, 0}, 1.0);
    const auto s = ccd::sphere_sphere_contact_intervals(a, b, 10.0);
    REQUIRE(s.count == 1);
    CHECK(s.intervals[0].lo == Approx(4.0).margin(4 * kEps * 10));
    CHECK(s.intervals[0].hi == Approx(6.0).margin(4 * kEps * 10));
    const auto c = ccd::sphere_sphere_first_contact(a, b, 10.0);
    CHECK(c.status == ContactStatus::Hit);
    CHECK(c.toi == s.intervals[0].lo);
    // Swapped roles give the same times.
    const auto t = ccd::sphere_sphere_contact_intervals(b, a, 10.0);
    REQUIRE(t.count == 1);
    CHECK(t.intervals[0].lo == s.intervals[0].lo);
  }
  SECTION("tangent: passing at exactly R touches once, at s = 10 (enter == exit)") {
    const auto a = sphere({0, 0, 0}, {0, 0, 0}, 1.0);
    const auto b = sphere({10, 2, 0}, {-1, 0, 0}, 1.0);
    const auto s = ccd::sphere_sphere_contact_intervals(a, b, 20.0);
    REQUIRE(s.count == 1);
    CHECK(s.intervals[0].lo == s.intervals[0].hi);
    CHECK(s.intervals[0].lo == Approx(10.0).margin(1e-9 * 20.0));
  }
  SECTION("tangent with inexact data: offset direction (0.6, 0.8) * R, oblique velocity") {
    // b would pass a at closest distance exactly R with exact decimals; the doubles that
    // represent them cross by a few ulps (long double: f(3) < 0), so the data's answer is
    // a short interval around 3 of width about sqrt(eps), not a point.
    const Vec3 dir(0.6, 0.8, 0.0);
    const Vec3 v(0.8, -0.6, 0.0);  // perpendicular to dir
    const auto a = sphere({0.3, 0.1, 0.7}, {0, 0, 0}, 0.7);
    const auto b = sphere(Vec3(0.3, 0.1, 0.7) + dir * 1.9 - v * 3.0, v, 1.2);
    const auto s = ccd::sphere_sphere_contact_intervals(a, b, 10.0);
    REQUIRE(f_ref(a, b, 3.0L) < -1e-17L);
    REQUIRE(s.count == 1);
    CHECK(s.intervals[0].lo < 3.0);
    CHECK(s.intervals[0].hi > 3.0);
    CHECK(s.intervals[0].hi - s.intervals[0].lo < 1e-7);
  }
  SECTION("grazing just-miss: closest distance R (1 + 1e-9): no contact") {
    const auto a = sphere({0, 0, 0}, {0, 0, 0}, 1.0);
    const auto b = sphere({10, 2.0 * (1.0 + 1e-9), 0}, {-1, 0, 0}, 1.0);
    CHECK(ccd::sphere_sphere_contact_intervals(a, b, 20.0).count == 0);
    CHECK(ccd::sphere_sphere_first_contact(a, b, 20.0).status == ContactStatus::Miss);
  }
  SECTION("grazing just-hit: closest distance R (1 - 1e-9): short interval around 10") {
    const double y = 2.0 * (1.0 - 1e-9);
    const auto a = sphere({0, 0, 0}, {0, 0, 0}, 1.0);
    const auto b = sphere({10, y, 0}, {-1, 0, 0}, 1.0);
    const auto s = ccd::sphere_sphere_contact_intervals(a, b, 20.0);
    REQUIRE(s.count == 1);
    // Half-width sqrt(R^2 - y^2) = sqrt((2 - y)(2 + y)), in long double. The data's
    // rounding moves the roots by ~ eps R^2 / (R w) (first order in the closing speed w).
    const long double w = std::sqrt((2.0L - y) * (2.0L + y));
    const double tol = 16 * kEps * 4.0 / static_cast<double>(w) + 4 * kEps * 20;
    CHECK(s.intervals[0].lo == Approx(static_cast<double>(10.0L - w)).margin(tol));
    CHECK(s.intervals[0].hi == Approx(static_cast<double>(10.0L + w)).margin(tol));
    CHECK(s.intervals[0].hi - s.intervals[0].lo > 1e-4);
  }
  SECTION("coincident centres at s = 0: overlapping from 0") {
    const auto a = sphere({1, 1, 1}, {1, 0, 0}, 0.5);
    const auto b = sphere({1, 1, 1}, {-1, 0, 0}, 0.5);
    const auto c = ccd::sphere_sphere_first_contact(a, b, 3.0);
    CHECK(c.status == ContactStatus::Overlapping);
    CHECK(c.toi == 0.0);
    const auto s = ccd::sphere_sphere_contact_intervals(a, b, 3.0);
    REQUIRE(s.count == 1);
    CHECK(s.intervals[0].lo == 0.0);
    CHECK(s.intervals[0].hi == Approx(0.5).margin(4 * kEps * 3));  // separation 2s reaches R = 1
  }
  SECTION("zero relative velocity, overlapping: the whole duration") {
    const auto a = sphere({0, 0, 0}, {3, 1, 2}, 1.0);
    const auto b = sphere({1.5, 0, 0}, {3, 1, 2}, 1.0);
    const auto s = ccd::sphere_sphere_contact_intervals(a, b, 7.0);
    REQUIRE(s.count == 1);
    CHECK((s.intervals[0].lo == 0.0 && s.intervals[0].hi == 7.0));
  }
  SECTION("zero relative velocity, exactly touching: the whole duration") {
    const auto a = sphere({0, 0, 0}, {3, 1, 2}, 1.0);
    const auto b = sphere({2, 0, 0}, {3, 1, 2}, 1.0);
    const auto s = ccd::sphere_sphere_contact_intervals(a, b, 7.0);
    REQUIRE(s.count == 1);
    CHECK((s.intervals[0].lo == 0.0 && s.intervals[0].hi == 7.0));
  }
  SECTION("zero relative velocity, apart: no contact") {
    const auto a = sphere({0, 0, 0}, {3, 1, 2}, 1.0);
    const auto b = sphere({2.5, 0, 0}, {3, 1, 2}, 1.0);
    CHECK(ccd::sphere_sphere_contact_intervals(a, b, 7.0).count == 0);
  }
  SECTION("separating from a touching start: the point s = 0") {
    const auto a = sphere({0, 0, 0}, {0, 0, 0}, 1.0);
    const auto b = sphere({2, 0, 0}, {1, 0, 0}, 1.0);
    const auto s = ccd::sphere_sphere_contact_intervals(a, b, 5.0);
    REQUIRE(s.count == 1);
    CHECK((s.intervals[0].lo == 0.0 && s.intervals[0].hi == 0.0));
    CHECK(ccd::sphere_sphere_first_contact(a, b, 5.0).status == ContactStatus::Overlapping);
  }
  SECTION("far from the origin (~1e6): head-on [4, 6]") {
    const Vec3 o(1e6, -1e6, 1e6);
    const auto a = sphere(o + Vec3(0.25, 0, 0), {1, 0, 0}, 1.0);
    const auto b = sphere(o + Vec3(10.25, 0, 0), {-1, 0, 0}, 1.0);
    const auto s = ccd::sphere_sphere_contact_intervals(a, b, 10.0);
    REQUIRE(s.count == 1);
    // Positions carry eps * 1e6 of rounding; the closing speed is 2.
    const double tol = 4 * kEps * 1e6 / 2.0;
    CHECK(s.intervals[0].lo == Approx(4.0).margin(tol));
    CHECK(s.intervals[0].hi == Approx(6.0).margin(tol));
  }
  SECTION("far from the origin (~1e6): tangent stays a point") {
    const Vec3 o(1e6, 1e6, -1e6);
    const auto a = sphere(o, {0, 0, 0}, 1.0);
    const auto b = sphere(o + Vec3(10, 2, 0), {-1, 0, 0}, 1.0);
    const auto s = ccd::sphere_sphere_contact_intervals(a, b, 20.0);
    REQUIRE(s.count == 1);
    CHECK(s.intervals[0].lo == s.intervals[0].hi);
    CHECK(s.intervals[0].lo == Approx(10.0).margin(1e-9 * 20));
  }
  SECTION("negative duration: no contact") {
    const auto a = sphere({0, 0, 0}, {0, 0, 0}, 1.0);
    CHECK(ccd::sphere_sphere_contact_intervals(a, a, -1.0).count == 0);
  }
}

TEST_CASE("accelerated motion: hand-worked contacts", "[queries][sphere]") {
  SECTION("shared acceleration (gravity) keeps the relative path linear: [4, 6]") {
    const Vec3 g(0, -9.81, 0);
    const auto a = sphere({0, 5, 0}, {1, 0, 0}, 1.0, g);
    const auto b = sphere({10, 5, 0}, {-1, 0, 0}, 1.0, g);
    const auto s = ccd::sphere_sphere_contact_intervals(a, b, 10.0);
    REQUIRE(s.count == 1);
    CHECK(s.intervals[0].lo == Approx(4.0).margin(4 * kEps * 10));
    CHECK(s.intervals[0].hi == Approx(6.0).margin(4 * kEps * 10));
  }
  SECTION("different accelerations, two separate intervals") {
    // Relative x(s) = s^2 - 4 s + 3 = (s-1)(s-3): D0 = 3, Dv = -4, Da = 2; R = 0.5.
    // |x| <= 1/2 on [2 - sqrt(1.5), 2 - sqrt(0.5)] and [2 + sqrt(0.5), 2 + sqrt(1.5)].
    const auto a = sphere({0, 0, 0}, {0, 0, 0}, 0.25);
    const auto b = sphere({3, 0, 0}, {-4, 0, 0}, 0.25, {2, 0, 0});
    const auto s = ccd::sphere_sphere_contact_intervals(a, b, 5.0);
    REQUIRE(s.count == 2);
    // Simple roots: rounding band over |f'| >= 2 |x| |x'| = 2 * 0.5 * 2 sqrt(0.5) at the roots.
    const double tol = 8 * kEps * 5;  // simple roots: a few ulps of the times
    CHECK(s.intervals[0].lo == Approx(2 - std::sqrt(1.5)).margin(tol));
    CHECK(s.intervals[0].hi == Approx(2 - std::sqrt(0.5)).margin(tol));
    CHECK(s.intervals[1].lo == Approx(2 + std::sqrt(0.5)).margin(tol));
    CHECK(s.intervals[1].hi == Approx(2 + std::sqrt(1.5)).margin(tol));
    CHECK(ccd::sphere_sphere_first_contact(a, b, 5.0).toi == s.intervals[0].lo);
  }
  SECTION("different accelerations, tangency of the quartic") {
    // d(s) = (s^2/2 - 2, 1, 0), R = 1: f = (s^2/2 - 2)^2, a double root at s = 2.
    const auto a = sphere({0, 0, 0}, {0, 0, 0}, 0.5);
    const auto b = sphere({-2, 1, 0}, {0, 0, 0}, 0.5, {1, 0, 0});
    const auto s = ccd::sphere_sphere_contact_intervals(a, b, 4.0);
    REQUIRE(s.count == 1);
    CHECK(s.intervals[0].lo == s.intervals[0].hi);
    CHECK(s.intervals[0].lo == Approx(2.0).margin(1e-9 * 4));
  }
  SECTION("different accelerations, tangency with inexact data (radii 0.3 + 0.7)") {
    const auto a = sphere({0.1, 0.2, 0.3}, {0, 0, 0}, 0.3, {0.0, 0.0, 0.1});
    const auto b = sphere({0.1 - 2.0, 0.2 + 1.0, 0.3}, {0, 0, 0}, 0.7, {1.0, 0.0, 0.1});
    const auto s = ccd::sphere_sphere_contact_intervals(a, b, 4.0);
    REQUIRE(s.count == 1);
    CHECK(s.intervals[0].lo == s.intervals[0].hi);
    CHECK(s.intervals[0].lo == Approx(2.0).margin(1e-9 * 4));
  }
  SECTION("different accelerations, just-miss of the quartic tangency") {
    const auto a = sphere({0, 0, 0}, {0, 0, 0}, 0.5);
    const auto b = sphere({-2, 1.0 + 1e-9, 0}, {0, 0, 0}, 0.5, {1, 0, 0});
    CHECK(ccd::sphere_sphere_contact_intervals(a, b, 4.0).count == 0);
  }
}

TEST_CASE("contact intervals agree with dense long double sampling", "[queries][sphere]") {
  // Random quartic and quadratic cases. At each sample s, a clear reference verdict
  // (|f| above a band of 1e-9 R^2, far beyond rounding) must agree with the intervals.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_real_distribution<double> rad(0.2, 1.0);
  int hits = 0;
  for (int it = 0; it < 400; ++it) {
    const bool shared = it % 2 == 0;
    const Vec3 acc = shared ? Vec3(0, -9.81, 0) : Vec3(3 * u(rng), 3 * u(rng), 3 * u(rng));
    const auto a = sphere({2 * u(rng), 2 * u(rng), 2 * u(rng)}, {2 * u(rng), 2 * u(rng), 2 * u(rng)}, rad(rng),
                          shared ? acc : Vec3(3 * u(rng), 3 * u(rng), 3 * u(rng)));
    const auto b = sphere({2 * u(rng), 2 * u(rng), 2 * u(rng)}, {2 * u(rng), 2 * u(rng), 2 * u(rng)}, rad(rng), acc);
    const double S = 3.0;
    const auto set = ccd::sphere_sphere_contact_intervals(a, b, S);
    hits += set.count > 0;
    const long double R = static_cast<long double>(a.radius) + b.radius;
    for (int k = 0; k <= 2000; ++k) {
      const double s = S * k / 2000.0;
      const long double f = f_ref(a, b, s);
      bool inside = false;
      for (int i = 0; i < set.count; ++i) inside = inside || (set.intervals[i].lo <= s && s <= set.intervals[i].hi);
      if (f < -1e-9L * R * R) REQUIRE(inside);
      if (f > 1e-9L * R * R) REQUIRE(!inside);
    }
  }
  CHECK(hits > 50);
}

TEST_CASE("near-tangencies from rounded data follow what the rounded data say", "[queries][sphere]") {
  // Tangent trajectories built from random frames: in exact arithmetic the centres would
  // come exactly R apart once, at s0. The rounded doubles are the data, and they miss by
  // a few ulps or cross by a few ulps. The query must say which, as an independent long
  // double minimisation of f does wherever that reference is clear (|f_min| > 1e-17):
  // a miss is no contact (the former band of 16 eps M^2 called all of these touching);
  // a crossing is an interval around s0 (about sqrt(eps) wide).
  std::mt19937_64 rng(31337);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto unit = [&] {
    Vec3 v;
    do v = Vec3(u(rng), u(rng), u(rng)); while (v.norm() < 0.1);
    return v.normalized();
  };
  const double S = 4.0;
  int misses = 0, crossings = 0;
  for (int it = 0; it < 4000; ++it) {
    const Vec3 e1 = unit();
    const Vec3 e2 = e1.cross(unit()).normalized();
    const double ra = 0.5 + 0.5 * (u(rng) + 1.0), rb = 0.1 + (u(rng) + 1.0);
    const double R = ra + rb;
    const double s0 = 0.5 + 1.5 * (u(rng) + 1.0);  // in [0.5, 3.5]
    MovingSphere a = sphere(Vec3(u(rng), u(rng), u(rng)) * 10.0, Vec3(u(rng), u(rng), u(rng)) * 3.0, ra);
    MovingSphere b = a;
    b.radius = rb;
    if (it % 2 == 0) {
      // Linear: d(s) = e1 w (s - s0) + e2 R.
      const double w = 0.5 + (u(rng) + 1.0);
      b.position = a.position + e1 * (-w * s0) + e2 * R;
      b.velocity = a.velocity + e1 * w;
    } else {
      // Quartic: d(s) = e1 g(s) + e2 R with g(s) = (k/2)(s - s0)(s - s1), s1 < 0.
      const double k = 0.5 + (u(rng) + 1.0), s1 = -1.0 - (u(rng) + 1.0);
      a.acceleration = Vec3(u(rng), u(rng), u(rng));
      b.position = a.position + e1 * (0.5 * k * s0 * s1) + e2 * R;
      b.velocity = a.velocity + e1 * (-0.5 * k * (s0 + s1));
      b.acceleration = a.acceleration + e1 * k;
    }
    const auto set = ccd::sphere_sphere_contact_intervals(a, b, S);
    INFO("case " << it);
    // Reference: minimise f in long double near s0 (f is convex there).
    long double lo = s0 - 1e-4L, hi = s0 + 1e-4L;
    for (int k = 0; k < 200; ++k) {
      const long double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      if (f_ref(a, b, m1) < f_ref(a, b, m2)) hi = m2; else lo = m1;
    }
    const long double fmin = f_ref(a, b, (lo + hi) / 2);
    REQUIRE(set.count <= 1);
    if (fmin > 1e-17L) {
      ++misses;
      CHECK(set.count == 0);
    } else if (fmin < -1e-17L) {
      ++crossings;
      REQUIRE(set.count == 1);
      CHECK(set.intervals[0].lo < set.intervals[0].hi);
      CHECK(set.intervals[0].lo == Approx(s0).margin(1e-6));
      CHECK(set.intervals[0].hi == Approx(s0).margin(1e-6));
    } else if (set.count == 1) {
      CHECK(set.intervals[0].lo == Approx(s0).margin(1e-6));
    }
  }
  // Both kinds occur in numbers (the rounding goes either way).
  CHECK(misses > 1000);
  CHECK(crossings > 1000);
}

}  // namespace ccd_queries_sphere_sphere_contact_test
