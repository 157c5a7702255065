#include <ccd/queries/convex_distance.hpp>
#include <ccd/shape/shape.hpp>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

namespace ccd_queries_convex_distance_test {

using ccd::ConvexDistance;
using ccd::ProxyPose;
using ccd::Vec3;
using Status = ccd::ConvexDistance::Status;

namespace {

ProxyPose at(const Vec3& c, const Eigen::Matrix3d& r = Eigen::Matrix3d::Identity()) { return {c, r}; }
Eigen::Matrix3d about_z(double angle) { return Eigen::AngleAxisd(angle, Vec3::UnitZ()).toRotationMatrix(); }

// The bracket holds `exact` and is at most the tolerance plus the rounding allowance wide.
void check_bracket(const ConvexDistance& d, double exact, double width) {
  CHECK(d.lower <= exact);
  CHECK(d.upper >= exact);
  CHECK(d.upper - d.lower <= width);
}

// A hull of 8 random points in [-1, 1] x [-0.5, 0.5] x [-0.25, 0.25], and a random rotation.
ccd::Shape random_hull(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> pts;
  for (int i = 0; i < 8; ++i) pts.emplace_back(u(rng), 0.5 * u(rng), 0.25 * u(rng));
  return ccd::make_hull_shape(pts);
}
Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized().toRotationMatrix();
}

}  // namespace

TEST_CASE("convex_distance brackets known distances", "[queries][gjk]") {
  const ccd::Shape unit_box = ccd::make_box_shape(Vec3(0.5, 0.5, 0.5));
  SECTION("two spheres: |c| - r_a - r_b = 4 - 0.5 - 0.25") {
    const ccd::Shape a = ccd::make_sphere_shape(0.5), b = ccd::make_sphere_shape(0.25);
    const ConvexDistance d = ccd::convex_distance(a.proxy(), at(Vec3(1, 2, 3)), b.proxy(), at(Vec3(1, 2, 7)));
    CHECK(d.status == Status::Separated);
    check_bracket(d, 3.25, 1e-8);
  }
  SECTION("face to face boxes 1 apart (ties between 4 support corners)") {
    const ConvexDistance d = ccd::convex_distance(unit_box.proxy(), at(Vec3(0, 0, 0)), unit_box.proxy(), at(Vec3(2, 0, 0)));
    CHECK(d.status == Status::Separated);
    check_bracket(d, 1.0, 1e-8);
    CHECK(d.direction.x() == Approx(1.0));
  }
  SECTION("box turned 45 degrees: its edge faces the other's face, 2 - sqrt(2)/2 - 1/2") {
    const ConvexDistance d =
        ccd::convex_distance(unit_box.proxy(), at(Vec3(0, 0, 0)), unit_box.proxy(), at(Vec3(2, 0, 0), about_z(M_PI / 4)));
    check_bracket(d, 2.0 - std::sqrt(0.5) - 0.5, 1e-8);
  }
  SECTION("edge to edge: two sticks crossing at right angles, 1 apart") {
    const ccd::Shape stick = ccd::make_capsule_shape(1.0, 0.125);
    const ConvexDistance d = ccd::convex_distance(stick.proxy(), at(Vec3(0, 0, 0)), stick.proxy(),
                                                  at(Vec3(0, 0, 1), about_z(M_PI / 2)));
    check_bracket(d, 0.75, 1e-8);
  }
  SECTION("parallel sticks side by side (a segment of closest points)") {
    const ccd::Shape stick = ccd::make_capsule_shape(1.0, 0.125);
    const ConvexDistance d = ccd::convex_distance(stick.proxy(), at(Vec3(0, 0, 0)), stick.proxy(), at(Vec3(0.5, 0.5, 0)));
    check_bracket(d, 0.25, 1e-8);
  }
  SECTION("far from the origin: the same boxes at 1e6 keep their bracket") {
    const Vec3 far(1e6, -1e6, 1e6);
    const ConvexDistance d = ccd::convex_distance(unit_box.proxy(), at(far), unit_box.proxy(), at(far + Vec3(2, 0, 0)));
    check_bracket(d, 1.0, 1e-8);
  }
  SECTION("deep overlap: coincident boxes") {
    const ConvexDistance d = ccd::convex_distance(unit_box.proxy(), at(Vec3(3, 3, 3)), unit_box.proxy(), at(Vec3(3, 3, 3)));
    CHECK(d.status == Status::Overlapping);
    CHECK(d.upper < -0.1);
  }
  SECTION("overlapping spheres: grown cores") {
    const ccd::Shape a = ccd::make_sphere_shape(0.5);
    const ConvexDistance d = ccd::convex_distance(a.proxy(), at(Vec3(0, 0, 0)), a.proxy(), at(Vec3(0.75, 0, 0)));
    CHECK(d.status == Status::Overlapping);
    check_bracket(d, -0.25, 1e-8);
  }
  SECTION("touching faces (dyadic): neither separated nor overlapping can be certified") {
    const ConvexDistance d = ccd::convex_distance(unit_box.proxy(), at(Vec3(0, 0, 0)), unit_box.proxy(), at(Vec3(1, 0.25, 0)));
    CHECK(d.status == Status::Uncertain);
    CHECK(d.lower <= 0.0);
    CHECK(d.upper >= 0.0);
  }
}

