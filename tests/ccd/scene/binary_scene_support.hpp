#pragma once
// Bit-for-bit equality of two sphere scenes (every double compared by its bits, so -0.0 and
// 0.0 differ and NaN equals itself), for the tests of the binary scene format.
#include <ccd/scene/scene.hpp>

#include <bit>
#include <cstdint>

namespace ccd::test {

inline bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

inline bool same_bits(const Vec3& a, const Vec3& b) {
  return same_bits(a.x(), b.x()) && same_bits(a.y(), b.y()) && same_bits(a.z(), b.z());
}

/// Horizon, gravity, box and boundaries, and every body's fields and changes; the scene
/// must have no shapes, spin or scenery (both sides are checked for that).
inline bool same_bits(const Scene& a, const Scene& b) {
  if (!same_bits(a.horizon, b.horizon) || !same_bits(a.gravity, b.gravity)) return false;
  if (a.box.has_value() != b.box.has_value()) return false;
  if (a.box && (!same_bits(a.box->min, b.box->min) || !same_bits(a.box->max, b.box->max) ||
                a.box->boundary != b.box->boundary))
    return false;
  if (a.is_rigid() || b.is_rigid() || !a.shapes.empty() || !b.shapes.empty() || !a.scenery.empty() ||
      !b.scenery.empty() || a.scenery_mesh || b.scenery_mesh)
    return false;
  if (a.bodies.size() != b.bodies.size()) return false;
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    const Body& x = a.bodies[i];
    const Body& y = b.bodies[i];
    if (!same_bits(x.radius, y.radius) || !same_bits(x.position, y.position) || !same_bits(x.velocity, y.velocity) ||
        !same_bits(x.acceleration, y.acceleration) || x.acceleration_changes.size() != y.acceleration_changes.size() ||
        x.velocity_changes.size() != y.velocity_changes.size())
      return false;
    for (std::size_t k = 0; k < x.acceleration_changes.size(); ++k)
      if (!same_bits(x.acceleration_changes[k].t, y.acceleration_changes[k].t) ||
          !same_bits(x.acceleration_changes[k].acceleration, y.acceleration_changes[k].acceleration))
        return false;
    for (std::size_t k = 0; k < x.velocity_changes.size(); ++k)
      if (!same_bits(x.velocity_changes[k].t, y.velocity_changes[k].t) ||
          !same_bits(x.velocity_changes[k].velocity, y.velocity_changes[k].velocity))
        return false;
  }
  return true;
}

}  // namespace ccd::test
