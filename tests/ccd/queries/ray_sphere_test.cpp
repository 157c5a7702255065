#include <ccd/queries/ray_sphere.hpp>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

namespace ccd_queries_ray_sphere_test {

using ccd::RaySphereStatus;
using ccd::Vec3;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double inf = std::numeric_limits<double>::infinity();

/// The query's documented tolerance (a length), see ray_sphere.hpp.
double tol_of(const Vec3& o, const Vec3& c) {
  return ccd::ray_sphere_tolerance_factor * eps * (o - c).cwiseAbs().maxCoeff();
}

/// Long double reference (64-bit significand on x86-64: about 2000 times more precise
/// than double), exact classification of the given doubles up to its own rounding.
struct Reference {
  RaySphereStatus status = RaySphereStatus::Miss;
  long double toi = 0;
  long double dist0 = 0;  // signed distance of the origin from the surface
  long double h = 0;      // distance of the centre from the line
  long double bhat = 0;   // -(m . d) / |d|: approach speed along the line, in length units
  long double w = 0;      // half chord (0 when the line misses)
  long double m = 0;      // |origin - centre|
};

Reference reference(const Vec3& o, const Vec3& d, const Vec3& c, double radius, double t_max) {
  Reference r;
  long double m[3], dd[3];
  long double mm = 0, a = 0, b = 0;
  for (int i = 0; i < 3; ++i) {
    m[i] = static_cast<long double>(o[i]) - static_cast<long double>(c[i]);
    dd[i] = d[i];
    mm += m[i] * m[i];
    a += dd[i] * dd[i];
    b += m[i] * dd[i];
  }
  const long double R = radius;
  r.m = std::sqrt(mm);
  r.dist0 = r.m - R;
  if (mm < R * R) {
    r.status = RaySphereStatus::Overlapping;
    return r;
  }
  if (mm == R * R) {
    r.status = RaySphereStatus::Hit;
    return r;
  }
  if (a == 0) {
    r.status = RaySphereStatus::Degenerate;
    return r;
  }
  long double h2 = 0;
  for (int i = 0; i < 3; ++i) {
    const long double e = m[i] - (b / a) * dd[i];
    h2 += e * e;
  }
  r.h = std::sqrt(h2);
  r.bhat = -b / std::sqrt(a);
  if (b >= 0 || h2 > R * R) {
    r.status = RaySphereStatus::Miss;
    return r;
  }
  const long double w2 = R * R - h2;
  r.w = std::sqrt(w2);
  r.toi = (mm - R * R) / (-b + std::sqrt(a * w2));
  r.status = r.toi <= t_max ? RaySphereStatus::Hit : RaySphereStatus::Miss;
  return r;
}

/// Bound on |toi - t*| |d| for a Hit outside the tangency band, from the error analysis of
/// t = k / q (docs/queries.md): k = |m|^2 - R^2 carries ~4.5 eps |m|^2, -b ~4 eps |m||d|,
/// sqrt(a w2) ~6 eps |d| R |m| / w. Each coefficient is rounded up to 8.
double toi_bound(const Reference& r, double radius) {
  const long double m = r.m;
  return static_cast<double>(8.0L * eps * (m * m / (r.bhat + r.w) + m + radius * m / r.w));
}

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Vec3 v;
  do {
    v = Vec3(n(rng), n(rng), n(rng));
  } while (v.norm() < 1e-3);
  return v.normalized();
}

}  // namespace

