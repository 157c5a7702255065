#include <ccd/queries/segment_segment.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

namespace ccd_queries_segment_segment_test {

using ccd::SegmentSegmentResult;
using ccd::Vec3;
using Status = SegmentSegmentResult::Status;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
using LVec = Eigen::Matrix<long double, 3, 1>;

// Reference in long double: g(t) = min_s |S1(s) - S2(t)|^2 (best s in closed form) is
// convex, so a ternary search over t finds its minimum.
long double reference_distance_squared(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
  const LVec P1 = p1.cast<long double>(), D1 = (q1.cast<long double>() - P1);
  const LVec P2 = p2.cast<long double>(), D2 = (q2.cast<long double>() - P2);
  const long double a = D1.dot(D1);
  const auto g = [&](long double t) {
    const LVec x = P2 + D2 * t;
    long double s = a > 0 ? (x - P1).dot(D1) / a : 0.0L;
    s = std::clamp(s, 0.0L, 1.0L);
    return (P1 + D1 * s - x).squaredNorm();
  };
  long double lo = 0, hi = 1;
  for (int i = 0; i < 200; ++i) {
    const long double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (g(m1) <= g(m2)) hi = m2; else lo = m1;
  }
  return std::min({g(lo), g(0), g(1)});
}

// The result's distance must match the reference to a few ulps of the magnitudes in the
// squared distance: 64 eps (|d1|^2 + |d2|^2 + |p1 - p2|^2) bounds the rounding of the
// double computation (each term is formed with a handful of roundings).
void check_against_reference(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
  const SegmentSegmentResult r = ccd::segment_segment_closest(p1, q1, p2, q2);
  const long double ref = reference_distance_squared(p1, q1, p2, q2);
  const double tol = 64 * eps * ((q1 - p1).squaredNorm() + (q2 - p2).squaredNorm() + (p1 - p2).squaredNorm());
  INFO("p1 " << p1.transpose() << " q1 " << q1.transpose() << " p2 " << p2.transpose() << " q2 " << q2.transpose());
  CHECK(r.s >= 0.0);
  CHECK(r.s <= 1.0);
  CHECK(r.t >= 0.0);
  CHECK(r.t <= 1.0);
  CHECK(std::abs(static_cast<long double>(r.distance_squared) - ref) <= tol);
  CHECK((r.closest1 - r.closest2).squaredNorm() == r.distance_squared);
}

}  // namespace

