#pragma once
// A plate spinning above and below resting balls: the near passes of docs/truth.md
// ("Undecided events").
#include <ccd/scene/scene.hpp>
#include <ccd/shape/shape.hpp>

#include <utility>
#include <vector>

namespace ccd::test {

/// A plate (a box of half extents `half`) at the origin spinning about z at `omega`, and
/// one ball of radius `radius` at (0, 0, z) for each z of `heights`, moving at `velocity`.
inline Scene spinning_plate_scene(const Vec3& half, double omega, double radius, const std::vector<double>& heights,
                                  const Vec3& velocity = Vec3::Zero(), double horizon = 1.0) {
  Scene s;
  s.horizon = horizon;
  s.shapes.push_back(make_box_shape(half, "plate"));
  RigidBody plate;
  plate.shape = 0;
  plate.angular_velocity = Vec3(0, 0, omega);
  s.add_rigid_body(Body{}, plate);
  for (const double z : heights) {
    Body ball;
    ball.radius = radius;
    ball.position = Vec3(0, 0, z);
    ball.velocity = velocity;
    s.add_rigid_body(ball, RigidBody{});
  }
  return s;
}

/// The dyadic plate of the undecided cases: half extents (1/2, 1/2, 1/64), balls of
/// radius 1/8 whose surfaces are `gap` from the faces (centres at +-(1/64 + 1/8 + gap)).
inline Scene dyadic_plate_scene(double omega, double gap, const Vec3& velocity = Vec3::Zero()) {
  const double z = 0.015625 + 0.125 + gap;
  return spinning_plate_scene(Vec3(0.5, 0.5, 0.015625), omega, 0.125, {z, -z}, velocity);
}

}  // namespace ccd::test
