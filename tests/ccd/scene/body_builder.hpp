#pragma once
// A body from its radius and start state, for tests that build scenes by hand.
#include <ccd/scene/scene.hpp>

namespace ccd::test {

inline Body body(double r, Vec3 p, Vec3 v = Vec3::Zero(), Vec3 a = Vec3::Zero()) {
  Body b;
  b.radius = r;
  b.position = p;
  b.velocity = v;
  b.acceleration = a;
  return b;
}

}  // namespace ccd::test
