#pragma once
// Rigid scenes that wrap around, for the truth, pipeline and runner tests: adversarial
// cases built from dyadic numbers with contact times worked out by hand (a stick or a crate
// meeting another body through the seam, contact at the crossing instant, at t = 0, at the
// horizon, across a corner, under a spin that does not change the answer), a random dyadic
// scene of spinning sticks, crates and plates (one tumbling freely), and the 3 x 3 x 3
// tiling that is their reference.
#include "periodic_scenes.hpp"

#include <ccd/scene/scene.hpp>
#include <ccd/shape/shape.hpp>

#include <Eigen/Geometry>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace ccd::test {

/// A rigid body: shape index, orientation, spin.
inline RigidBody shaped(std::int32_t shape, const Vec3& omega = Vec3::Zero(), const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity(),
                        SpinModel spin = SpinModel::Prescribed) {
  RigidBody r;
  r.shape = shape;
  r.orientation = q;
  r.angular_velocity = omega;
  r.spin = spin;
  return r;
}

inline Body placed(const Vec3& p, const Vec3& v = Vec3::Zero(), double radius = 0.0) {
  Body b;
  b.position = p;
  b.velocity = v;
  b.radius = radius;
  return b;
}

/// A quarter turn about z: the stick's axis (body x) along world y.
inline Eigen::Quaterniond along_y() { return Eigen::Quaterniond(Eigen::AngleAxisd(0.5 * 3.141592653589793, Vec3::UnitZ())); }

struct RigidPeriodicCase {
  std::string name;
  Scene scene;
  ContactEvent expected;  ///< the one event, exact times
  bool grazing = false;   ///< touching without overlap: the truth can only flag it
};

/// Shapes of every case: 0 a cube of half edge 1/2 (enclosing radius sqrt(3)/2), 1 a stick
/// of half length 1 and radius 1/8 along the body x axis (enclosing radius 9/8). The box is
/// [0, 8]^3, wrapped on every axis unless said.
inline Scene rigid_wrapped_box(double T, std::array<Boundary, 3> b = {Boundary::Wrap, Boundary::Wrap, Boundary::Wrap}) {
  Scene s = wrapped_box(T, b);
  s.shapes.push_back(make_box_shape(Vec3(0.5, 0.5, 0.5), "cube"));
  s.shapes.push_back(make_capsule_shape(1.0, 0.125, "stick"));
  return s;
}

inline std::vector<RigidPeriodicCase> rigid_periodic_cases() {
  std::vector<RigidPeriodicCase> out;
  {  // A cube at rest at x = 1/2 (faces x = 0 = 8 and x = 1); a stick along y, moving +x
     // from x = 6: its front (x + 1/8) reaches the face 8 at t = 15/8; it crosses the seam
     // at t = 2 while touching and leaves the far face x = 1 (= 9) when x - 1/8 = 9, at
     // t = 25/8. The stick spins about its own axis (y): its shape does not change.
    Scene s = rigid_wrapped_box(4.0);
    s.add_rigid_body(placed({0.5, 4, 4}), shaped(0));
    s.add_rigid_body(placed({6, 4, 4}, {1, 0, 0}), shaped(1, {0, 8, 0}, along_y()));
    out.push_back({"a stick through a cube across the seam", s, {0, 1, 1.875, 3.125}});
  }
  {  // Cube A at x = 7 spinning about x (its x faces 6.5 and 7.5 do not move, and they
     // always hold the axis y = z = 4); a ball B of radius 1/2 from x = 1 at speed -1
     // reaches the face x = 0 at t = 1, when its image touches A's face x = 7.5 at
     // (7.5, 4, 4): exactly at the crossing instant. B's centre (image 9 - t) runs along
     // A's axis and leaves the face 6.5 by 1/2 at t = 3.
    Scene s = rigid_wrapped_box(4.0);
    s.add_rigid_body(placed({7, 4, 4}), shaped(0, {16, 0, 0}));
    s.add_rigid_body(placed({1, 4, 4}, {-1, 0, 0}, 0.5), RigidBody{});
    out.push_back({"contact at the crossing instant", s, {0, 1, 1.0, 3.0}});
  }
  {  // Overlapping across the seam from t = 0 to the horizon: a cube straddling the seam at
     // x = 1/4 (spans [7.75, 8.75] as an image) and a stick along y at x = 7.75 (spans
     // [7.625, 7.875]), both moving at (1, 0, 0): the stick wraps at t = 1/4 while in contact.
    Scene s = rigid_wrapped_box(1.0);
    s.add_rigid_body(placed({0.25, 4, 4}, {1, 0, 0}), shaped(0));
    s.add_rigid_body(placed({7.75, 4, 4}, {1, 0, 0}), shaped(1, {0, 4, 0}, along_y()));
    out.push_back({"overlapping across the seam from t = 0 to the horizon", s, {0, 1, 0.0, 1.0}});
  }
  {  // As the first case with horizon 2: enter 15/8, still in contact at the horizon.
    Scene s = rigid_wrapped_box(2.0);
    s.add_rigid_body(placed({0.5, 4, 4}), shaped(0));
    s.add_rigid_body(placed({6, 4, 4}, {1, 0, 0}), shaped(1, {0, 8, 0}, along_y()));
    out.push_back({"in contact at the horizon", s, {0, 1, 1.875, 2.0}});
  }
  {  // Touching exactly at the horizon (T = 15/8): no overlap can be certified, so the
     // truth flags the event grazing, with 15/8 inside its bracket.
    Scene s = rigid_wrapped_box(1.875);
    s.add_rigid_body(placed({0.5, 4, 4}), shaped(0));
    s.add_rigid_body(placed({6, 4, 4}, {1, 0, 0}), shaped(1, {0, 8, 0}, along_y()));
    out.push_back({"touching at the horizon", s, {0, 1, 1.875, 1.875}, true});
  }
  {  // Across a corner (image shift in x and y): cube A at rest at (1/2, 1/4, 4) straddles
     // the seam y = 0 and spans x in [0, 1], y in [-1/4, 3/4]; its image (+8, +8) spans
     // [8, 9] x [7.75, 8.75]. A ball of radius 5/8 at y = 7.375 (3/8 below that image's
     // face) moves +x from x = 6: it reaches the image's edge (8, 7.75) when its centre is
     // 1/2 short of it (3-4-5: 1/2^2 + 3/8^2 = 5/8^2), at x = 7.5, t = 3/2; it crosses the
     // seam x = 8 at t = 2 and leaves the far edge x = 9 at x = 9.5, t = 7/2.
    Scene s = rigid_wrapped_box(4.0);
    s.add_rigid_body(placed({0.5, 0.25, 4}), shaped(0));
    s.add_rigid_body(placed({6, 7.375, 4}, {1, 0, 0}, 0.625), RigidBody{});
    out.push_back({"across a corner", s, {0, 1, 1.5, 3.5}});
  }
  {  // Wrap on x only, elastic walls on y and z: the first case again, and a ball bouncing
     // off the wall y = 1/2 at t = 1/2, far from both (no event of its own).
    Scene s = rigid_wrapped_box(4.0, {Boundary::Wrap, Boundary::Reflect, Boundary::Reflect});
    s.add_rigid_body(placed({0.5, 4, 4}), shaped(0));
    s.add_rigid_body(placed({6, 4, 4}, {1, 0, 0}), shaped(1, {0, 8, 0}, along_y()));
    s.add_rigid_body(placed({4, 1, 1}, {0, -1, 0}, 0.5), RigidBody{});
    out.push_back({"wrap on x, walls on y and z", s, {0, 1, 1.875, 3.125}});
  }
  return out;
}

