#pragma once
// Rigid scenes that several tests work out by hand.
#include <ccd/scene/scene.hpp>
#include <ccd/shape/shape.hpp>

#include <utility>
#include <vector>

namespace ccd::test {

/// A stick (half length 1, radius 1/16) at the origin spinning about z at `omega`, and a
/// ball of radius 1/8 resting at (0, 3/4, 0): no translation at all. The ball's centre is
/// 3/4 |cos(theta)| from the stick's axis and projects inside the segment, so the pair is in
/// contact while |cos(theta)| <= 1/4.
inline Scene spinning_stick_scene(double omega, double horizon, std::vector<AngularVelocityChange> changes = {}) {
  Scene s;
  s.horizon = horizon;
  s.shapes.push_back(make_capsule_shape(1.0, 1.0 / 16, "stick"));
  RigidBody stick;
  stick.shape = 0;
  stick.angular_velocity = Vec3(0, 0, omega);
  stick.angular_velocity_changes = std::move(changes);
  s.add_rigid_body(Body{}, stick);
  Body ball;
  ball.radius = 1.0 / 8;
  ball.position = Vec3(0, 0.75, 0);
  s.add_rigid_body(ball, RigidBody{});
  return s;
}

}  // namespace ccd::test
