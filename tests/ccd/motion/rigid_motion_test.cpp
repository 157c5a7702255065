#include <ccd/motion/rigid_motion.hpp>

#include <catch2/catch.hpp>
#include <cmath>

namespace ccd_motion_rigid_motion_test {

using ccd::Vec3;

TEST_CASE("max_point_speed bounds every point's speed: |v| + |omega| R", "[motion][rigid]") {
  ccd::Scene s;
  s.horizon = 2.0;
  s.shapes.push_back(ccd::make_capsule_shape(1.0, 0.25, "stick"));  // R = 1.25
  ccd::Body b;
  b.position = Vec3(0, 0, 0);
  b.velocity = Vec3(3, 0, 0);
  b.acceleration = Vec3(0, 4, 0);  // |v(t)| = |(3, 4t, 0)|: 3 at t = 0, 5 at t = 1
  ccd::RigidBody r;
  r.shape = 0;
  r.angular_velocity = Vec3(0, 0, 2);
  s.add_rigid_body(b, r);
  ccd::Body sphere;
  sphere.radius = 0.5;
  sphere.position = Vec3(10, 0, 0);
  s.add_rigid_body(sphere, ccd::RigidBody{});
  const ccd::Trajectories traj(s);
  const ccd::RigidMotion m(s, traj);
  CHECK(m.kind(0) == ccd::ShapeKind::Capsule);
  CHECK(m.kind(1) == ccd::ShapeKind::Sphere);
  CHECK(m.proxy(1).points.size() == 1);
  CHECK(m.proxy(1).radius == 0.5);
  CHECK(m.proxy(0).radius == 0.25);
  const double u = std::numeric_limits<double>::epsilon();
  // Over [0, 1]: 5 + 2 x 1.25 = 7.5, rounded up.
  CHECK(m.max_point_speed(0, 0.0, 1.0) >= 7.5);
  CHECK(m.max_point_speed(0, 0.0, 1.0) <= 7.5 * (1 + 40 * u));
  // Sampled: the tip's speed by finite differences never exceeds the bound.
  for (int k = 0; k < 64; ++k) {
    const double t = k / 64.0, h = 1.0 / 1024;
    const Vec3 tip0 = m.pose(0, t).apply(Vec3(1, 0, 0)), tip1 = m.pose(0, t + h).apply(Vec3(1, 0, 0));
    CHECK((tip1 - tip0).norm() / h <= m.max_point_speed(0, t, t + h));
  }
  // A resting sphere: 0.
  CHECK(m.max_point_speed(1, 0.0, 2.0) == 0.0);
}

TEST_CASE("walls act on the enclosing sphere of a shaped body", "[motion][rigid]") {
  ccd::Scene s;
  s.horizon = 1.0;
  s.box = ccd::WallBox{Vec3(0, 0, 0), Vec3(8, 8, 8)};
  s.shapes.push_back(ccd::make_box_shape(Vec3(3, 4, 12) / 16.0, "crate"));  // R = 13/16
  ccd::Body b;
  b.position = Vec3(4, 4, 4);
  b.velocity = Vec3(4, 0, 0);
  ccd::RigidBody r;
  r.shape = 0;
  r.angular_velocity = Vec3(0, 0, 10);
  s.add_rigid_body(b, r);
  const ccd::Trajectories traj(s);
  // The centre reflects at 8 - 13/16 (rounded up by ulps): at t ~ (8 - 13/16 - 4) / 4.
  const auto ps = traj.pieces(0);
  REQUIRE(ps.size() == 2);
  CHECK(ps[0].t1 == Approx((8.0 - 13.0 / 16 - 4.0) / 4.0).epsilon(1e-14));
  CHECK(ps[1].v.x() == -4.0);
  // The spin is unchanged by the wall.
  const ccd::Rotations rot(s);
  CHECK(rot.pieces(0).size() == 1);
}

TEST_CASE("spheres(): plain spheres only, decided once for the scene, and assign_spheres reuses a motion",
          "[motion][rigid]") {
  ccd::Scene s;
  s.horizon = 1.0;
  ccd::Body ball;
  ball.radius = 0.5;
  ball.position = Vec3(1, 0, 0);
  ball.velocity = Vec3(1, 0, 0);
  s.add_rigid_body(ball, ccd::RigidBody{});
  ball.position = Vec3(4, 0, 0);
  ball.radius = 0.25;
  s.add_rigid_body(ball, ccd::RigidBody{});
  const ccd::Trajectories balls(s);
  // A scene of balls, built from the scene or from its trajectories alone: plain spheres.
  CHECK(ccd::RigidMotion(s, balls).spheres());
  CHECK(ccd::RigidMotion(balls).spheres());
  CHECK(ccd::RigidMotion(balls).rotations().empty());

  // One shaped body (spinning or not) makes the whole scene's motion not plain.
  ccd::Scene shaped = s;
  shaped.shapes.push_back(ccd::make_box_shape(Vec3(0.25, 0.25, 0.25), "cube"));
  ccd::Body cube;
  cube.position = Vec3(8, 0, 0);
  ccd::RigidBody still;
  still.shape = 0;
  shaped.add_rigid_body(cube, still);
  const ccd::Trajectories shaped_centres(shaped);
  ccd::RigidMotion m(shaped, shaped_centres);
  CHECK_FALSE(m.spheres());
  CHECK(m.kind(0) == ccd::ShapeKind::Sphere);
  CHECK(m.kind(2) == ccd::ShapeKind::Box);

  // The images of a step keep the source's answer, as they keep its shapes.
  ccd::RigidMotion images;
  const std::vector<std::uint32_t> owner = {2, 0, 2};
  images.assign_images(m, shaped_centres, owner, 0.0, 1.0);
  CHECK_FALSE(images.spheres());
  CHECK(images.kind(0) == ccd::ShapeKind::Box);
  CHECK(images.kind(1) == ccd::ShapeKind::Sphere);

  // The same object made the plain-sphere motion of other trajectories.
  m.assign_spheres(balls);
  CHECK(m.spheres());
  CHECK(m.rotations().empty());
  REQUIRE(m.size() == 2);
  CHECK(&m.centres() == &balls);
  for (std::uint32_t i = 0; i < 2; ++i) {
    CHECK(m.kind(i) == ccd::ShapeKind::Sphere);
    CHECK(m.proxy(i).points.size() == 1);
    CHECK(m.proxy(i).points[0] == Vec3::Zero());
    CHECK(m.proxy(i).radius == balls.radius(i));
  }
}

}  // namespace ccd_motion_rigid_motion_test
