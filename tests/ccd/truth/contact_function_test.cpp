// The truth's definition of touching on constructions whose exact answer is known: every
// scene is built from dyadic numbers, so positions, velocities, radii, contact times and
// reflection times are exact doubles and the exact contact set follows by hand.
#include <ccd/truth/contact_function.hpp>
#include <ccd/truth/ground_truth.hpp>
#include <ccd/truth/pair_contact.hpp>

#include <tests/ccd/scene/body_builder.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

namespace ccd_truth_contact_function_test {

using ccd::Body;
using ccd::ContactInterval;
using ccd::Scene;
using ccd::Trajectories;
using ccd::Vec3;
using ccd::test::body;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Scene two_bodies(double horizon, const Body& a, const Body& b) {
  Scene s;
  s.horizon = horizon;
  s.bodies = {a, b};
  return s;
}

std::vector<ContactInterval> truth_of(const Scene& s) {
  const Trajectories t(s);
  std::vector<ContactInterval> out;
  ccd::pair_contact_intervals(t, 0, 1, 0.0, s.horizon, out);
  // The whole-scene truth must say the same.
  const std::vector<ccd::ContactEvent> events = ccd::compute_truth(t);
  REQUIRE(events.size() == out.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    CHECK(events[i].enter == out[i].enter);
    CHECK(events[i].exit == out[i].exit);
  }
  return out;
}

double step_ulps(double x, int k) {
  for (int i = 0; i < std::abs(k); ++i) x = std::nextafter(x, k > 0 ? kInf : -kInf);
  return x;
}

// A body at rest at (X, X, X) and one passing along +x at height h above it, closest at
// t = 1/2 (horizon 1): tangent when h == R, a near miss when h > R, a crossing of
// half-width sqrt(R^2 - h^2) / v when h < R.
Scene pass_by(double X, double r, double v, double y) {
  return two_bodies(1.0, body(r, Vec3(X, X, X)), body(r, Vec3(X - 0.5 * v, y, X), Vec3(v, 0, 0)));
}

}  // namespace

TEST_CASE("the contact band is the rounding of the data, not the motion over the radius", "[truth][band]") {
  SECTION("reproducer: radii 1e-3 passing 1e-6 apart at 1000 m/s is no contact") {
    // Used to give [0.5, 0.5]: the old band grew with |motion|^2 / R.
    const Scene s = two_bodies(1.0, body(0.001, Vec3(0, 0, 0)),
                               body(0.001, Vec3(-500, 0.002001, 0), Vec3(1000, 0, 0)));
    CHECK(truth_of(s).empty());
  }
  SECTION("near misses a few ulps away are separations, tangencies points, shallow crossings intervals") {
    const double X = GENERATE(0.0, 131072.0, 100000.0);  // 2^17 and 1e5: far from the origin
    const double r = GENERATE(0x1p-10, 0.5);
    const double v = GENERATE(1024.0, 1.0);
    CAPTURE(X, r, v);
    const double R = 2 * r;
    const double touch = X + R;  // exact
    // Tangent: exactly one point at t = 1/2.
    const auto tangent = truth_of(pass_by(X, r, v, touch));
    REQUIRE(tangent.size() == 1);
    CHECK(tangent[0].enter == 0.5);
    CHECK(tangent[0].exit == 0.5);
    for (int k = 1; k <= 4; ++k) {
      CAPTURE(k);
      // k ulps of the coordinates beyond touching: no contact.
      CHECK(truth_of(pass_by(X, r, v, step_ulps(touch, k))).empty());
      // k ulps inside: an interval around 1/2 of the exact half-width sqrt(R^2 - h^2) / v.
      const double y = step_ulps(touch, -k);
      const double h = y - X;  // exact (Sterbenz or X == 0)
      const auto cross = truth_of(pass_by(X, r, v, y));
      REQUIRE(cross.size() == 1);
      const long double half = std::sqrt(((long double)R - h) * ((long double)R + h)) / v;
      const double tol = 8 * std::numeric_limits<double>::epsilon() * 0.5 + 1e-6 * (double)half;
      CHECK(cross[0].enter < 0.5);
      CHECK(cross[0].exit > 0.5);
      CHECK(std::fabs(cross[0].enter - (0.5 - (double)half)) <= tol);
      CHECK(std::fabs(cross[0].exit - (0.5 + (double)half)) <= tol);
    }
  }
  SECTION("a crossing of depth 2^-31 near 1e5 is an interval of width 2^-16, not a point") {
    const double X = 100000.0;
    const double y = X + 1.0 - 0x1p-31;
    const auto iv = truth_of(pass_by(X, 0.5, 4.0, y));
    REQUIRE(iv.size() == 1);
    const long double h = 1.0L - 0x1p-31L;
    const long double half = std::sqrt((1.0L - h) * (1.0L + h)) / 4.0L;
    CHECK(iv[0].exit - iv[0].enter == Approx(double(2 * half)).epsilon(1e-9));
    CHECK(iv[0].exit - iv[0].enter == Approx(0x1p-16).epsilon(1e-9));
  }
  SECTION("long segments: horizon 64 at 1024 m/s, a gap of 2.25 radii sums is no contact") {
    const double r = 0x1p-10, R = 2 * r, v = 1024.0;
    auto scene = [&](double h) {
      return two_bodies(64.0, body(r, Vec3(0, 0, 0)), body(r, Vec3(-32.0 * v, h, 0), Vec3(v, 0, 0)));
    };
    CHECK(truth_of(scene(3.25 * R)).empty());
    CHECK(truth_of(scene(std::nextafter(R, kInf))).empty());
    const auto t = truth_of(scene(R));
    REQUIRE(t.size() == 1);
    CHECK(t[0].enter == 32.0);
    CHECK(t[0].exit == 32.0);
  }
  SECTION("separating over a long horizon is never touching") {
    // Two spheres 5 apart separating at 10 m/s over 1e7 s.
    const Scene s = two_bodies(1e7, body(1.0, Vec3(0, 0, 0)), body(1.0, Vec3(5, 0, 0), Vec3(10, 0, 0)));
    CHECK(truth_of(s).empty());
  }
}

