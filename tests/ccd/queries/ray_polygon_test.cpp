#include <ccd/queries/ray_polygon.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace ccd_queries_ray_polygon_test {

using ccd::RayPolygonStatus;
using ccd::Vec3;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double pi = 3.14159265358979323846;

using Triangle = std::array<Vec3, 3>;

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Vec3 v;
  do {
    v = Vec3(n(rng), n(rng), n(rng));
  } while (v.norm() < 1e-3);
  return v.normalized();
}

/// A rotation from the seeded engine (columns: an orthonormal, right-handed frame).
Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  const Vec3 a = random_unit(rng);
  Vec3 b = random_unit(rng);
  while (std::abs(a.dot(b)) > 0.9) b = random_unit(rng);
  b = (b - a * a.dot(b)).normalized();
  Eigen::Matrix3d m;
  m << a, b, a.cross(b);
  return m;
}

/// Number of polygons of `mesh` hit by the ray (t in [0, inf)).
int count_hits(const Vec3& o, const Vec3& d, const std::vector<Triangle>& mesh) {
  int hits = 0;
  for (const Triangle& tri : mesh) hits += ccd::ray_polygon(o, d, tri, inf).status == RayPolygonStatus::Hit;
  return hits;
}

/// A fan of n triangles (apex, rim_i, rim_{i+1}) closing around the apex; the rim is a
/// circle of radius r in the plane spanned by (e1, e2), each rim point lifted by a random
/// height along e3 (heights 0 make the fan planar). Some triangles are given reversed.
std::vector<Triangle> fan(const Vec3& apex, const Vec3& e1, const Vec3& e2, const Vec3& e3, int n, double r,
                          double lift, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::vector<Vec3> rim;
  const double phase = U(rng);
  for (int i = 0; i < n; ++i) {
    const double a = phase + 2 * pi * (i + 0.2 * U(rng)) / n;  // gaps < 1.4 (2 pi / n)
    rim.push_back(apex + r * (std::cos(a) * e1 + std::sin(a) * e2) + lift * U(rng) * e3);
  }
  std::vector<Triangle> tris;
  for (int i = 0; i < n; ++i) {
    Triangle t{apex, rim[i], rim[(i + 1) % n]};
    if (U(rng) < 0) std::swap(t[1], t[2]);  // mixed windings
    tris.push_back(t);
  }
  return tris;
}

}  // namespace

TEST_CASE("ray_polygon hand-worked hits", "[queries][ray_polygon]") {
  const std::vector<Vec3> square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<Vec3> reversed(square.rbegin(), square.rend());
  SECTION("unit square in z = 0, from above and below, both windings") {
    for (const auto* poly : {&square, &reversed}) {
      auto r = ccd::ray_polygon(Vec3(0.5, 0.25, 2), Vec3(0, 0, -1), *poly, inf);
      REQUIRE(r.status == RayPolygonStatus::Hit);
      CHECK(r.toi == 2.0);
      r = ccd::ray_polygon(Vec3(0.5, 0.25, -1), Vec3(0, 0, 4), *poly, inf);
      REQUIRE(r.status == RayPolygonStatus::Hit);
      CHECK(r.toi == 0.25);
      // Oblique: from (-1, 0.5, 1) towards (1, 0.5, -1) crosses z = 0 at x = 0 + 0.5... t = 0.5.
      r = ccd::ray_polygon(Vec3(-0.5, 0.5, 1), Vec3(2, 0, -2), *poly, inf);
      REQUIRE(r.status == RayPolygonStatus::Hit);
      CHECK(r.toi == 0.5);
      CHECK(ccd::ray_polygon(Vec3(1.5, 0.5, 2), Vec3(0, 0, -1), *poly, inf).status == RayPolygonStatus::Miss);
      CHECK(ccd::ray_polygon(Vec3(0.5, -1e-9, 2), Vec3(0, 0, -1), *poly, inf).status ==
            RayPolygonStatus::Miss);
      CHECK(ccd::ray_polygon(Vec3(0.5, 0.5, 2), Vec3(0, 0, 1), *poly, inf).status == RayPolygonStatus::Miss);
      CHECK(ccd::ray_polygon(Vec3(0.5, 0.5, 2), Vec3(0, 0, -1), *poly, 1.5).status == RayPolygonStatus::Miss);
    }
  }
  SECTION("tilted pentagon with negative coordinates") {
    // Regular pentagon of radius 2 in the plane x + y + z = -3 around (-1,-1,-1).
    const Vec3 c(-1, -1, -1);
    const Vec3 e1 = Vec3(1, -1, 0).normalized(), e2 = Vec3(1, 1, -2).normalized();
    std::vector<Vec3> pent;
    for (int i = 0; i < 5; ++i)
      pent.push_back(c + 2 * (std::cos(2 * pi * i / 5) * e1 + std::sin(2 * pi * i / 5) * e2));
    // Along the normal from 3 units away: t = 3 (a few roundings at scale 3).
    const Vec3 nrm = Vec3(1, 1, 1).normalized();
    auto r = ccd::ray_polygon(c + 0.5 * e1 + 3 * nrm, -nrm, pent, inf);
    REQUIRE(r.status == RayPolygonStatus::Hit);
    CHECK(r.toi == Approx(3.0).epsilon(16 * eps));
    // Inradius is 2 cos(36 deg) = 1.618: 1.7 along e1 rotated to an edge midpoint misses.
    const Vec3 mid_dir = std::cos(pi / 5) * e1 + std::sin(pi / 5) * e2;
    CHECK(ccd::ray_polygon(c + 1.7 * mid_dir + 3 * nrm, -nrm, pent, inf).status == RayPolygonStatus::Miss);
    CHECK(ccd::ray_polygon(c + 1.5 * mid_dir + 3 * nrm, -nrm, pent, inf).status == RayPolygonStatus::Hit);
  }
}