TEST_CASE("ray_sphere hand-worked hits", "[queries][ray_sphere]") {
  const Vec3 c = Vec3::Zero();
  SECTION("head-on: t = |m| - R, exact in binary") {
    // m = (-5,0,0), b = -5, h = 0, q = 5 + 1, t = 24 / 6 = 4.
    const auto r = ccd::ray_sphere(Vec3(-5, 0, 0), Vec3(1, 0, 0), c, 1.0, inf);
    REQUIRE(r.status == RaySphereStatus::Hit);
    CHECK(r.toi == 4.0);
    CHECK(r.normal == Vec3(-1, 0, 0));
  }
  SECTION("direction length scales t: speed 2 reaches the surface at t = 2") {
    const auto r = ccd::ray_sphere(Vec3(-5, 0, 0), Vec3(2, 0, 0), c, 1.0, inf);
    REQUIRE(r.status == RaySphereStatus::Hit);
    CHECK(r.toi == 2.0);
  }
  SECTION("off-axis: h = 0.6, half chord 0.8, t = 5 - 0.8, normal (-0.8, 0.6, 0)") {
    const auto r = ccd::ray_sphere(Vec3(-5, 0.6, 0), Vec3(1, 0, 0), c, 1.0, inf);
    REQUIRE(r.status == RaySphereStatus::Hit);
    // A handful of roundings on quantities of size <= 25: 16 eps relative is generous
    // but still 1e6 times tighter than any wrong formula.
    CHECK(r.toi == Approx(4.2).epsilon(16 * eps));
    CHECK(r.normal.x() == Approx(-0.8).epsilon(16 * eps));
    CHECK(r.normal.y() == Approx(0.6).epsilon(16 * eps));
    CHECK(r.normal.z() == 0.0);
    CHECK(r.normal.norm() == Approx(1.0).epsilon(4 * eps));
  }
  SECTION("sphere away from the coordinate origin, oblique direction") {
    // Centre (1,2,3), R = 5, d = (3,4,0) (unit u = (0.6,0.8,0), |d| = 5), p = (-0.8,0.6,0).
    // m = -10 u + 3 p = (-8.4,-6.2,0): h = 3, half chord 4, entry 10 - 4 = 6 along the
    // line, t = 6 / 5 = 1.2; contact m + t d = (-4.8,-1.4,0), normal (-0.96,-0.28,0).
    // The decimal inputs are rounded (relative eps / 2 on |m| = 10.4), and the root's
    // sensitivity is about |m| (1 + R/w) / |d| = 4.7: 32 eps relative covers both.
    const Vec3 cc(1, 2, 3);
    const auto r = ccd::ray_sphere(Vec3(-7.4, -4.2, 3), Vec3(3, 4, 0), cc, 5.0, inf);
    REQUIRE(r.status == RaySphereStatus::Hit);
    CHECK(r.toi == Approx(1.2).epsilon(32 * eps));
    CHECK(r.normal.x() == Approx(-0.96).epsilon(32 * eps));
    CHECK(r.normal.y() == Approx(-0.28).epsilon(64 * eps));
    CHECK(r.normal.z() == 0.0);
  }
  SECTION("range: contact exactly at t_max is a hit, t_max just below is a miss") {
    auto r = ccd::ray_sphere(Vec3(-5, 0, 0), Vec3(1, 0, 0), c, 1.0, 4.0);
    REQUIRE(r.status == RaySphereStatus::Hit);
    CHECK(r.toi == 4.0);
    r = ccd::ray_sphere(Vec3(-5, 0, 0), Vec3(1, 0, 0), c, 1.0, std::nextafter(4.0, 0.0));
    CHECK(r.status == RaySphereStatus::Miss);
    CHECK(r.toi == inf);
    r = ccd::ray_sphere(Vec3(-5, 0, 0), Vec3(1, 0, 0), c, 1.0, 0.0);
    CHECK(r.status == RaySphereStatus::Miss);
  }
  SECTION("behind the origin and moving away: miss") {
    auto r = ccd::ray_sphere(Vec3(5, 0, 0), Vec3(1, 0, 0), c, 1.0, inf);
    CHECK(r.status == RaySphereStatus::Miss);
    CHECK(r.toi == inf);
    CHECK(r.normal == Vec3::Zero());
    // Perpendicular to m (b = 0) and outside: the distance only grows.
    r = ccd::ray_sphere(Vec3(5, 0, 0), Vec3(0, 1, 0), c, 1.0, inf);
    CHECK(r.status == RaySphereStatus::Miss);
  }
  SECTION("clear miss: line 2 away from a unit sphere") {
    const auto r = ccd::ray_sphere(Vec3(-5, 2, 0), Vec3(1, 0, 0), c, 1.0, inf);
    CHECK(r.status == RaySphereStatus::Miss);
  }
}

