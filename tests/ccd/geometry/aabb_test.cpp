#include <ccd/geometry/aabb.hpp>

#include <array>
#include <catch2/catch.hpp>
#include <random>

namespace ccd_geometry_aabb_test {

using ccd::Aabb;
using ccd::Vec3;

TEST_CASE("Aabb::overlaps uses closed intervals on every axis", "[geometry][aabb]") {
  const Aabb a{Vec3(0, 0, 0), Vec3(1, 1, 1)};
  SECTION("overlapping, contained, identical") {
    CHECK(a.overlaps(Aabb{Vec3(0.5, 0.5, 0.5), Vec3(2, 2, 2)}));
    CHECK(a.overlaps(Aabb{Vec3(0.25, 0.25, 0.25), Vec3(0.75, 0.75, 0.75)}));
    CHECK(Aabb{Vec3(0.25, 0.25, 0.25), Vec3(0.75, 0.75, 0.75)}.overlaps(a));
    CHECK(a.overlaps(a));
  }
  SECTION("touching: face, edge, corner count as overlap, from either side") {
    for (const Vec3& shift : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, -1), Vec3(1, 1, 0),
                              Vec3(1, -1, 1), Vec3(-1, -1, -1)}) {
      const Aabb b{a.lo + shift, a.hi + shift};
      INFO("shift " << shift.transpose());
      CHECK(a.overlaps(b));
      CHECK(b.overlaps(a));
    }
  }
  SECTION("separated on exactly one axis (each axis, each side) is no overlap") {
    for (int axis = 0; axis < 3; ++axis) {
      for (double side : {-1.0, 1.0}) {
        Vec3 shift = Vec3::Zero();
        shift[axis] = side * std::nextafter(1.0, 2.0);  // 1 ulp beyond touching
        const Aabb b{a.lo + shift, a.hi + shift};
        INFO("axis " << axis << " side " << side);
        CHECK_FALSE(a.overlaps(b));
        CHECK_FALSE(b.overlaps(a));
      }
    }
  }
  SECTION("negative coordinates") {
    const Aabb n{Vec3(-3, -2, -1), Vec3(-2, -1, 0)};
    CHECK(n.overlaps(Aabb{Vec3(-2, -1, 0), Vec3(5, 5, 5)}));  // corner touch at (-2,-1,0)
    CHECK_FALSE(n.overlaps(Aabb{Vec3(-1.5, -1, 0), Vec3(5, 5, 5)}));
    CHECK(n.overlaps(Aabb{Vec3(-10, -10, -10), Vec3(-2.5, -1.5, -0.5)}));
  }
  SECTION("zero-size boxes (points) and far from the origin (~1e6)") {
    const Aabb p{Vec3(1, 0.5, 0.5), Vec3(1, 0.5, 0.5)};
    CHECK(a.overlaps(p));
    CHECK(p.overlaps(p));
    const Vec3 s(1e6, -1e6, 1e6);
    const Aabb far{a.lo + s, a.hi + s};
    CHECK(far.overlaps(Aabb{Vec3(1, 0, 0) + s, Vec3(2, 1, 1) + s}));
    CHECK_FALSE(
        far.overlaps(Aabb{Vec3(std::nextafter(1e6 + 1, 2e6), -1e6, 1e6), Vec3(1e6 + 2, -1e6 + 1, 1e6 + 1)}));
  }
  SECTION("agrees with a per-axis interval test on random integer boxes") {
    std::mt19937_64 rng(1);
    std::uniform_int_distribution<int> C(-3, 3), L(0, 4);
    int yes = 0;
    for (int n = 0; n < 10000; ++n) {
      Aabb b, c;
      bool expect = true;
      for (int i = 0; i < 3; ++i) {
        b.lo[i] = C(rng);
        b.hi[i] = b.lo[i] + L(rng);
        c.lo[i] = C(rng);
        c.hi[i] = c.lo[i] + L(rng);
        // Closed intervals intersect iff max(lo) <= min(hi).
        expect = expect && std::max(b.lo[i], c.lo[i]) <= std::min(b.hi[i], c.hi[i]);
      }
      yes += expect;
      CHECK(b.overlaps(c) == expect);
      CHECK(c.overlaps(b) == expect);
    }
    CHECK(yes > 500);
  }
}

TEST_CASE("Aabb::around and merge", "[geometry][aabb]") {
  const Aabb s = Aabb::around(Vec3(1, -2, 3), 0.5);
  CHECK(s.lo == Vec3(0.5, -2.5, 2.5));
  CHECK(s.hi == Vec3(1.5, -1.5, 3.5));
  Aabb m = s;
  m.merge(Aabb{Vec3(-1, 0, 3), Vec3(0, 1, 3)});
  CHECK(m.lo == Vec3(-1, -2.5, 2.5));
  CHECK(m.hi == Vec3(1.5, 1, 3.5));
}

}  // namespace ccd_geometry_aabb_test
