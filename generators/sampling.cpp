#include <generators/sampling.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ccdlab {

std::size_t Random::index(std::size_t n) {
  const auto i = static_cast<std::size_t>(uniform() * static_cast<double>(n));
  return std::min(i, n == 0 ? 0 : n - 1);  // u n < n in exact arithmetic; guard the rounding
}

// The three draws of a try come in the order z, y, x (one statement each: the order of a
// constructor's arguments is unspecified, and GCC, which made the published scenes,
// evaluated them last to first).
ccd::Vec3 Random::unit_cube() {
  const double z = 2.0 * uniform() - 1.0;
  const double y = 2.0 * uniform() - 1.0;
  const double x = 2.0 * uniform() - 1.0;
  return {x, y, z};
}

ccd::Vec3 Random::direction() {
  while (true) {
    const ccd::Vec3 x = unit_cube();
    const double n2 = x.squaredNorm();
    if (n2 > 0.0 && n2 <= 1.0) return x / std::sqrt(n2);
  }
}

ccd::Vec3 Random::in_ball(double radius) {
  while (true) {
    const ccd::Vec3 x = unit_cube();
    if (x.squaredNorm() > 1.0) continue;
    const ccd::Vec3 a = radius * x;
    if (a.norm() <= radius) return a;
  }
}

ccd::Vec3 Random::in_horizontal_disc(double radius) {
  while (true) {
    const double x = 2.0 * uniform() - 1.0;
    const double z = 2.0 * uniform() - 1.0;
    if (x * x + z * z > 1.0) continue;
    const ccd::Vec3 a(radius * x, 0.0, radius * z);
    if (a.norm() <= radius) return a;
  }
}

double Random::coordinate(double lo, double hi, double r) {
  if (!(hi - lo >= 4.0 * r)) throw std::logic_error("Random::coordinate: walls closer than 4 radii");
  while (true) {
    const double p = uniform(lo + r, hi - r);
    if (!(p - r < lo) && !(p + r > hi)) return p;
  }
}

ccd::Vec3 Random::position_in_cube(double side, double r) {
  const double x = coordinate(0.0, side, r);
  const double y = coordinate(0.0, side, r);
  const double z = coordinate(0.0, side, r);
  return {x, y, z};
}

ccd::Vec3 Random::velocity(double speed_max) {
  const ccd::Vec3 dir = direction();
  return uniform(0.0, speed_max) * dir;
}

double cube_side(std::size_t bodies, double mean_r3, double fraction, double r_max) {
  const double volume = static_cast<double>(bodies) * (4.0 / 3.0) * std::numbers::pi * mean_r3;
  return std::max(std::cbrt(volume / fraction), 4.0 * r_max);
}

double mean_cube_uniform(double a, double b) {
  if (a == b) return a * a * a;
  return (b * b * b * b - a * a * a * a) / (4.0 * (b - a));
}

double mean_cube_log_uniform(double a, double b) {
  if (a == b) return a * a * a;
  return (b * b * b - a * a * a) / (3.0 * std::log(b / a));
}

}  // namespace ccdlab
