#include <ccd/queries/polynomial_roots.hpp>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

namespace ccd_queries_polynomial_roots_test {

using ccd::Polynomial;
using ccd::SublevelSet;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Expands prod (x - r_i) times lead.
Polynomial from_roots(double lead, const std::vector<double>& roots) {
  Polynomial p;
  p.c[0] = lead;
  for (double r : roots) {
    Polynomial q;
    for (int i = 0; i < 4; ++i) q.c[i + 1] = p.c[i];
    for (int i = 0; i <= 4; ++i) q.c[i] -= r * p.c[i];
    p = q;
  }
  return p;
}

// First-order error of a simple root: the evaluation rounding band divided by |p'(r)|,
// plus one ulp of the range for the final bracket.
double root_tolerance(const Polynomial& p, double r, double lo, double hi) {
  return ccd::polynomial_rounding_bound(p, lo, hi) / std::fabs(p.derivative()(r)) +
         4.0 * kEps * std::max(std::fabs(lo), std::fabs(hi));
}

}  // namespace

TEST_CASE("sublevel sets of hand-worked polynomials", "[queries][roots]") {
  SECTION("quadratic with two simple roots: (x-1)(x-3) <= 0 on [0,4] is [1,3]") {
    const Polynomial p = from_roots(1.0, {1.0, 3.0});
    const SublevelSet s = ccd::polynomial_sublevel_set(p, 0.0, 4.0, ccd::polynomial_rounding_bound(p, 0, 4));
    REQUIRE(s.count == 1);
    CHECK(s.intervals[0].lo == Approx(1.0).margin(root_tolerance(p, 1.0, 0, 4)));
    CHECK(s.intervals[0].hi == Approx(3.0).margin(root_tolerance(p, 3.0, 0, 4)));
    CHECK(p(s.intervals[0].lo) <= 0.0);  // boundaries on the side where p <= 0
    CHECK(p(s.intervals[0].hi) <= 0.0);
  }
  SECTION("tangent: (x-2)^2 touches zero at 2 only") {
    const Polynomial p = from_roots(1.0, {2.0, 2.0});
    const SublevelSet s = ccd::polynomial_sublevel_set(p, 0.0, 4.0, ccd::polynomial_rounding_bound(p, 0, 4));
    REQUIRE(s.count == 1);
    CHECK(s.intervals[0].lo == s.intervals[0].hi);
    CHECK(s.intervals[0].lo == Approx(2.0).margin(4 * kEps * 4));
  }
  SECTION("tangent with rounding: (x - 0.1)^2 has an inexact vertex value") {
    const Polynomial p = from_roots(1.0, {0.1, 0.1});
    const SublevelSet s = ccd::polynomial_sublevel_set(p, 0.0, 1.0, ccd::polynomial_rounding_bound(p, 0, 1));
    REQUIRE(s.count == 1);
    CHECK(s.intervals[0].lo == s.intervals[0].hi);
    CHECK(s.intervals[0].lo == Approx(0.1).margin(16 * kEps));
  }
  SECTION("quartic with four simple roots gives two intervals") {
    const Polynomial p = from_roots(1.0, {1.0, 2.0, 3.0, 4.0});
    const SublevelSet s = ccd::polynomial_sublevel_set(p, 0.0, 5.0, ccd::polynomial_rounding_bound(p, 0, 5));
    REQUIRE(s.count == 2);
    const double want[4] = {1, 2, 3, 4};
    for (int k = 0; k < 4; ++k) {
      const double got = k % 2 == 0 ? s.intervals[k / 2].lo : s.intervals[k / 2].hi;
      CHECK(got == Approx(want[k]).margin(root_tolerance(p, want[k], 0, 5)));
    }
  }
  SECTION("quartic with two double roots: two touching points") {
    const Polynomial p = from_roots(1.0, {1.0, 1.0, 3.0, 3.0});
    const SublevelSet s = ccd::polynomial_sublevel_set(p, 0.0, 4.0, ccd::polynomial_rounding_bound(p, 0, 4));
    REQUIRE(s.count == 2);
    CHECK(s.intervals[0].lo == s.intervals[0].hi);
    CHECK(s.intervals[1].lo == s.intervals[1].hi);
    // The critical points are refined to a few ulps of the range.
    CHECK(s.intervals[0].lo == Approx(1.0).margin(64 * kEps * 4));
    CHECK(s.intervals[1].lo == Approx(3.0).margin(64 * kEps * 4));
  }
  SECTION("negative leading coefficient: -(x-1)(x-3) <= 0 on [0,4] is [0,1] and [3,4]") {
    const Polynomial p = from_roots(-1.0, {1.0, 3.0});
    const SublevelSet s = ccd::polynomial_sublevel_set(p, 0.0, 4.0, ccd::polynomial_rounding_bound(p, 0, 4));
    REQUIRE(s.count == 2);
    CHECK(s.intervals[0].lo == 0.0);
    CHECK(s.intervals[1].hi == 4.0);
    CHECK(s.intervals[0].hi == Approx(1.0).margin(root_tolerance(p, 1.0, 0, 4)));
    CHECK(s.intervals[1].lo == Approx(3.0).margin(root_tolerance(p, 3.0, 0, 4)));
  }
  SECTION("three components: -(x-1)(x-3)^2(x-5) <= 0 has [0,1], {3} and [5,6]") {
    const Polynomial p = from_roots(-1.0, {1.0, 3.0, 3.0, 5.0});
    const SublevelSet s = ccd::polynomial_sublevel_set(p, 0.0, 6.0, ccd::polynomial_rounding_bound(p, 0, 6));
    REQUIRE(s.count == 3);
    CHECK(s.intervals[0].lo == 0.0);
    CHECK(s.intervals[1].lo == s.intervals[1].hi);
    CHECK(s.intervals[1].lo == Approx(3.0).margin(64 * kEps * 6));
    CHECK(s.intervals[2].hi == 6.0);
  }
  SECTION("constants and the zero polynomial") {
    Polynomial zero;
    SublevelSet s = ccd::polynomial_sublevel_set(zero, 0.0, 2.0, 0.0);
    REQUIRE(s.count == 1);
    CHECK((s.intervals[0].lo == 0.0 && s.intervals[0].hi == 2.0));
    Polynomial pos;
    pos.c[0] = 1.0;
    CHECK(ccd::polynomial_sublevel_set(pos, 0.0, 2.0, 0.5).count == 0);
    CHECK(ccd::polynomial_roots(zero, 0.0, 2.0, 0.0).count == 0);
  }
  SECTION("empty and single-point ranges") {
    const Polynomial p = from_roots(1.0, {1.0, 3.0});
    CHECK(ccd::polynomial_sublevel_set(p, 3.0, 2.0, 0.0).count == 0);
    const SublevelSet s = ccd::polynomial_sublevel_set(p, 2.0, 2.0, 0.0);
    REQUIRE(s.count == 1);
    CHECK((s.intervals[0].lo == 2.0 && s.intervals[0].hi == 2.0));
  }
  SECTION("a root just outside the range is not reported, the touching boundary is") {
    const Polynomial p = from_roots(1.0, {-1.0, 0.0});  // x (x+1): zero at 0, increasing
    const SublevelSet s = ccd::polynomial_sublevel_set(p, 0.0, 1.0, ccd::polynomial_rounding_bound(p, 0, 1));
    REQUIRE(s.count == 1);
    CHECK((s.intervals[0].lo == 0.0 && s.intervals[0].hi == 0.0));
  }
}

