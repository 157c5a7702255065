#include <ccd/motion/rotation.hpp>

#include <catch2/catch.hpp>
#include <cmath>

namespace ccd_motion_rotation_test {

using ccd::Vec3;

namespace {

ccd::Scene stick_scene(const Vec3& omega, std::vector<ccd::AngularVelocityChange> changes = {}) {
  ccd::Scene s;
  s.horizon = 2.0;
  s.shapes.push_back(ccd::make_capsule_shape(1.0, 0.125, "stick"));
  ccd::RigidBody r;
  r.shape = 0;
  r.angular_velocity = omega;
  r.angular_velocity_changes = std::move(changes);
  s.add_rigid_body(ccd::Body{}, r);
  return s;
}

}  // namespace

TEST_CASE("a sphere-only scene has no rotations", "[motion][rotation]") {
  ccd::Scene s;
  s.horizon = 1.0;
  ccd::Body b;
  b.radius = 0.5;
  ccd::RigidBody r;
  r.angular_velocity = Vec3(0, 0, 3);  // a spinning sphere: its orientation never matters
  s.add_rigid_body(b, r);
  CHECK(s.is_rigid());
  CHECK(ccd::Rotations(s).empty());
}

TEST_CASE("constant spin: a quarter turn about z after pi/2 / omega seconds", "[motion][rotation]") {
  const double w = 4.0;
  const ccd::Rotations rot(stick_scene(Vec3(0, 0, w)));
  REQUIRE(rot.size() == 1);
  REQUIRE(rot.pieces(0).size() == 1);
  // The stick's tip (1, 0, 0) points along +y after a quarter turn.
  const Vec3 tip = rot.orientation(0, M_PI / 2 / w) * Vec3(1, 0, 0);
  CHECK(tip.x() == Approx(0).margin(1e-15));
  CHECK(tip.y() == Approx(1).margin(1e-15));
  CHECK(rot.orientation(0, 0.0).coeffs() == ccd::Quat::Identity().coeffs());
  CHECK(rot.max_omega(0, 0.0, 2.0) == w);
}

TEST_CASE("the angular velocity is in the world frame, applied after the initial orientation", "[motion][rotation]") {
  ccd::Scene s = stick_scene(Vec3(0, 0, 1));
  // Initially turned a quarter about x: the body's y axis points along world z.
  s.rigid[0].orientation = ccd::Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitX()));
  const ccd::Rotations rot(s);
  // World-frame spin about z turns the body's x axis (world x at t = 0) towards world y.
  const Vec3 x = rot.orientation(0, M_PI / 2) * Vec3(1, 0, 0);
  CHECK(x.y() == Approx(1).margin(1e-15));
  // ... and leaves the body's y axis (world z) fixed.
  const Vec3 y = rot.orientation(0, M_PI / 2) * Vec3(0, 1, 0);
  CHECK(y.z() == Approx(1).margin(1e-15));
}

TEST_CASE("an angular-velocity change starts a piece from the orientation at the change", "[motion][rotation]") {
  // Half a turn about z over [0, 1] (omega pi), then a quarter turn about x per second.
  const ccd::Rotations rot(stick_scene(Vec3(0, 0, M_PI), {{1.0, Vec3(M_PI / 2, 0, 0)}}));
  const auto ps = rot.pieces(0);
  REQUIRE(ps.size() == 2);
  CHECK(ps[0].t1 == 1.0);
  CHECK(ps[1].t0 == 1.0);
  CHECK(ps[1].t1 == 2.0);
  // Continuous at the change.
  CHECK(ps[0].orientation(1.0).coeffs() == ps[1].q0.coeffs());
  // At t = 1 the tip (1,0,0) points along -x; turning about x leaves it there.
  const Vec3 tip = rot.orientation(0, 1.75) * Vec3(1, 0, 0);
  CHECK(tip.x() == Approx(-1).margin(1e-15));
  // The later piece at the change.
  CHECK(&rot.piece_at(0, 1.0) == &ps[1]);
  CHECK(rot.max_omega(0, 0.0, 0.5) == M_PI);
  CHECK(rot.max_omega(0, 1.5, 2.0) == M_PI / 2);
  CHECK(rot.max_omega(0, 0.5, 1.5) == M_PI);
}

}  // namespace ccd_motion_rotation_test
