#pragma once
// Scenes that wrap around, for the truth, pipeline and runner tests: adversarial cases
// built from dyadic numbers (every position, velocity and expected time exact in binary),
// a random dyadic scene, and the 3 x 3 x 3 tiling that is their reference.
#include "body_builder.hpp"

#include <ccd/scene/scene.hpp>
#include <ccd/truth/ground_truth.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace ccd::test {

/// A box [0, 8]^3 that wraps on every axis (or per `b`), horizon T, no bodies yet.
inline Scene wrapped_box(double T, std::array<Boundary, 3> b = {Boundary::Wrap, Boundary::Wrap, Boundary::Wrap}) {
  Scene s;
  s.horizon = T;
  WallBox box;
  box.min = Vec3::Zero();
  box.max = Vec3::Constant(8.0);
  box.boundary = b;
  s.box = box;
  return s;
}

struct PeriodicCase {
  std::string name;
  Scene scene;
  std::vector<ContactEvent> expected;  ///< exact truth, sorted by (enter, a, b)
};

/// Named adversarial cases in the box [0, 8]^3 (radius 0.5: contact at centre distance 1);
/// the expected intervals are worked out in the comments.
inline std::vector<PeriodicCase> periodic_cases() {
  std::vector<PeriodicCase> out;
  {  // Touching across the seam from t = 0, both at rest: x distance 0.5 + (8 - 7.5) = 1.
    Scene s = wrapped_box(1.0);
    s.bodies = {body(0.5, {0.5, 4, 4}), body(0.5, {7.5, 4, 4})};
    out.push_back({"tangent at rest across the seam, t = 0 to the horizon", s, {{0, 1, 0.0, 1.0}}});
  }
  {  // 0 reaches the face x = 0 at t = 0.5 when 1 is at x = 7: image distance 1 exactly at
     // the crossing instant; they pass through each other and part at t = 1 = horizon, when
     // 0 is at x = -1 -> 7 and 1 reaches the face x = 8.
    Scene s = wrapped_box(1.0);
    s.bodies = {body(0.5, {1, 4, 4}, {-2, 0, 0}), body(0.5, {6, 4, 4}, {2, 0, 0})};
    out.push_back({"contact at the crossing instant, exit at the horizon", s, {{0, 1, 0.5, 1.0}}});
  }
  {  // 0 sits exactly on the face x = 0 at rest; 1 comes from x = 6 at speed 1: contact
     // from x = 7 (t = 1) through the seam (t = 2) to x = 1 (t = 3).
    Scene s = wrapped_box(4.0);
    s.bodies = {body(0.5, {0, 4, 4}), body(0.5, {6, 4, 4}, {1, 0, 0})};
    out.push_back({"a body on the face, the other through the seam", s, {{0, 1, 1.0, 3.0}}});
  }
  {  // The same with 0 on the opposite face x = 8 (the same point of the periodic space).
    Scene s = wrapped_box(4.0);
    s.bodies = {body(0.5, {8, 4, 4}), body(0.5, {6, 4, 4}, {1, 0, 0})};
    out.push_back({"a body on the max face", s, {{0, 1, 1.0, 3.0}}});
  }
  {  // Tangent across the seam: 1 slides along y at x = 7.5, 0 at x = 0.5: touching only
     // when the y coordinates meet, at t = 2.
    Scene s = wrapped_box(3.0);
    s.bodies = {body(0.5, {0.5, 4, 4}), body(0.5, {7.5, 2, 4}, {0, 1, 0})};
    out.push_back({"tangent across the seam", s, {{0, 1, 2.0, 2.0}}});
  }
  {  // Across a corner (image shift in x and y): 1 on the face y = 8 moves in x from 6; its
     // image at y = 0 is 1 below 0 (y = 1), so the two touch when x meets, at t = 3 (1 has
     // crossed x = 8 at t = 2).
    Scene s = wrapped_box(4.0);
    s.bodies = {body(0.5, {1, 1, 4}), body(0.5, {6, 8, 4}, {1, 0, 0})};
    out.push_back({"tangent across a corner", s, {{0, 1, 3.0, 3.0}}});
  }
  {  // A body on the face moving out wraps at once: 0 at x = 8 moving +1 is at x = 0;
     // 1 at x = 2 at rest: contact from t = 0 (distance 2 - 0 > 1) ... at t = 1 (x = 1).
     // Exit when 0 passes 1 at x = 3: t = 3; horizon 4.
    Scene s = wrapped_box(4.0);
    s.bodies = {body(0.5, {8, 4, 4}, {1, 0, 0}), body(0.5, {2, 4, 4})};
    out.push_back({"a body on the face moving out", s, {{0, 1, 1.0, 3.0}}});
  }
  {  // Contact exactly at the horizon across the seam: 1 reaches x = 7 at t = 2 = horizon.
    Scene s = wrapped_box(2.0);
    s.bodies = {body(0.5, {0, 4, 4}), body(0.5, {5, 4, 4}, {1, 0, 0})};
    out.push_back({"contact at the horizon", s, {{0, 1, 2.0, 2.0}}});
  }
  {  // Gravity along a wrapped axis (y: -2): 1 falls from y = 2 at rest through the face
     // y = 0 at t = sqrt(2) and meets 0, resting at y = 6 (image -2), when its y is -1:
     // 2 - t^2 = -1 at t = sqrt(3) (not dyadic), no exit before the horizon 2 (y = -2).
     // Also: acceleration change on a wrapped axis. Expected enter sqrt(3).
    Scene s = wrapped_box(2.0);
    s.gravity = {0, -2, 0};
    Body rest = body(0.5, {4, 6, 4}, {0, 0, 0}, {0, 2, 0});  // own +2 cancels gravity
    s.bodies = {rest, body(0.5, {4, 2, 4})};
    out.push_back({"gravity along a wrapped axis", s, {{0, 1, 1.7320508075688772, 2.0}}});
  }
  {  // Mixed axes (wrap, wrap, reflect): 1 bounces off the wall z = 8 - 0.5 at t = 1 and
     // comes back to meet 0 through nothing but the wall: 0 at z = 6.5, 1 from z = 5.5
     // moving +2: contact at t = 0 (distance 1) ... they are touching and 1 moves into 0:
     // overlapping from t = 0 to the reflection and back until z = 5.5 at t = 2. Along x
    // (wrapped) both move at speed 1 and cross the seam together at t = 1.
    Scene s = wrapped_box(3.0, {Boundary::Wrap, Boundary::Wrap, Boundary::Reflect});
    s.bodies = {body(0.5, {7, 4, 6.5}, {1, 0, 0}), body(0.5, {7, 4, 5.5}, {1, 0, 2})};
    out.push_back({"mixed wrap and reflect axes", s, {{0, 1, 0.0, 2.0}}});
  }
  return out;
}

