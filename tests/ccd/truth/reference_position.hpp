#pragma once
// A body's centre at time t recomputed from the scene's own numbers in a wider number type
// Q (__float128, mpq_class): initial state, acceleration and velocity changes merged in
// time order (at equal times, both), no walls. The reference of the truth tests, so it
// shares no code with the trajectories it checks.
#include <ccd/scene/scene.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace ccd::test {

template <class Q>
std::array<Q, 3> reference_position(const Scene& s, const Body& b, double t) {
  std::array<Q, 3> p, v, a;
  for (int k = 0; k < 3; ++k) {
    p[k] = Q(b.position[k]);
    v[k] = Q(b.velocity[k]);
    a[k] = Q(b.acceleration[k]) + Q(s.gravity[k]);
  }
  Q t0 = 0;
  std::size_t ia = 0, iv = 0;
  while (true) {
    const double ta = ia < b.acceleration_changes.size() ? b.acceleration_changes[ia].t : INFINITY;
    const double tv = iv < b.velocity_changes.size() ? b.velocity_changes[iv].t : INFINITY;
    const double tc = std::min(ta, tv);
    if (!(tc < t)) break;
    const Q dt = Q(tc) - t0;
    for (int k = 0; k < 3; ++k) {
      p[k] += v[k] * dt + a[k] * dt * dt / 2;
      v[k] += a[k] * dt;
    }
    if (ta == tc) {
      for (int k = 0; k < 3; ++k) a[k] = Q(b.acceleration_changes[ia].acceleration[k]) + Q(s.gravity[k]);
      ++ia;
    }
    if (tv == tc) {
      for (int k = 0; k < 3; ++k) v[k] = Q(b.velocity_changes[iv].velocity[k]);
      ++iv;
    }
    t0 = Q(tc);
  }
  const Q dt = Q(t) - t0;
  std::array<Q, 3> r;
  for (int k = 0; k < 3; ++k) r[k] = p[k] + v[k] * dt + a[k] * dt * dt / 2;
  return r;
}

}  // namespace ccd::test