TEST_CASE("ray_polygon degenerate cases", "[queries][ray_polygon]") {
  const std::vector<Vec3> square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  SECTION("parallel to the plane, off it") {
    const auto r = ccd::ray_polygon(Vec3(0.5, 0.5, 1), Vec3(1, 0, 0), square, inf);
    CHECK(r.status == RayPolygonStatus::Parallel);
    CHECK(r.toi == inf);
  }
  SECTION("in-plane ray: coplanar, not computed") {
    const auto r = ccd::ray_polygon(Vec3(-1, 0.5, 0), Vec3(1, 0, 0), square, inf);
    CHECK(r.status == RayPolygonStatus::Coplanar);
    CHECK(r.toi == 0.0);
  }
  SECTION("origin on the polygon: touching at t = 0; on the plane outside it: miss") {
    auto r = ccd::ray_polygon(Vec3(0.5, 0.5, 0), Vec3(0, 0, 1), square, inf);
    CHECK(r.status == RayPolygonStatus::Hit);
    CHECK(r.toi == 0.0);
    r = ccd::ray_polygon(Vec3(2, 0.5, 0), Vec3(0, 0, 1), square, inf);
    CHECK(r.status == RayPolygonStatus::Miss);
  }
  SECTION("fewer than 3 vertices, zero area, zero direction, invalid input") {
    const std::vector<Vec3> two{{0, 0, 0}, {1, 0, 0}};
    const std::vector<Vec3> line{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    CHECK(ccd::ray_polygon(Vec3(0.5, 0.5, 1), Vec3(0, 0, -1), two, inf).status ==
          RayPolygonStatus::Degenerate);
    CHECK(ccd::ray_polygon(Vec3(0.5, 0.5, 1), Vec3(0, 0, -1), line, inf).status ==
          RayPolygonStatus::Degenerate);
    CHECK(ccd::ray_polygon(Vec3(0.5, 0.5, 1), Vec3(0, 0, 0), square, inf).status ==
          RayPolygonStatus::Degenerate);
    CHECK(ccd::ray_polygon(Vec3(0.5, 0.5, 1), Vec3(0, 0, -1), square, -1.0).status ==
          RayPolygonStatus::Degenerate);
  }
  SECTION("repeated vertex: its zero-length edge is ignored") {
    const std::vector<Vec3> tri{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    CHECK(ccd::ray_polygon(Vec3(0.25, 0.25, 1), Vec3(0, 0, -1), tri, inf).status == RayPolygonStatus::Hit);
    CHECK(ccd::ray_polygon(Vec3(0.75, 0.75, 1), Vec3(0, 0, -1), tri, inf).status == RayPolygonStatus::Miss);
  }
  SECTION("far from the origin (~1e6)") {
    // Square of side 1 at (1e6, -1e6, 1e6) + [0,1]^2: t = 2 exactly (dyadic inputs).
    const Vec3 s(1e6, -1e6, 1e6);
    std::vector<Vec3> far;
    for (const Vec3& v : square) far.push_back(v + s);
    auto r = ccd::ray_polygon(s + Vec3(0.5, 0.25, 2), Vec3(0, 0, -1), far, inf);
    REQUIRE(r.status == RayPolygonStatus::Hit);
    CHECK(r.toi == 2.0);
    // 1e-9 outside an edge (ulp(1e6) = 1.2e-10) is resolved.
    r = ccd::ray_polygon(s + Vec3(1 + 1e-9, 0.25, 2), Vec3(0, 0, -1), far, inf);
    CHECK(r.status == RayPolygonStatus::Miss);
    r = ccd::ray_polygon(s + Vec3(1 - 1e-9, 0.25, 2), Vec3(0, 0, -1), far, inf);
    CHECK(r.status == RayPolygonStatus::Hit);
  }
}

TEST_CASE("ray_polygon is watertight: shared vertices and edges count exactly once",
          "[queries][ray_polygon]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  SECTION("planar fan in z = 0, ray exactly through the shared vertex (all spokes tie)") {
    for (int n : {3, 4, 5, 6, 7, 12}) {
      for (int rep = 0; rep < 20; ++rep) {
        const auto tris = fan(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), n, 1.0, 0.0, rng);
        INFO("n " << n << " rep " << rep);
        CHECK(count_hits(Vec3(0, 0, 1), Vec3(0, 0, -1), tris) == 1);
        CHECK(count_hits(Vec3(0, 0, -1), Vec3(0, 0, 2), tris) == 1);
      }
    }
  }
  SECTION("planar fan, ray exactly through a shared edge (the edge function is 0)") {
    // Square split along its diagonal and along x = 0.5 lines: dyadic points on shared
    // edges, axis rays, so the edge function at the ray is exactly zero.
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(0, 1, 0), m(0.5, 0.5, 0);
    const std::vector<Triangle> tris{{a, b, m}, {b, c, m}, {c, d, m}, {d, a, m}};
    for (const Vec3& p : {Vec3(0.25, 0.25, 0), Vec3(0.75, 0.75, 0), Vec3(0.25, 0.75, 0), Vec3(0.75, 0.25, 0),
                          Vec3(0.5, 0.5, 0)}) {
      INFO("through " << p.transpose());
      CHECK(count_hits(p + Vec3(0, 0, 1), Vec3(0, 0, -1), tris) == 1);
      CHECK(count_hits(p - Vec3(0, 0, 1), Vec3(0, 0, 1), tris) == 1);
    }
  }
  SECTION("tilted and non-planar fans (cones), random rays through the vertex and edges") {
    int rays = 0;
    for (int rep = 0; rep < 300; ++rep) {
      const Eigen::Matrix3d rot = random_rotation(rng);
      const Vec3 apex = Vec3(U(rng), U(rng), U(rng)) * (rep % 3 == 0 ? 1e6 : 3.0);
      // n >= 4, jitter 0.2: apex angles <= 126 deg; tilt <= 35 deg stretches that to
      // <= 140 deg and rim heights <= 0.3 (radius 1) turn spokes by <= 17.5 deg each in
      // projection, so the projected fan still tiles a disc around the apex (< 180 deg).
      const int n = 4 + rep % 8;
      const double lift = rep % 2 == 0 ? 0.0 : 0.15 * (U(rng) + 1);
      const auto tris = fan(apex, rot.col(0), rot.col(1), rot.col(2), n, 1.0, lift, rng);
      for (int k = 0; k < 20; ++k) {
        Vec3 dir = -rot.col(2) + 0.5 * U(rng) * rot.col(0) + 0.5 * U(rng) * rot.col(1);
        if (k % 2) dir = -dir;
        // Through the apex, or through a point on a shared spoke (apex + s (rim - apex)).
        const Triangle& t = tris[k % n];
        const Vec3 rim = t[1];
        const Vec3 target = k % 4 < 2 ? apex : Vec3(apex + (0.1 + 0.4 * (U(rng) + 1)) * (rim - apex));
        const Vec3 o = target - (2 + U(rng)) * dir;
        INFO("rep " << rep << " k " << k);
        CHECK(count_hits(o, dir, tris) == 1);
        ++rays;
      }
    }
    CHECK(rays == 6000);
  }
  SECTION("closed octahedron: every line through the interior crosses exactly twice") {
    // Lines through vertices, edge points and random interior points of a randomly
    // rotated, shifted octahedron; the origin starts outside, so both crossings are ahead.
    for (int rep = 0; rep < 200; ++rep) {
      const Eigen::Matrix3d rot = random_rotation(rng);
      const Vec3 centre = Vec3(U(rng), U(rng), U(rng)) * (rep % 2 ? 1e6 : 5.0);
      std::array<Vec3, 6> v;
      for (int i = 0; i < 3; ++i) {
        v[2 * i] = centre + 2.0 * rot.col(i);
        v[2 * i + 1] = centre - 2.0 * rot.col(i);
      }
      std::vector<Triangle> mesh;
      for (int sx : {0, 1})
        for (int sy : {2, 3})
          for (int sz : {4, 5}) mesh.push_back({v[sx], v[sy], v[sz]});
      for (int k = 0; k < 30; ++k) {
        const Vec3 inner = centre + 0.3 * Vec3(U(rng), U(rng), U(rng));
        Vec3 through;
        switch (k % 3) {
          case 0:
            through = v[k % 6];
            break;  // a vertex
          case 1:
            through = v[k % 2] + 0.5 * (v[2 + (k / 3) % 4] - v[k % 2]);
            break;  // an edge
          default:
            through = centre + Vec3(U(rng), U(rng), U(rng));
            break;  // anywhere
        }
        const Vec3 dir = (inner - through).normalized();
        const Vec3 o = through - 5.0 * dir;
        INFO("rep " << rep << " k " << k);
        CHECK(count_hits(o, dir, mesh) == 2);
      }
    }
  }
}

}  // namespace ccd_queries_ray_polygon_test
