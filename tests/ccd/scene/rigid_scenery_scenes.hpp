#pragma once
// Rigid bodies against static polygons, worked out by hand (dyadic data; docs/scenery.md):
// each case has its own body and polygon, and the cases are 16 apart so that no body
// meets another case's polygon. Exact contact intervals in the comments.
#include "scenery_support.hpp"

#include <ccd/scene/scene.hpp>
#include <ccd/shape/shape.hpp>

#include <cmath>
#include <vector>

namespace ccd::test {

/// The stick of rigid_static_cases (half length 1, radius 1/16) spinning at pi about z
/// touches the vertical square's edge x = 33/32 with its tips while cos(pi t) >= 703/704:
/// on [k - c, k + c] for every integer k, c = acos(703/704) / pi.
inline double stick_edge_half_width() { return std::acos(703.0 / 704.0) / M_PI; }

/// The cases, in order of their bodies (body i meets polygon i), horizon 2:
///  0. a cube (half extent 1/2) falling at 1 onto a floor square, face on face (parallel):
///     contact on [3/2, 2] (the horizon), still overlapping at T;
///  1. a stick (half length 1, radius 1/16) spinning at pi about z, no translation: its
///     tips graze the edge x = 33/32 of a vertical square in the plane y = 0: contact on
///     [0, c], [1 - c, 1 + c] and [2 - c, 2] (stick_edge_half_width), from t = 0;
///  2. a cube moving along (1, 1, 1): its corner meets the triangle's vertex (1, 1, 1)
///     (plane z = 1) at t = 1/2, its bottom face leaves the plane at t = 3/2: [1/2, 3/2];
///  3. case 0 far from the origin (offset 2^20 on every axis, -2^20 on y): [3/2, 2];
///  4. a cube (half extent 1/2) falling at 1/4 whose bottom face reaches the floor square
///     exactly at the horizon: one touch at t = 2.
inline Scene rigid_static_cases() {
  Scene s;
  s.horizon = 2.0;
  s.shapes.push_back(make_box_shape(Vec3(0.5, 0.5, 0.5), "cube"));
  s.shapes.push_back(make_capsule_shape(1.0, 1.0 / 16, "stick"));
  auto add = [&](int k, std::int32_t shape, Vec3 position, Vec3 velocity, Vec3 omega, std::vector<Vec3> polygon,
                 Vec3 offset = Vec3::Zero()) {
    const Vec3 o = offset + Vec3(16.0 * k, 0, 0);
    Body b;
    b.position = position + o;
    b.velocity = velocity;
    RigidBody r;
    r.shape = shape;
    r.angular_velocity = omega;
    s.add_rigid_body(b, r);
    for (Vec3& v : polygon) v += o;
    s.scenery.push_back(make_polygon(std::move(polygon)));
  };
  const std::vector<Vec3> floor{{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}};
  add(0, 0, {0, 0, 2}, {0, 0, -1}, Vec3::Zero(), floor);
  add(1, 1, Vec3::Zero(), Vec3::Zero(), {0, 0, M_PI}, {{33.0 / 32, 0, -0.5}, {2, 0, -0.5}, {2, 0, 0.5}, {33.0 / 32, 0, 0.5}});
  add(2, 0, Vec3::Zero(), {1, 1, 1}, Vec3::Zero(), {{1, 1, 1}, {3, 1, 1}, {1, 3, 1}});
  add(3, 0, {0, 0, 2}, {0, 0, -1}, Vec3::Zero(), floor, Vec3(1048576, -1048576, 1048576));
  add(4, 0, {0, 0, 1}, {0, 0, -0.25}, Vec3::Zero(), floor);
  return s;
}

/// A cube (half extent 1/2) at rest exactly on a floor square (distance 0 throughout:
/// `grazing` over [0, horizon]) and a stick spinning about z just above another square
/// (its axis 1/8 + 1/64 above the plane: apart by 1/64 throughout, no event). Horizon 1.
inline Scene resting_scene() {
  Scene s;
  s.horizon = 1.0;
  s.shapes.push_back(make_box_shape(Vec3(0.5, 0.5, 0.5), "cube"));
  s.shapes.push_back(make_capsule_shape(1.0, 1.0 / 8, "stick"));
  Body cube;
  cube.position = Vec3(0, 0, 0.5);
  RigidBody rc;
  rc.shape = 0;
  s.add_rigid_body(cube, rc);
  s.scenery.push_back(make_polygon({{-2, -2, 0}, {2, -2, 0}, {2, 2, 0}, {-2, 2, 0}}));
  Body stick;
  stick.position = Vec3(16, 0, 0.140625);
  RigidBody rs;
  rs.shape = 1;
  rs.angular_velocity = Vec3(0, 0, 2);
  s.add_rigid_body(stick, rs);
  s.scenery.push_back(make_polygon({{14, -2, 0}, {18, -2, 0}, {18, 2, 0}, {14, 2, 0}}));
  return s;
}

}  // namespace ccd::test