TEST_CASE("segment_segment_closest on named configurations", "[queries][segment_segment]") {
  SECTION("crossing: distance 0 at the crossing point") {
    const auto r = ccd::segment_segment_closest(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 1, 0));
    CHECK(r.status == Status::Unique);
    CHECK(r.distance_squared == 0.0);
    CHECK(r.s == 0.5);
    CHECK(r.t == 0.5);
  }
  SECTION("skew: closest points interior, distance 2") {
    const auto r = ccd::segment_segment_closest(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 2), Vec3(0, 1, 2));
    CHECK(r.distance_squared == 4.0);
    CHECK(r.closest1 == Vec3(0, 0, 0));
    CHECK(r.closest2 == Vec3(0, 0, 2));
  }
  SECTION("T-shape: the stem's end touches the bar's middle") {
    const auto r = ccd::segment_segment_closest(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, 3, 0), Vec3(0, 1, 0));
    CHECK(r.distance_squared == 1.0);  // stem end (0, 1, 0) to bar point (0, 0, 0)
    CHECK(r.t == 1.0);
    CHECK(r.s == 0.5);
  }
  SECTION("the t > 1 branch: clamping t at 1 moves s") {
    // Second segment ends before the foot of the first's closest point.
    const auto r = ccd::segment_segment_closest(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(-3, 1, 0), Vec3(-1, 1, 0));
    CHECK(r.t == 1.0);
    CHECK(r.s == 0.0);
    CHECK(r.distance_squared == 2.0);
  }
  SECTION("parallel, offset: distance 1, smallest t among the minimisers") {
    const auto r = ccd::segment_segment_closest(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(1, 1, 0), Vec3(3, 1, 0));
    CHECK(r.status == Status::Parallel);
    CHECK(r.distance_squared == 1.0);
    CHECK(r.t == 0.0);  // every t in [0, 1] is a minimiser: the deterministic choice is t = 0
    CHECK(r.s == 0.25);
  }
  SECTION("anti-parallel overlapping") {
    const auto r = ccd::segment_segment_closest(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(3, 2, 0), Vec3(1, 2, 0));
    CHECK(r.status == Status::Parallel);
    CHECK(r.distance_squared == 4.0);
    CHECK(r.t == 0.0);
    CHECK(r.s == 0.75);
  }
  SECTION("parallel, disjoint along the line: end points are closest") {
    const auto r = ccd::segment_segment_closest(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(3, 1, 0), Vec3(5, 1, 0));
    CHECK(r.distance_squared == 5.0);  // (1,0,0) to (3,1,0)
    CHECK(r.s == 1.0);
    CHECK(r.t == 0.0);
  }
  SECTION("collinear overlapping: distance 0") {
    const auto r = ccd::segment_segment_closest(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(2, 0, 0), Vec3(6, 0, 0));
    CHECK(r.distance_squared == 0.0);
    CHECK(r.t == 0.0);
    CHECK(r.s == 0.5);
  }
  SECTION("zero-length first segment") {
    const auto r = ccd::segment_segment_closest(Vec3(1, 2, 0), Vec3(1, 2, 0), Vec3(0, 0, 0), Vec3(4, 0, 0));
    CHECK(r.status == Status::Degenerate);
    CHECK(r.s == 0.0);
    CHECK(r.t == 0.25);
    CHECK(r.distance_squared == 4.0);
  }
  SECTION("zero-length second segment beyond the first's end") {
    const auto r = ccd::segment_segment_closest(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(6, 0, 0), Vec3(6, 0, 0));
    CHECK(r.status == Status::Degenerate);
    CHECK(r.s == 1.0);
    CHECK(r.distance_squared == 4.0);
  }
  SECTION("both zero-length") {
    const auto r = ccd::segment_segment_closest(Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 3), Vec3(1, 1, 3));
    CHECK(r.status == Status::Degenerate);
    CHECK(r.distance_squared == 4.0);
  }
  SECTION("near-parallel (angle 1e-9): matches the long-double reference") {
    for (const double ang : {1e-9, 1e-12, 1e-6}) {
      check_against_reference(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.3, 1e-3, 0), Vec3(1.3, 1e-3 + ang, 0));
      check_against_reference(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1.3, 1e-3 + ang, 0), Vec3(0.3, 1e-3, 0));
      check_against_reference(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(-0.5, 0, 1e-3), Vec3(0.5, ang, 1e-3));
    }
  }
  SECTION("far from the origin (~1e6)") {
    const Vec3 o(1e6, -1e6, 1e6);
    const auto r = ccd::segment_segment_closest(o + Vec3(-1, 0, 0), o + Vec3(1, 0, 0), o + Vec3(0, -1, 0.5),
                                                o + Vec3(0, 1, 0.5));
    CHECK(r.distance_squared == Approx(0.25).epsilon(1e-9));  // absolute rounding ~ eps * 1e6
    check_against_reference(o + Vec3(-1, 0, 0), o + Vec3(1, 0, 0), o + Vec3(0.2, -1, 0.5), o + Vec3(0.3, 1, 0.5));
    check_against_reference(o, o + Vec3(1, 0, 0), o + Vec3(0.5, 0.1, 0), o + Vec3(1.5, 0.1 + 1e-9, 0));
  }
}

TEST_CASE("segment_segment_closest matches the long-double reference on random segments",
          "[queries][segment_segment]") {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 4000; ++i) {
    const Vec3 p1(u(rng), u(rng), u(rng)), q1(u(rng), u(rng), u(rng));
    Vec3 p2(u(rng), u(rng), u(rng)), q2(u(rng), u(rng), u(rng));
    switch (i % 4) {
      case 1: q2 = p2 + (q1 - p1) * (2 * u(rng)) + Vec3(u(rng), u(rng), u(rng)) * 1e-10; break;  // near-parallel
      case 2: q2 = p2; break;                                                                   // point
      default: break;
    }
    check_against_reference(p1, q1, p2, q2);
    check_against_reference(p2, q2, p1, q1);  // swapped roles
  }
}

}  // namespace ccd_queries_segment_segment_test