/// Random dyadic scene in [0, 16]^3 wrapping on every axis: radii in {0.5, 0.75, 1},
/// positions multiples of 1/64, velocities multiples of 1/16 with |v_k| <= 2, gravity
/// (0, -1/2, 0), some acceleration changes at dyadic times; horizon 2. Each body moves at
/// most 5 per axis, so a body of the central tile meets only images of the neighbouring
/// tiles (2 x 5 + 2 < 16) in the tiling below.
inline Scene random_periodic_scene(std::uint64_t seed, std::size_t n) {
  std::mt19937_64 rng(seed);
  auto dyadic = [&](int lo, int hi, double unit) { return unit * std::uniform_int_distribution<int>(lo, hi)(rng); };
  Scene s;
  s.horizon = 2.0;
  s.gravity = {0, -0.5, 0};
  WallBox box;
  box.min = Vec3::Zero();
  box.max = Vec3::Constant(16.0);
  box.boundary.fill(Boundary::Wrap);
  s.box = box;
  const double radii[] = {0.5, 0.75, 1.0};
  for (std::size_t i = 0; i < n; ++i) {
    Body b = body(radii[std::uniform_int_distribution<int>(0, 2)(rng)],
                  {dyadic(0, 1024, 1.0 / 64), dyadic(0, 1024, 1.0 / 64), dyadic(0, 1024, 1.0 / 64)},
                  {dyadic(-32, 32, 1.0 / 16), dyadic(-32, 32, 1.0 / 16), dyadic(-32, 32, 1.0 / 16)});
    if (i % 5 == 0) b.acceleration_changes.push_back({dyadic(1, 7, 0.25), {dyadic(-4, 4, 0.25), 0, 0}});
    s.bodies.push_back(b);
  }
  return s;
}

/// The scene tiled 3 x 3 x 3 over its wrapped axes (3 copies per wrapped axis, one per
/// reflecting axis), without walls on the wrapped axes: copy c of body i is body c n + i,
/// moved by the copy's offset; `central` is the copy with offset 0.
struct Tiling {
  Scene scene;
  std::uint32_t central = 0;
};

inline Tiling tiled(const Scene& s) {
  Tiling t{s, 0};
  t.scene.bodies.clear();
  const Vec3 L = s.box->max - s.box->min;
  std::uint32_t copy = 0;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z) {
        const int o[3] = {x, y, z};
        bool skip = false;
        Vec3 off = Vec3::Zero();
        for (int k = 0; k < 3; ++k) {
          if (!s.box->wraps(k) && o[k] != 0) skip = true;
          off[k] = o[k] * L[k];
        }
        if (skip) continue;
        if (x == 0 && y == 0 && z == 0) t.central = copy;
        for (Body b : s.bodies) {
          b.position += off;
          t.scene.bodies.push_back(b);
        }
        ++copy;
      }
  // Open the wrapped axes: walls far away that no body reaches.
  for (int k = 0; k < 3; ++k)
    if (s.box->wraps(k)) {
      t.scene.box->min[k] = s.box->min[k] - 64.0 * L[k];
      t.scene.box->max[k] = s.box->max[k] + 64.0 * L[k];
      t.scene.box->boundary[static_cast<std::size_t>(k)] = Boundary::Reflect;
    }
  return t;
}

/// The events of the tiled scene's central copy, as events of the periodic scene: (x, y)
/// with the copy of the lower original index central, mapped to (x mod n, y mod n).
inline std::vector<ContactEvent> central_events(const std::vector<ContactEvent>& tiled_events, std::size_t n,
                                                std::uint32_t central) {
  std::vector<ContactEvent> out;
  const auto m = static_cast<std::uint32_t>(n);
  for (const ContactEvent& e : tiled_events) {
    const std::uint32_t ox = e.a % m, oy = e.b % m;
    if (ox == oy) continue;
    if ((ox < oy ? e.a / m : e.b / m) != central) continue;
    out.push_back({std::min(ox, oy), std::max(ox, oy), e.enter, e.exit});
  }
  std::sort(out.begin(), out.end(), event_order);
  return out;
}

}  // namespace ccd::test