TEST_CASE("ray_sphere degenerate cases", "[queries][ray_sphere]") {
  const Vec3 c = Vec3::Zero();
  SECTION("tangent: exact grazing is a hit at the tangency point") {
    // Line y = 1 against the unit sphere: h = R exactly, D = 0, t = 5 exactly.
    auto r = ccd::ray_sphere(Vec3(-5, 1, 0), Vec3(1, 0, 0), c, 1.0, inf);
    REQUIRE(r.status == RaySphereStatus::Hit);
    CHECK(r.toi == 5.0);
    CHECK(r.normal == Vec3(0, 1, 0));
    // Oblique, all exact: R = 5, tangent point (3,4,0), direction (4,-3,0), origin two
    // direction lengths before it: m.m = 125, b = -50, a = 25, e = m + 2 d = (3,4,0).
    r = ccd::ray_sphere(Vec3(-5, 10, 0), Vec3(4, -3, 0), c, 5.0, inf);
    REQUIRE(r.status == RaySphereStatus::Hit);
    CHECK(r.toi == 2.0);
    // The normal is p / R renormalised by a Newton step: unit within a few eps.
    CHECK((r.normal - Vec3(0.6, 0.8, 0)).norm() <= 4 * eps);
  }
  SECTION("tangent in random directions: always a hit, t at the tangency point") {
    // The inputs are rounded, so the exact line passes within a few eps |m| of tangency:
    // the tolerance band (tol = 16 eps max|m_i|) must report every one as a hit. The
    // root of a near-double root moves by sqrt(2 R tol) / |d| at most (the half chord of
    // a line tol inside the sphere), plus the ordinary rounding of t.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    for (int n = 0; n < 2000; ++n) {
      const Vec3 cc(10 * U(rng), 10 * U(rng), 10 * U(rng));
      const double R = std::exp2(4 * U(rng));
      const Vec3 p = random_unit(rng);
      const Vec3 u = (random_unit(rng) - p * p.dot(random_unit(rng))).normalized();
      const Vec3 dir = u - p * p.dot(u);  // perpendicular to p
      const double speed = std::exp2(6 * U(rng));
      const double s = 1.0 + 4.0 * (U(rng) + 1.0);  // distance before the tangent point
      const Vec3 d = dir.normalized() * speed;
      const Vec3 o = cc + R * p - s * dir.normalized();
      const auto r = ccd::ray_sphere(o, d, cc, R, inf);
      INFO("case " << n);
      REQUIRE(r.status == RaySphereStatus::Hit);
      const double t_tan = s / speed;
      const double band = std::sqrt(2 * R * tol_of(o, cc)) + 8 * eps * (o - cc).norm();
      CHECK(std::abs(r.toi - t_tan) * speed <= band);
      CHECK(std::abs(r.normal.dot(p)) == Approx(1.0).margin(band / R));
    }
  }
  SECTION("just miss: 1 ulp outside is a grazing hit, beyond the band a miss") {
    // tol = 16 eps * 5 = 80 eps. y = 1 + eps (1 ulp above R = 1) is inside the band:
    // reported as grazing at the closest approach (conservative policy).
    auto r = ccd::ray_sphere(Vec3(-5, std::nextafter(1.0, 2.0), 0), Vec3(1, 0, 0), c, 1.0, inf);
    REQUIRE(r.status == RaySphereStatus::Hit);
    CHECK(r.toi == 5.0);
    // 1 ulp inside: a genuine, ill-conditioned hit, half chord sqrt(2 * eps/2) = 1.5e-8.
    r = ccd::ray_sphere(Vec3(-5, std::nextafter(1.0, 0.0), 0), Vec3(1, 0, 0), c, 1.0, inf);
    REQUIRE(r.status == RaySphereStatus::Hit);
    CHECK(r.toi <= 5.0);
    CHECK(r.toi == Approx(5.0 - std::sqrt(eps)).margin(std::sqrt(2 * 80 * eps)));
    // Twice the band outside: a miss.
    r = ccd::ray_sphere(Vec3(-5, 1.0 + 160 * eps, 0), Vec3(1, 0, 0), c, 1.0, inf);
    CHECK(r.status == RaySphereStatus::Miss);
    CHECK(r.toi == inf);
  }
  SECTION("origin on the surface, moving in, out or not at all: touching at t = 0") {
    // (3,4,0) is exactly on the sphere of radius 5.
    for (const Vec3& d : {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 1), Vec3(0, 0, 0)}) {
      const auto r = ccd::ray_sphere(Vec3(3, 4, 0), d, c, 5.0, 1.0);
      REQUIRE(r.status == RaySphereStatus::Hit);
      CHECK(r.toi == 0.0);
      CHECK(r.normal == Vec3(0.6, 0.8, 0));
    }
    // Rounding-level outside (1 ulp in x) and moving away: still touching at t = 0.
    const auto r = ccd::ray_sphere(Vec3(std::nextafter(3.0, 4.0), 4, 0), Vec3(1, 1, 0), c, 5.0, 1.0);
    REQUIRE(r.status == RaySphereStatus::Hit);
    CHECK(r.toi == 0.0);
  }
  SECTION("origin just outside the surface moving in: cancellation-free small root") {
    // Distance 1e-9 R outside, radially inward at unit speed: t = 1e-9 R up to the input
    // rounding; compare with the long double reference with the derived bound.
    const Vec3 p = Vec3(1, 2, 2) / 3.0;
    const double R = 3.0;
    const Vec3 o = p * (R * (1 + 1e-9));
    const Vec3 d = -p;
    const auto r = ccd::ray_sphere(o, d, c, R, inf);
    const Reference ref = reference(o, d, c, R, inf);
    REQUIRE(ref.status == RaySphereStatus::Hit);
    REQUIRE(r.status == RaySphereStatus::Hit);
    CHECK(std::abs(r.toi - static_cast<double>(ref.toi)) * d.norm() <= toi_bound(ref, R));
    CHECK(r.toi == Approx(3e-9).epsilon(1e-6));  // the input rounding is eps R / 3e-9 R
  }
  SECTION("origin just inside: overlapping") {
    const auto r = ccd::ray_sphere(Vec3(0, 0, 1 - 1e-9), Vec3(0, 0, 1), c, 1.0, inf);
    CHECK(r.status == RaySphereStatus::Overlapping);
    CHECK(r.toi == 0.0);
    CHECK(r.normal == Vec3::Zero());
  }
  SECTION("coincident: origin at the centre") {
    for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, 0, 0)}) {
      const auto r = ccd::ray_sphere(Vec3(1, 2, 3), d, Vec3(1, 2, 3), 0.5, 1.0);
      CHECK(r.status == RaySphereStatus::Overlapping);
      CHECK(r.toi == 0.0);
    }
    // A point sphere (R = 0) at the origin: touching, no normal exists.
    const auto r = ccd::ray_sphere(Vec3(1, 2, 3), Vec3(1, 0, 0), Vec3(1, 2, 3), 0.0, 1.0);
    CHECK(r.status == RaySphereStatus::Hit);
    CHECK(r.toi == 0.0);
    CHECK(r.normal == Vec3::Zero());
  }
  SECTION("point sphere (R = 0) on the line: hit when the ray passes through it") {
    const auto r = ccd::ray_sphere(Vec3(-2, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 0), 0.0, inf);
    REQUIRE(r.status == RaySphereStatus::Hit);
    CHECK(r.toi == 2.0);
    CHECK(ccd::ray_sphere(Vec3(-2, 1e-3, 0), Vec3(1, 0, 0), c, 0.0, inf).status == RaySphereStatus::Miss);
  }
  SECTION("tiny sphere (R = 1e-9 |m|): exact normalisation of the normal") {
    const auto r = ccd::ray_sphere(Vec3(-1, 0.6e-9, 0), Vec3(1, 0, 0), c, 1e-9, inf);
    REQUIRE(r.status == RaySphereStatus::Hit);
    CHECK(r.toi == Approx(1 - 0.8e-9).epsilon(4 * eps));
    CHECK(r.normal.norm() == Approx(1.0).epsilon(4 * eps));
    CHECK(r.normal.x() == Approx(-0.8).epsilon(1e-6));  // toi error eps / R: 1e-7 relative
  }
  SECTION("zero-length direction: degenerate outside, overlapping inside") {
    auto r = ccd::ray_sphere(Vec3(5, 0, 0), Vec3(0, 0, 0), c, 1.0, 1.0);
    CHECK(r.status == RaySphereStatus::Degenerate);
    CHECK(r.toi == inf);
    r = ccd::ray_sphere(Vec3(0.5, 0, 0), Vec3(0, 0, 0), c, 1.0, 1.0);
    CHECK(r.status == RaySphereStatus::Overlapping);
    // |d|^2 underflows below the smallest normal double: treated as zero.
    r = ccd::ray_sphere(Vec3(5, 0, 0), Vec3(-1e-160, 0, 0), c, 1.0, inf);
    CHECK(r.status == RaySphereStatus::Degenerate);
    // Tiny but representable: a = 1e-300 is normal; t = 4e150.
    r = ccd::ray_sphere(Vec3(5, 0, 0), Vec3(-1e-150, 0, 0), c, 1.0, inf);
    REQUIRE(r.status == RaySphereStatus::Hit);
    CHECK(r.toi == Approx(4e150).epsilon(8 * eps));
  }
  SECTION("invalid input: degenerate") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK(ccd::ray_sphere(Vec3(5, 0, 0), Vec3(-1, 0, 0), c, -1.0, 1.0).status == RaySphereStatus::Degenerate);
    CHECK(ccd::ray_sphere(Vec3(5, 0, 0), Vec3(-1, 0, 0), c, nan, 1.0).status == RaySphereStatus::Degenerate);
    CHECK(ccd::ray_sphere(Vec3(5, 0, 0), Vec3(-1, 0, 0), c, 1.0, -1.0).status == RaySphereStatus::Degenerate);
    CHECK(ccd::ray_sphere(Vec3(5, 0, 0), Vec3(-1, 0, 0), c, 1.0, nan).status == RaySphereStatus::Degenerate);
    CHECK(ccd::ray_sphere(Vec3(nan, 0, 0), Vec3(-1, 0, 0), c, 1.0, 1.0).status ==
          RaySphereStatus::Degenerate);
    CHECK(ccd::ray_sphere(Vec3(5, 0, 0), Vec3(-inf, 0, 0), c, 1.0, 1.0).status ==
          RaySphereStatus::Degenerate);
    CHECK(ccd::ray_sphere(Vec3(1e200, 0, 0), Vec3(-1, 0, 0), c, 1.0, 1.0).status ==
          RaySphereStatus::Degenerate);
  }
  SECTION("far from the origin (~1e6): matches the long double reference") {
    // Same geometry as the off-axis case, shifted by ~1e6 in every coordinate. The shift
    // rounds the inputs by up to ulp(1e6)/2 = 5.8e-11, so the expected value comes from
    // the reference on the actual doubles; the bound is the derived one (scale |m|).
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    for (int n = 0; n < 1000; ++n) {
      const Vec3 shift(1e6 * (1 + U(rng)), -1e6 * (1 + U(rng)), 1e6 * U(rng));
      const Vec3 cc = shift + Vec3(U(rng), U(rng), U(rng));
      const double R = 1.0 + U(rng) * 0.5;
      const Vec3 o = cc + 5 * random_unit(rng);
      const Vec3 d = (cc + 0.9 * R * random_unit(rng) - o) * (0.5 + U(rng) * 0.25);
      const auto r = ccd::ray_sphere(o, d, cc, R, inf);
      const Reference ref = reference(o, d, cc, R, inf);
      INFO("case " << n);
      REQUIRE(ref.status == RaySphereStatus::Hit);
      REQUIRE(r.status == RaySphereStatus::Hit);
      CHECK(std::abs(r.toi - static_cast<double>(ref.toi)) * d.norm() <= toi_bound(ref, R));
      // The computed normal is the contact point relative to the centre, normalised.
      const Vec3 pref = (o - cc) + static_cast<double>(ref.toi) * d;
      CHECK((r.normal - pref / R).norm() <= 4 * toi_bound(ref, R) / R + 8 * eps);
    }
  }
}

