// The closed-form ball-box distance: exact (lower = upper) on dyadic axis-aligned cases,
// touching included; certified bounds that hold convex_distance's value when the box is
// turned; bounds that do not certify what rounding can hide.
#include <ccd/queries/sphere_box_distance.hpp>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

namespace ccd_queries_sphere_box_distance_test {

using ccd::ConvexDistance;
using ccd::Vec3;

namespace {

const Vec3 kHalf(0.5, 0.25, 0.125);

ccd::ProxyPose at(const Vec3& c, const Eigen::Matrix3d& R = Eigen::Matrix3d::Identity()) { return {c, R}; }

}  // namespace

TEST_CASE("sphere-box distance: exact on dyadic axis-aligned cases", "[queries][sphere_box]") {
  const Vec3 c(1.0, -2.0, 4.0);
  SECTION("outside a face: 1/16") {
    const ConvexDistance d = ccd::sphere_box_distance(c + Vec3(0, 0, 0.125 + 0.25 + 0.0625), 0.25, at(c), kHalf);
    CHECK(d.lower == 0.0625);
    CHECK(d.upper == 0.0625);
    CHECK(d.status == ConvexDistance::Status::Separated);
  }
  SECTION("touching a face exactly: distance 0, certified") {
    const ConvexDistance d = ccd::sphere_box_distance(c + Vec3(0.5 + 0.25, 0.125, -0.0625), 0.25, at(c), kHalf);
    CHECK(d.lower == 0.0);
    CHECK(d.upper == 0.0);
    CHECK(d.status == ConvexDistance::Status::Uncertain);
  }
  SECTION("touching an edge exactly: a 3-4-5 offset") {
    // Outside by 3/16 along x and 4/16 along y: distance 5/16, the ball's radius.
    const ConvexDistance d =
        ccd::sphere_box_distance(c + Vec3(0.5 + 0.1875, 0.25 + 0.25, 0.0), 0.3125, at(c), kHalf);
    CHECK(d.lower == 0.0);
    CHECK(d.upper == 0.0);
  }
  SECTION("the centre inside: minus the depth to the nearest face, minus the radius") {
    const ConvexDistance d = ccd::sphere_box_distance(c + Vec3(0.25, 0.0, 0.0625), 0.125, at(c), kHalf);
    CHECK(d.lower == -0.0625 - 0.125);
    CHECK(d.upper == d.lower);
    CHECK(d.status == ConvexDistance::Status::Overlapping);
  }
  SECTION("a quarter turn about z swaps the half extents x and y") {
    Eigen::Matrix3d R;
    R << 0, -1, 0, 1, 0, 0, 0, 0, 1;
    const ConvexDistance d = ccd::sphere_box_distance(c + Vec3(0.25 + 0.125, 0, 0), 0.0625, at(c, R), kHalf);
    CHECK(d.lower == 0.0625);
    CHECK(d.upper == 0.0625);
  }
  SECTION("a gap of 2^-50 above a face: certified exactly") {
    const double z = 0.125 + 0.25 + std::ldexp(1.0, -50);
    const ConvexDistance d = ccd::sphere_box_distance(Vec3(0, 0, z), 0.25, at(Vec3::Zero()), kHalf);
    CHECK(d.lower == std::ldexp(1.0, -50));
    CHECK(d.status == ConvexDistance::Status::Separated);
  }
}

TEST_CASE("sphere-box distance: a turned box has certified bounds holding the true distance", "[queries][sphere_box]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    const Eigen::Quaterniond q = Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized();
    const Eigen::Matrix3d R = q.toRotationMatrix();
    const Vec3 c(u(rng), u(rng), u(rng));
    const Vec3 s = c + Vec3(u(rng), u(rng), u(rng));
    const double r = 0.25 * (1.0 + u(rng));
    const ConvexDistance d = ccd::sphere_box_distance(s, r, at(c, R), kHalf);
    // Reference: the point's distance in the box frame from long-double arithmetic.
    Eigen::Matrix<long double, 3, 1> p;
    for (int i = 0; i < 3; ++i) {
      long double x = 0;
      for (int j = 0; j < 3; ++j) x += static_cast<long double>(R(j, i)) * (static_cast<long double>(s[j]) - c[j]);
      p[i] = x;
    }
    long double out2 = 0, inside = -1e300L;
    bool in = true;
    for (int i = 0; i < 3; ++i) {
      const long double e = std::fabs(p[i]) - kHalf[i];
      inside = std::max(inside, e);
      if (e > 0) {
        out2 += e * e;
        in = false;
      }
    }
    const long double f = (in ? inside : std::sqrt(out2)) - r;
    INFO(k);
    CHECK(d.lower < d.upper);  // a turned box is never taken as exact
    CHECK(static_cast<long double>(d.lower) <= f);
    CHECK(f <= static_cast<long double>(d.upper));
    CHECK(d.upper - d.lower < 1e-13);
  }
}

TEST_CASE("sphere-box distance: a gap below the rounding allowance is not certified under a turn",
          "[queries][sphere_box]") {
  // A turn about z leaves the face z = 1/8 in place; 2^-52 above it cannot be told apart
  // from touching once R is not a signed permutation.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.3, Vec3::UnitZ()).toRotationMatrix();
  const ConvexDistance d =
      ccd::sphere_box_distance(Vec3(0, 0, 0.125 + 0.25 + std::ldexp(1.0, -52)), 0.25, at(Vec3::Zero(), R), kHalf);
  CHECK(d.status == ConvexDistance::Status::Uncertain);
  CHECK(d.lower < 0.0);
  CHECK(d.upper > 0.0);
}

}  // namespace ccd_queries_sphere_box_distance_test