TEST_CASE("convex_distance bounds hold on random hulls and poses", "[queries][gjk]") {
  std::mt19937_64 rng(1313);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int separated = 0, overlapping = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const ccd::Shape a = random_hull(rng), b = random_hull(rng);
    const ProxyPose pa = at(Vec3(u(rng), u(rng), u(rng)), random_rotation(rng));
    const ProxyPose pb = at(Vec3(u(rng), u(rng), u(rng)) * 0.75, random_rotation(rng));
    const ConvexDistance d = ccd::convex_distance(a.proxy(), pa, b.proxy(), pb);
    REQUIRE(d.status != Status::Failed);
    REQUIRE(d.lower <= d.upper);
    separated += d.status == Status::Separated;
    overlapping += d.status == Status::Overlapping;
    // Upper bound: no separating direction shows a larger gap (min over A minus max over B
    // along n). Lower bound: no pair of points (vertices and vertex mixtures) is closer.
    for (int k = 0; k < 50; ++k) {
      const Vec3 n = Vec3(u(rng), u(rng), u(rng)).normalized();
      double amax = -1e300, bmin = 1e300;
      for (const Vec3& p : a.points) amax = std::max(amax, n.dot(pa.centre + pa.rotation * p));
      for (const Vec3& p : b.points) bmin = std::min(bmin, n.dot(pb.centre + pb.rotation * p));
      CHECK(bmin - amax <= d.upper);
      const Vec3 x = pa.centre + pa.rotation * (0.5 * (a.points[k % 8] + a.points[(k * 3 + 1) % 8]));
      const Vec3 y = pb.centre + pb.rotation * (0.5 * (b.points[(k * 5) % 8] + b.points[(k + 2) % 8]));
      CHECK((x - y).norm() >= d.lower);
    }
    if (d.status == Status::Separated) CHECK(d.upper - d.lower <= 2e-9);
  }
  // The generator makes both outcomes often enough for the checks above to mean something.
  CHECK(separated > 50);
  CHECK(overlapping > 50);
}

TEST_CASE("convex_distance: a warm start changes no certificate, and the gap along direction is at least lower",
          "[queries][gjk]") {
  std::mt19937_64 rng(2626);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int separated = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const ccd::Shape a = random_hull(rng), b = random_hull(rng);
    const ProxyPose pa = at(Vec3(u(rng), u(rng), u(rng)), random_rotation(rng));
    const ProxyPose pb = at(Vec3(u(rng), u(rng), u(rng)) * 1.5, random_rotation(rng));
    const ConvexDistance cold = ccd::convex_distance(a.proxy(), pa, b.proxy(), pb);
    ccd::DistanceOptions o;
    o.start_direction = Vec3(u(rng), u(rng), u(rng));  // any guess, good or bad
    const ConvexDistance warm = ccd::convex_distance(a.proxy(), pa, b.proxy(), pb, o);
    REQUIRE(warm.status != Status::Failed);
    // Both bracket the same distance.
    CHECK(std::max(cold.lower, warm.lower) <= std::min(cold.upper, warm.upper));
    if (cold.lower > 1e-6) CHECK(warm.status == Status::Separated);
    if (cold.upper < -1e-6) CHECK(warm.status == Status::Overlapping);
    // The certificate the advancement relies on: along `direction`, every point of B is at
    // least `lower` further than every point of A.
    for (const ConvexDistance& d : {cold, warm}) {
      if (d.status != Status::Separated) continue;
      ++separated;
      double amax = -1e300, bmin = 1e300;
      for (const Vec3& p : a.points) amax = std::max(amax, d.direction.dot(pa.centre + pa.rotation * p));
      for (const Vec3& p : b.points) bmin = std::min(bmin, d.direction.dot(pb.centre + pb.rotation * p));
      CHECK(bmin - amax >= d.lower);
      CHECK(std::fabs(d.direction.norm() - 1.0) < 1e-12);
    }
  }
  CHECK(separated > 100);
}

TEST_CASE("convex_distance: near-tangent faces and edges keep a bracket of the tolerance", "[queries][gjk]") {
  // Two crates face to face, the upper one turned about the shared normal, the pair turned
  // as a whole and put far from the origin: the distance is the gap g (1e-9 to 1e-3 m)
  // however close the faces; the bracket must close to the tolerance, not stop nanometres
  // short. Then the upper crate tilted about x by g: an edge over a face at gap g.
  std::mt19937_64 rng(1717);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const ccd::Shape crate = ccd::make_box_shape(Vec3(0.5, 0.3, 0.2));
  for (int trial = 0; trial < 400; ++trial) {
    const double g = std::pow(10.0, -9.0 + 6.0 * u(rng));
    const Eigen::Matrix3d whole =
        Eigen::Quaterniond(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5).normalized().toRotationMatrix();
    const Vec3 far = Vec3(1, -1, 1) * (trial % 2 ? 0.0 : 1024.0);
    const bool edge = trial % 4 >= 2;
    const Eigen::Matrix3d turn =
        edge ? Eigen::AngleAxisd(0.5, Vec3::UnitX()).toRotationMatrix()
             : Eigen::AngleAxisd(6.28 * u(rng), Vec3::UnitZ()).toRotationMatrix();
    // Edge case: turned by 1/2 rad about x, the upper crate's lowest edge is
    // 0.3 sin(1/2) + 0.2 cos(1/2) below its centre.
    const double drop = edge ? 0.3 * std::sin(0.5) + 0.2 * std::cos(0.5) : 0.2;
    const Vec3 offset(0.1 * u(rng), 0.1 * u(rng), 0.2 + g + drop);
    const ProxyPose pa = at(far, whole);
    const ProxyPose pb = at(far + whole * offset, whole * turn);
    const ConvexDistance d = ccd::convex_distance(crate.proxy(), pa, crate.proxy(), pb);
    INFO("trial " << trial << " gap " << g << " lower " << d.lower << " upper " << d.upper);
    CHECK(d.upper - d.lower <= 2e-9);
    CHECK(d.lower <= g + 1e-12);
    CHECK(d.upper >= g - 1e-12);
    if (g > 4e-9) CHECK(d.status == Status::Separated);
  }
}

}  // namespace ccd_queries_convex_distance_test
