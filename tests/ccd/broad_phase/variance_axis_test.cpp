#include <ccd/broad_phase/variance_axis.hpp>

#include <catch2/catch.hpp>
#include <vector>

namespace ccd_broad_phase_variance_axis_test {

using ccd::Aabb;
using ccd::Vec3;

TEST_CASE("the sweep axis is the axis of largest centre variance", "[broad_phase]") {
  std::vector<Aabb> boxes;
  SECTION("spread along y") {
    for (int i = 0; i < 10; ++i) boxes.push_back(Aabb::around(Vec3(0.1 * i, 5.0 * i, 0.2 * (i % 3)), 0.5));
    CHECK(ccd::largest_variance_axis(boxes) == 1);
  }
  SECTION("far from the origin, where s2 - s^2/n would cancel: spread along z by 1e-3") {
    // Centres 1e9 + k * 1e-3 on z, 1e9 exactly on x and y: the naive formula loses all
    // digits (1e18 * eps = 1e2 >> 1e-6), Welford keeps them.
    for (int i = 0; i < 10; ++i) boxes.push_back(Aabb::around(Vec3(1e9, 1e9, 1e9 + 1e-3 * i), 0.5));
    CHECK(ccd::largest_variance_axis(boxes) == 2);
  }
  SECTION("no boxes, and ties, give the lowest axis") {
    CHECK(ccd::largest_variance_axis(boxes) == 0);
    boxes.push_back(Aabb::around(Vec3(1, 2, 3), 1.0));
    CHECK(ccd::largest_variance_axis(boxes) == 0);
  }
}

}  // namespace ccd_broad_phase_variance_axis_test