/// Random dyadic rigid scene in [0, 8]^3 wrapping on every axis: sticks (half length 1,
/// radius 1/8), crates (1/2, 1/4, 1/8), plates (3/4, 3/4, 1/16) and balls (radius 1/2),
/// all enclosing radii <= 9/8 <= 8 / 4; positions multiples of 1/128, velocities multiples
/// of 1/16 with |v_k| <= 2, spins multiples of 1/4 with |omega_k| <= 4, body 0 tumbling
/// freely, some angular-velocity changes; horizon 2. A body moves at most 4 per axis and
/// reaches 9/8 beyond its centre, so a body of the central tile meets only images of the
/// neighbouring tiles.
inline Scene random_rigid_periodic_scene(std::uint64_t seed, std::size_t n) {
  std::mt19937_64 rng(seed);
  auto dyadic = [&](int lo, int hi, double unit) { return unit * std::uniform_int_distribution<int>(lo, hi)(rng); };
  Scene s;
  s.horizon = 2.0;
  WallBox box;
  box.min = Vec3::Zero();
  box.max = Vec3::Constant(8.0);
  box.boundary.fill(Boundary::Wrap);
  s.box = box;
  s.shapes.push_back(make_capsule_shape(1.0, 0.125, "stick"));
  s.shapes.push_back(make_box_shape(Vec3(0.5, 0.25, 0.125), "crate"));
  s.shapes.push_back(make_box_shape(Vec3(0.75, 0.75, 0.0625), "plate"));
  for (std::size_t i = 0; i < n; ++i) {
    const Body b = placed({dyadic(0, 1024, 1.0 / 128), dyadic(0, 1024, 1.0 / 128), dyadic(0, 1024, 1.0 / 128)},
                          {dyadic(-32, 32, 1.0 / 16), dyadic(-32, 32, 1.0 / 16), dyadic(-32, 32, 1.0 / 16)}, 0.5);
    const int kind = std::uniform_int_distribution<int>(0, 3)(rng);
    Eigen::Quaterniond q(dyadic(-4, 4, 0.25), dyadic(-4, 4, 0.25), dyadic(-4, 4, 0.25), dyadic(-4, 4, 0.25));
    q = q.norm() > 0.0 ? q.normalized() : Eigen::Quaterniond::Identity();
    const Vec3 omega(dyadic(-16, 16, 0.25), dyadic(-16, 16, 0.25), dyadic(-16, 16, 0.25));
    if (kind == 3 && i != 0) {
      s.add_rigid_body(b, RigidBody{});
      continue;
    }
    RigidBody r = shaped(kind == 3 ? 1 : kind, omega, q, i == 0 ? SpinModel::Free : SpinModel::Prescribed);
    if (i % 4 == 1) r.angular_velocity_changes.push_back({dyadic(1, 7, 0.25), Vec3(0, 0, dyadic(-16, 16, 0.25))});
    s.add_rigid_body(b, r);
  }
  return s;
}

/// The rigid scene tiled 3 x 3 x 3 over its wrapped axes (as tiled(), with the shapes and
/// spins of every copy the original's).
inline Tiling tiled_rigid(const Scene& s) {
  Tiling t = tiled(s);
  const std::size_t n = s.bodies.size();
  Scene out = t.scene;
  out.bodies.clear();
  out.rigid.clear();
  for (std::size_t i = 0; i < t.scene.bodies.size(); ++i) out.add_rigid_body(t.scene.bodies[i], s.rigid_body(i % n));
  t.scene = out;
  return t;
}

}  // namespace ccd::test
