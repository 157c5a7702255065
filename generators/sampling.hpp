#pragma once
// Random draws shared by the scene generators, defined bit for bit so that a seed gives
// the same scene on every run (and, given the same libm for exp/log/cbrt, on every
// machine): std::mt19937_64 seeded with the seed, and uniform doubles built from its top
// 53 bits, never from std::uniform_real_distribution (whose algorithm is the library's).
// Each function's comment states how many engine outputs it consumes; docs/generators.md
// lists the order of the calls per generator.
#include <ccd/geometry/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <random>

namespace ccdlab {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [0, 1) on the grid k 2^-53: (engine() >> 11) * 2^-53. One output.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  /// lo + (hi - lo) u, in [lo, hi] (hi itself only by rounding). One output.
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// floor(n u), in [0, n) for n >= 1. One output.
  std::size_t index(std::size_t n);
  /// A point uniform in the cube [-1, 1]^3: three outputs, drawn z first, then y, then x
  /// (each 2u - 1).
  ccd::Vec3 unit_cube();
  /// Unit vector, uniform on the sphere: rejection in the unit ball (unit_cube() per try,
  /// accepted when 0 < |x|^2 <= 1), then normalised.
  ccd::Vec3 direction();
  /// Uniform in the ball of radius `radius`: radius * x with x drawn as in direction()
  /// (0 accepted), retried until the computed norm is <= radius, so the bound holds in
  /// floating point. Three outputs per try.
  ccd::Vec3 in_ball(double radius);
  /// Uniform in the disc of radius `radius` in the plane of axes 0 and 2: as in_ball with
  /// two outputs (x, z) per try; component 1 is 0.
  ccd::Vec3 in_horizontal_disc(double radius);
  /// A centre coordinate for a sphere of radius r between walls lo < hi: uniform in
  /// [lo + r, hi - r], retried (one output per try) until fl(p - r) >= lo and
  /// fl(p + r) <= hi, the test of ccd::validate_scene. Requires hi - lo >= 4r (throws
  /// std::logic_error otherwise).
  double coordinate(double lo, double hi, double r);
  /// Centre of a sphere of radius r in the cube [0, side]^3: coordinate() for x, y, z.
  ccd::Vec3 position_in_cube(double side, double r);
  /// Velocity of uniform direction and speed uniform in [0, speed_max]: direction()
  /// first, then the speed (one output).
  ccd::Vec3 velocity(double speed_max);

 private:
  std::mt19937_64 engine_;
};

/// Side L of a cube that N spheres of mean cubed radius `mean_r3` fill to volume
/// `fraction`: cbrt(N (4/3) pi mean_r3 / fraction), but at least 4 r_max so that every
/// sphere fits with room to move.
double cube_side(std::size_t bodies, double mean_r3, double fraction, double r_max);
/// E[r^3] for r ~ U[a, b] (a <= b): (b^4 - a^4) / (4 (b - a)), or a^3 when a == b.
double mean_cube_uniform(double a, double b);
/// E[r^3] for log r ~ U[log a, log b]: (b^3 - a^3) / (3 ln(b / a)), or a^3 when a == b.
double mean_cube_log_uniform(double a, double b);

}  // namespace ccdlab
