// The static 15-axis SAT of two oriented boxes (bounds/oriented_box.hpp): dyadic cases
// (touching faces, parallel edges, exact quarter and third turns, far from the origin) and
// random boxes against the certified GJK distance of the same boxes.
#include <bounds/oriented_box.hpp>
#include <ccd/queries/convex_distance.hpp>
#include <ccd/shape/shape.hpp>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

namespace bounds_oriented_box_test {

using ccd::OrientedBox;
using ccd::Vec3;

namespace {

OrientedBox box(const Vec3& c, const Vec3& h, const Eigen::Matrix3d& axes = Eigen::Matrix3d::Identity()) {
  OrientedBox o;
  o.centre = c;
  o.half = h;
  o.axes = axes;
  return o;
}

}  // namespace

TEST_CASE("oriented box SAT on dyadic cases", "[bounds][obb]") {
  const Vec3 h(0.5, 0.25, 0.125);
  const Vec3 offset = GENERATE(Vec3(0, 0, 0), Vec3(1048576, -1048576, 1048576));
  const OrientedBox a = box(offset, h);
  SECTION("coincident, touching faces, parallel edges and corners overlap") {
    CHECK(ccd::oriented_boxes_overlap(a, a));
    CHECK(ccd::oriented_boxes_overlap(a, box(offset + Vec3(1, 0, 0), h)));
    CHECK(ccd::oriented_boxes_overlap(a, box(offset + Vec3(1, 0.5, 0), h)));       // parallel edges
    CHECK(ccd::oriented_boxes_overlap(a, box(offset + Vec3(1, 0.5, 0.25), h)));    // corners
    CHECK(ccd::oriented_boxes_overlap(a, box(offset + Vec3(-1, -0.5, -0.25), h)));
  }
  SECTION("a dyadic gap separates, also along parallel edges") {
    CHECK_FALSE(ccd::oriented_boxes_overlap(a, box(offset + Vec3(1.015625, 0, 0), h)));
    CHECK_FALSE(ccd::oriented_boxes_overlap(a, box(offset + Vec3(1, 0.515625, 0), h)));
    CHECK_FALSE(ccd::oriented_boxes_overlap(a, box(offset + Vec3(0, 0, 0.265625), h)));
  }
  SECTION("a third turn about the diagonal permutes the axes exactly") {
    const Eigen::Matrix3d r = Eigen::Quaterniond(0.5, 0.5, 0.5, 0.5).toRotationMatrix();
    const Vec3 world = (r.cwiseAbs() * h);  // the turned box's half extents on the world axes
    CHECK(ccd::oriented_boxes_overlap(a, box(offset + Vec3(0.5 + world.x(), 0.25 + world.y(), 0), h, r)));
    CHECK_FALSE(
        ccd::oriented_boxes_overlap(a, box(offset + Vec3(0.5 + world.x() + 0.015625, 0.25 + world.y(), 0), h, r)));
  }
  SECTION("an eighth turn about z: a cube's edge against a face") {
    const Eigen::Matrix3d r = Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()).toRotationMatrix();
    const Vec3 cube(0.5, 0.5, 0.5);
    const double reach = 0.5 + 0.5 * std::sqrt(2.0);
    CHECK(ccd::oriented_boxes_overlap(box(offset, cube), box(offset + Vec3(reach - 1e-9, 0, 0), cube, r)));
    CHECK_FALSE(ccd::oriented_boxes_overlap(box(offset, cube), box(offset + Vec3(reach + 1e-6, 0, 0), cube, r)));
    // The same edge at a face's corner: x and y both at reach / sqrt(2) beyond.
    const double d = 1e-6;
    CHECK_FALSE(ccd::oriented_boxes_overlap(box(offset, cube), box(offset + Vec3(reach + d, 0.5, 0), cube, r)));
  }
}

TEST_CASE("oriented box SAT agrees with the certified distance of random boxes", "[bounds][obb]") {
  std::mt19937_64 rng(1313);
  std::uniform_real_distribution<double> u(-1.0, 1.0), size(0.01, 1.0);
  long overlapping = 0, separated = 0, wrong = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec3 offset = k % 4 == 3 ? Vec3(65536, 65536, -65536) : Vec3::Zero();
    OrientedBox o[2];
    ccd::Shape shapes[2];
    for (int i = 0; i < 2; ++i) {
      Eigen::Quaterniond q(u(rng), u(rng), u(rng), u(rng));
      q.normalize();
      // A quarter of the pairs share their axes (parallel edges everywhere).
      o[i].axes = (k % 4 == 1 && i == 1) ? o[0].axes : Eigen::Matrix3d(q.toRotationMatrix());
      o[i].half = Vec3(size(rng), size(rng), size(rng));
      o[i].centre = offset + (i == 0 ? Vec3::Zero() : Vec3(1.5 * u(rng), 1.5 * u(rng), 1.5 * u(rng)));
      shapes[i] = ccd::make_box_shape(o[i].half);
    }
    const ccd::ConvexDistance d = ccd::convex_distance(shapes[0].proxy(), {o[0].centre, o[0].axes},
                                                       shapes[1].proxy(), {o[1].centre, o[1].axes});
    const bool sat = ccd::oriented_boxes_overlap(o[0], o[1]);
    if (d.status != ccd::ConvexDistance::Status::Separated) {
      ++overlapping;
      if (!sat && ++wrong <= 3) FAIL_CHECK("SAT separates touching boxes, pair " << k);
    } else if (d.lower > 1e-7) {
      ++separated;
      if (sat && ++wrong <= 3) FAIL_CHECK("SAT misses a separation of " << d.lower << ", pair " << k);
    }
  }
  CHECK(wrong == 0);
  CHECK(overlapping > 2000);
  CHECK(separated > 2000);
}

}  // namespace bounds_oriented_box_test