TEST_CASE("ray_sphere against a long double reference on 1e5 random rays", "[queries][ray_sphere]") {
  // Thin band (where the double query may legitimately differ from the reference):
  //  - origin within 2 tol of the surface (the query snaps |dist| <= tol to "touching");
  //  - line within 2 tol of tangency (|h - R| <= 2 tol: the query reports h <= R + tol
  //    as grazing hits);
  //  - reference toi within the derived toi error of t_max (range end decided on the
  //    computed toi).
  // tol bounds the query's rounding of |m| and h (~6 eps |m|) with margin, and the
  // reference's own error is ~1e-19 relative, so outside the band the classification
  // must be identical: zero differences are required.
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int differences = 0, in_band = 0, hits = 0, band_differences = 0;
  double max_rel = 0.0, max_norm = 0.0;
  const int cases = 100000;
  for (int n = 0; n < cases; ++n) {
    const double kind = U(rng);
    Vec3 centre(20 * U(rng) - 10, 20 * U(rng) - 10, 20 * U(rng) - 10);
    const double R = std::exp2(-4 + 8 * U(rng));
    const double speed = std::exp2(-10 + 20 * U(rng));
    Vec3 o, d;
    if (kind < 0.4) {  // generic: origin anywhere, aimed near the sphere
      o = centre + (R + 20 * U(rng)) * random_unit(rng);
      d = (centre + 2 * R * U(rng) * random_unit(rng) - o).normalized() * speed;
    } else if (kind < 0.7) {  // near tangency: h = R (1 +- 10^(-16..-4))
      const Vec3 p = random_unit(rng);
      Vec3 u = random_unit(rng);
      u = (u - p * p.dot(u)).normalized();
      const double rel = std::pow(10.0, -16 + 12 * U(rng)) * (U(rng) < 0.5 ? -1 : 1);
      o = centre + R * (1 + rel) * p - (0.1 + 10 * U(rng)) * R * u;
      d = u * speed;
    } else if (kind < 0.85) {  // origin near the surface: |dist| = R 10^(-16..-2)
      const double rel = std::pow(10.0, -16 + 14 * U(rng)) * (U(rng) < 0.5 ? -1 : 1);
      o = centre + R * (1 + rel) * random_unit(rng);
      d = random_unit(rng) * speed;
    } else {  // far from the origin: the generic case shifted by ~1e6 (inputs rounded)
      centre += 1e6 * Vec3(U(rng) + 0.5, -U(rng) - 0.5, U(rng) - 0.5);
      o = centre + (R + 10 * U(rng)) * random_unit(rng);
      d = (centre + 2 * R * U(rng) * random_unit(rng) - o).normalized() * speed;
    }
    const double t_max = U(rng) < 0.5 ? inf : U(rng) * 2 * ((o - centre).norm() + R) / speed;
    const auto r = ccd::ray_sphere(o, d, centre, R, t_max);
    const Reference ref = reference(o, d, centre, R, t_max);
    const double tol = tol_of(o, centre);
    bool band = std::abs(static_cast<double>(ref.dist0)) <= 2 * tol ||
                std::abs(static_cast<double>(ref.h - R)) <= 2 * tol;
    if (ref.w > 0 && !band) {  // ref.toi is set before its range test
      band = std::abs(static_cast<double>(ref.toi) - t_max) * d.norm() <= toi_bound(ref, R);
    }
    in_band += band;
    if (r.status != ref.status) {
      if (band) {
        ++band_differences;
      } else {
        ++differences;
        UNSCOPED_INFO("case " << n << " status " << static_cast<int>(r.status) << " ref "
                              << static_cast<int>(ref.status));
      }
      continue;
    }
    if (r.status == RaySphereStatus::Hit) {
      // Unit normal: |p|/R - 1 <= ~60 eps |m| / R and one Newton step squares it.
      CHECK(std::abs(r.normal.norm() - 1.0) <= 8 * eps);
    }
    if (r.status == RaySphereStatus::Hit && !band && ref.toi > 0) {
      ++hits;
      const double err = std::abs(r.toi - static_cast<double>(ref.toi));
      max_rel = std::max(max_rel, err / static_cast<double>(ref.toi));
      const double norm = err * d.norm() / toi_bound(ref, R);
      max_norm = std::max(max_norm, norm);
      if (norm > 1.0) UNSCOPED_INFO("case " << n << " toi error " << err << " bound exceeded x" << norm);
      CHECK(norm <= 1.0);
    }
  }
  std::printf(
      "ray_sphere random: %d cases, %d in band (%d differ there), %d hits checked, "
      "max rel toi error %.3g, max error / derived bound %.3g\n",
      cases, in_band, band_differences, hits, max_rel, max_norm);
  CHECK(differences == 0);
  CHECK(hits > cases / 5);  // the generator really produces hits outside the band
}

}  // namespace ccd_queries_ray_sphere_test