TEST_CASE("contacts that begin, end or touch exactly at a piece break are exact", "[truth][breaks]") {
  SECTION("reproducer: touching a neighbour exactly at a floor bounce (t = 1 + 2^-16) is a point") {
    // y0 = 0.5 + 2^-13 (1 + 2^-16)^2 falls at 2^-12 onto the plane y = 0.5 at t = 1 + 2^-16,
    // exactly when it is at distance 1 = R from its neighbour. Used to give
    // [0.99997210, 1.00005842].
    Scene s = two_bodies(2.0, body(0.5, Vec3(1, 0.5001220740378187, 2), Vec3::Zero(), Vec3(0, -0x1p-12, 0)),
                         body(0.5, Vec3(2, 0.5, 2)));
    s.box = ccd::WallBox{Vec3(0, 0, 0), Vec3(4, 4, 4)};
    REQUIRE(0.5001220740378187 == 0.5 + 0x1p-13 + 0x1p-28 + 0x1p-45);
    const auto iv = truth_of(s);
    REQUIRE(iv.size() == 1);
    CHECK(iv[0].enter == 1.0 + 0x1p-16);
    CHECK(iv[0].exit == 1.0 + 0x1p-16);
    const Trajectories t(s);
    REQUIRE(t.pieces(0).size() == 2);
    CHECK(t.pieces(0)[0].t1 == 1.0 + 0x1p-16);  // the exact reflection time
    // The runner's sample test agrees: no sample near the bounce touches but the bounce itself.
    CHECK_FALSE(ccd::in_contact(t, 0, 1, 1.0));
    CHECK_FALSE(ccd::in_contact(t, 0, 1, 1.0 + 0x1p-17));
    CHECK(ccd::in_contact(t, 0, 1, 1.0 + 0x1p-16));
    CHECK_FALSE(ccd::in_contact(t, 0, 1, 1.0 + 0x1p-16 + 0x1p-30));
  }
  SECTION("contact beginning exactly at a floor bounce") {
    // A: falls from 0.625 at 1/4 m/s^2 onto y = 0.5 at t = 1 while moving +x at 1 m/s; at
    // t = 1 it is exactly R = 1 from B (resting on the floor) and moving into it.
    Scene s = two_bodies(2.0, body(0.5, Vec3(1, 0.625, 4), Vec3(1, 0, 0), Vec3(0, -0.25, 0)),
                         body(0.5, Vec3(3, 0.5, 4)));
    s.box = ccd::WallBox{Vec3(0, 0, 0), Vec3(8, 8, 8)};
    const auto iv = truth_of(s);
    REQUIRE(iv.size() == 1);
    CHECK(iv[0].enter == 1.0);
    CHECK(iv[0].exit > 1.0);
  }
  SECTION("tangent exactly at an acceleration change") {
    // A passes B at height 1 = R at t = 1/2 and then curves away: a point.
    Body a = body(0.5, Vec3(-1, 1, 0), Vec3(2, 0, 0));
    a.acceleration_changes.push_back({0.5, Vec3(0, 0.0625, 0)});
    const auto iv = truth_of(two_bodies(1.0, a, body(0.5, Vec3(0, 0, 0))));
    REQUIRE(iv.size() == 1);
    CHECK(iv[0].enter == 0.5);
    CHECK(iv[0].exit == 0.5);
  }
  SECTION("contact beginning exactly at an acceleration change") {
    // Slow pass at height R until t = 1/2, then pulled down into B: contact from 1/2 on.
    Body a = body(0.5, Vec3(-0x1p-7, 1, 0), Vec3(0x1p-6, 0, 0));
    a.acceleration_changes.push_back({0.5, Vec3(0, -1, 0)});
    const auto iv = truth_of(two_bodies(1.0, a, body(0.5, Vec3(0, 0, 0))));
    REQUIRE(iv.size() == 1);
    CHECK(iv[0].enter == 0.5);
    CHECK(iv[0].exit > 0.5);
  }
  SECTION("tangent at t = 0 and at t = T") {
    // Closest approach (distance exactly R) at the first and at the last instant.
    const auto start = truth_of(two_bodies(1.0, body(0.5, Vec3(0, 0, 0)), body(0.5, Vec3(0, 1, 0), Vec3(1, 0, 0))));
    REQUIRE(start.size() == 1);
    CHECK(start[0].enter == 0.0);
    CHECK(start[0].exit == 0.0);
    const auto end = truth_of(two_bodies(1.0, body(0.5, Vec3(0, 0, 0)), body(0.5, Vec3(-1, 1, 0), Vec3(1, 0, 0))));
    REQUIRE(end.size() == 1);
    CHECK(end[0].enter == 1.0);
    CHECK(end[0].exit == 1.0);
  }
  SECTION("touching throughout: moving side by side at exactly R is one interval, not points") {
    const auto iv = truth_of(
        two_bodies(1.0, body(0.5, Vec3(0, 0, 0), Vec3(3, 0, 0)), body(0.5, Vec3(0, 1, 0), Vec3(3, 0, 0))));
    REQUIRE(iv.size() == 1);
    CHECK(iv[0].enter == 0.0);
    CHECK(iv[0].exit == 1.0);
  }
  SECTION("radii whose sum is not a double") {
    // 0.1 + 0.2 rounds up; the exact sum is used. Centres exactly fl(0.1 + 0.2) apart are
    // farther than the exact sum: no contact.
    const double d = 0.1 + 0.2;
    REQUIRE((long double)d > (long double)0.1 + (long double)0.2);
    const auto iv = truth_of(two_bodies(1.0, body(0.1, Vec3(0, 0, 0)), body(0.2, Vec3(d, 0, 0))));
    CHECK(iv.empty());
  }
}

TEST_CASE("the sample test is the truth's definition of touching", "[truth][band]") {
  // Random dyadic passes: at every sample time, in_contact agrees with membership in a
  // truth interval.
  for (int k = -3; k <= 3; ++k) {
    CAPTURE(k);
    const Scene s = pass_by(0.0, 0.5, 1.0, step_ulps(1.0, k));
    const Trajectories t(s);
    std::vector<ContactInterval> iv;
    ccd::pair_contact_intervals(t, 0, 1, 0.0, 1.0, iv);
    for (int j = 0; j <= 256; ++j) {
      const double x = j / 256.0;
      bool inside = false;
      for (const ContactInterval& c : iv) inside = inside || (c.enter <= x && x <= c.exit);
      CAPTURE(x);
      CHECK(ccd::in_contact(t, 0, 1, x) == inside);
    }
  }
}

}  // namespace ccd_truth_contact_function_test