TEST_CASE("real roots with multiplicity flags", "[queries][roots]") {
  const Polynomial p = from_roots(1.0, {0.5, 2.0, 2.0, 3.5});
  const ccd::RealRoots r = ccd::polynomial_roots(p, 0.0, 4.0, ccd::polynomial_rounding_bound(p, 0, 4));
  REQUIRE(r.count == 3);
  CHECK(r.x[0] == Approx(0.5).margin(root_tolerance(p, 0.5, 0, 4)));
  CHECK(!r.touching[0]);
  CHECK(r.x[1] == Approx(2.0).margin(64 * kEps * 4));
  CHECK(r.touching[1]);
  CHECK(r.x[2] == Approx(3.5).margin(root_tolerance(p, 3.5, 0, 4)));
  CHECK(!r.touching[2]);
}

TEST_CASE("random quartics with known roots", "[queries][roots]") {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> root(0.0, 1.0);
  std::uniform_real_distribution<double> lead(0.1, 10.0);
  int checked = 0;
  for (int it = 0; it < 20000; ++it) {
    std::vector<double> r = {root(rng), root(rng), root(rng), root(rng)};
    std::sort(r.begin(), r.end());
    // Keep the roots apart so that each is well conditioned (its tolerance is first order).
    bool apart = true;
    for (int k = 0; k < 3; ++k) apart = apart && r[k + 1] - r[k] > 0.02;
    if (!apart) continue;
    const Polynomial p = from_roots(lead(rng), r);
    const double tol = ccd::polynomial_rounding_bound(p, 0.0, 1.0);
    const SublevelSet s = ccd::polynomial_sublevel_set(p, 0.0, 1.0, tol);
    REQUIRE(s.count == 2);
    const double got[4] = {s.intervals[0].lo, s.intervals[0].hi, s.intervals[1].lo, s.intervals[1].hi};
    for (int k = 0; k < 4; ++k) {
      REQUIRE(got[k] == Approx(r[k]).margin(root_tolerance(p, r[k], 0.0, 1.0)));
      REQUIRE(p(got[k]) <= 0.0);
    }
    const ccd::RealRoots rr = ccd::polynomial_roots(p, 0.0, 1.0, tol);
    REQUIRE(rr.count == 4);
    for (int k = 0; k < 4; ++k) REQUIRE(rr.x[k] == Approx(r[k]).margin(root_tolerance(p, r[k], 0.0, 1.0)));
    ++checked;
  }
  CHECK(checked > 1000);
}

}  // namespace ccd_queries_polynomial_roots_test
