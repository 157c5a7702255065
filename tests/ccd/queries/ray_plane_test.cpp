#include <ccd/queries/ray_plane.hpp>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

namespace ccd_queries_ray_plane_test {

using ccd::RayPlaneStatus;
using ccd::Vec3;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double inf = std::numeric_limits<double>::infinity();

}  // namespace

TEST_CASE("ray_plane hand-worked hits", "[queries][ray_plane]") {
  const Vec3 n(0, 0, 1);
  SECTION("axis plane z = 2: t = (2 - 5) / -1 = 3, scaled by the speed") {
    auto r = ccd::ray_plane(Vec3(1, 1, 5), Vec3(0, 0, -1), n, 2.0, inf);
    REQUIRE(r.status == RayPlaneStatus::Hit);
    CHECK(r.toi == 3.0);
    r = ccd::ray_plane(Vec3(1, 1, 5), Vec3(3, -7, -2), n, 2.0, inf);
    REQUIRE(r.status == RayPlaneStatus::Hit);
    CHECK(r.toi == 1.5);
  }
  SECTION("non-unit normal: 4z = 8 is the same plane") {
    const auto r = ccd::ray_plane(Vec3(1, 1, 5), Vec3(0, 0, -1), Vec3(0, 0, 4), 8.0, inf);
    REQUIRE(r.status == RayPlaneStatus::Hit);
    CHECK(r.toi == 3.0);
  }
  SECTION("tilted plane x + y + z = 3, hit from either side") {
    auto r = ccd::ray_plane(Vec3(0, 0, 0), Vec3(1, 2, 3), Vec3(1, 1, 1), 3.0, inf);
    REQUIRE(r.status == RayPlaneStatus::Hit);
    CHECK(r.toi == 0.5);  // 3 / 6
    r = ccd::ray_plane(Vec3(2, 2, 2), Vec3(-1, -2, -3), Vec3(1, 1, 1), 3.0, inf);
    REQUIRE(r.status == RayPlaneStatus::Hit);
    CHECK(r.toi == 0.5);  // (3 - 6) / -6
  }
  SECTION("negative coordinates: plane -x = 4 (x = -4)") {
    const auto r = ccd::ray_plane(Vec3(-1, -2, -3), Vec3(-0.5, 0, 0), Vec3(-1, 0, 0), 4.0, inf);
    REQUIRE(r.status == RayPlaneStatus::Hit);
    CHECK(r.toi == 6.0);
  }
  SECTION("range: crossing behind the origin or after t_max is a miss; exactly t_max hits") {
    auto r = ccd::ray_plane(Vec3(1, 1, 5), Vec3(0, 0, 1), n, 2.0, inf);
    CHECK(r.status == RayPlaneStatus::Miss);
    CHECK(r.toi == inf);
    r = ccd::ray_plane(Vec3(1, 1, 5), Vec3(0, 0, -1), n, 2.0, 2.0);
    CHECK(r.status == RayPlaneStatus::Miss);
    r = ccd::ray_plane(Vec3(1, 1, 5), Vec3(0, 0, -1), n, 2.0, 3.0);
    CHECK(r.status == RayPlaneStatus::Hit);
    CHECK(r.toi == 3.0);
  }
}

TEST_CASE("ray_plane degenerate cases", "[queries][ray_plane]") {
  const Vec3 n(0, 0, 1);
  SECTION("parallel: off the plane, exactly and within 16 eps of the angle") {
    auto r = ccd::ray_plane(Vec3(1, 1, 5), Vec3(1, 0, 0), n, 2.0, inf);
    CHECK(r.status == RayPlaneStatus::Parallel);
    CHECK(r.toi == inf);
    // sin(angle) = 1e-17 < 16 eps = 3.6e-15: parallel.
    r = ccd::ray_plane(Vec3(1, 1, 5), Vec3(1, 0, -1e-17), n, 2.0, inf);
    CHECK(r.status == RayPlaneStatus::Parallel);
    // sin(angle) = 1e-14 > 16 eps: a hit far away, t = 3e14 with one rounding.
    r = ccd::ray_plane(Vec3(1, 1, 5), Vec3(1, 0, -1e-14), n, 2.0, inf);
    REQUIRE(r.status == RayPlaneStatus::Hit);
    CHECK(r.toi == Approx(3e14).epsilon(2 * eps));
  }
  SECTION("in-plane ray: the whole ray lies in the plane") {
    auto r = ccd::ray_plane(Vec3(1, 1, 2), Vec3(1, -1, 0), n, 2.0, inf);
    CHECK(r.status == RayPlaneStatus::InPlane);
    CHECK(r.toi == 0.0);
    r = ccd::ray_plane(Vec3(1, 1, 2), Vec3(0, 0, 0), n, 2.0, inf);  // a point on the plane
    CHECK(r.status == RayPlaneStatus::InPlane);
    // Tilted plane through (1,2,3) with normal (0.1,0.2,0.3): the residual of an on-plane
    // origin is rounding noise, inside the 8 eps band.
    const Vec3 tn(0.1, 0.2, 0.3);
    const Vec3 p(1, 2, 3);
    const double off = tn.dot(p);
    r = ccd::ray_plane(p, tn.cross(Vec3(1, 0, 0)), tn, off, inf);
    CHECK(r.status == RayPlaneStatus::InPlane);
  }
  SECTION("origin on the plane: touching at t = 0 whichever way it leaves") {
    for (const Vec3& d : {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 1, 1)}) {
      const auto r = ccd::ray_plane(Vec3(1, 1, 2), d, n, 2.0, 1.0);
      CHECK(r.status == RayPlaneStatus::Hit);
      CHECK(r.toi == 0.0);
    }
  }
  SECTION("zero-length direction off the plane, zero normal, invalid input: degenerate") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK(ccd::ray_plane(Vec3(1, 1, 5), Vec3(0, 0, 0), n, 2.0, inf).status == RayPlaneStatus::Degenerate);
    CHECK(ccd::ray_plane(Vec3(1, 1, 5), Vec3(0, 0, -1), Vec3(0, 0, 0), 2.0, inf).status ==
          RayPlaneStatus::Degenerate);
    CHECK(ccd::ray_plane(Vec3(1, 1, 5), Vec3(0, 0, -1), n, 2.0, -1.0).status == RayPlaneStatus::Degenerate);
    CHECK(ccd::ray_plane(Vec3(1, 1, 5), Vec3(0, 0, -1), n, nan, 1.0).status == RayPlaneStatus::Degenerate);
    CHECK(ccd::ray_plane(Vec3(1, nan, 5), Vec3(0, 0, -1), n, 2.0, 1.0).status == RayPlaneStatus::Degenerate);
    CHECK(ccd::ray_plane(Vec3(1, 1, 5), Vec3(0, 0, -1), n, 2.0, nan).status == RayPlaneStatus::Degenerate);
  }
  SECTION("far from the origin (~1e6): matches the long double formula") {
    // Relative error bound of t = -res / den from the dot-product error bounds:
    // res within gamma_4 (sum|n_i o_i| + |offset|), den within gamma_3 sum|n_i d_i|, one
    // rounding for the quotient; coefficients 4, 3, 1 rounded up to 8.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    int hits = 0;
    for (int k = 0; k < 10000; ++k) {
      const Vec3 nn(U(rng), U(rng), U(rng));
      const Vec3 p0 = Vec3(1e6, -1e6, 1e6) + 1e3 * Vec3(U(rng), U(rng), U(rng));
      const double off = nn.dot(p0);
      const Vec3 o = p0 + 10 * Vec3(U(rng), U(rng), U(rng));
      const Vec3 d(U(rng), U(rng), U(rng));
      const auto r = ccd::ray_plane(o, d, nn, off, inf);
      long double res = -static_cast<long double>(off), den = 0, sr = std::abs(off), sd = 0;
      for (int i = 0; i < 3; ++i) {
        res += static_cast<long double>(nn[i]) * o[i];
        den += static_cast<long double>(nn[i]) * d[i];
        sr += std::abs(static_cast<long double>(nn[i]) * o[i]);
        sd += std::abs(static_cast<long double>(nn[i]) * d[i]);
      }
      const long double t = -res / den;
      const double bound_rel = static_cast<double>(8 * eps * (sr / std::abs(res) + sd / std::abs(den) + 1));
      if (bound_rel > 0.1) continue;  // ill-conditioned: inside the bands, decided either way
      INFO("case " << k);
      if (t < 0) {
        CHECK(r.status == RayPlaneStatus::Miss);
        continue;
      }
      REQUIRE(r.status == RayPlaneStatus::Hit);
      ++hits;
      CHECK(std::abs(r.toi - static_cast<double>(t)) <= bound_rel * static_cast<double>(t));
    }
    CHECK(hits > 1000);
  }
}

}  // namespace ccd_queries_ray_plane_test
