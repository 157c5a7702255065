// `grazing`: pairs of equal spheres, one at rest and one passing it in a straight line,
// whose closest approach is exactly tangent, one ulp beyond tangent, a shallow crossing
// or a near miss, at times on or off a dyadic grid of sample times. Built so that the
// tangent cases are exact in floating point: the radius and the speed are powers of two
// and the offset of the passing line is a difference of exactly representable
// coordinates, so the closest distance computed from the scene is exactly the intended
// one (see docs/generators.md).
#include <generators/box_scene.hpp>
#include <generators/registry.hpp>
#include <generators/sampling.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace ccdlab {
namespace {

constexpr ParameterSpec kGrazingParameters[] = {
    kSeedParameter,
    kBodiesParameter,
    kHorizonParameter,
    kOffsetParameter,
    {"radius", 0.5, "radius of every sphere; a power of two", ParameterKind::Real, {1e-9, 1e4, false, false}},
    {"speed", 8.0, "speed of the passing sphere of each pair; a power of two", ParameterKind::Real,
     {1e-9, kMaxRate, false, false}},
    {"gap", 1e-6, "relative miss distance of shallow crossings and near misses: R (1 -+ gap), R = 2 radius",
     ParameterKind::Real, {0.0, 0.5, true, false}},
    {"tick", 0.015625, "grid of closest-approach times (a power of two <= horizon / 2): on-grid pairs pass at k tick",
     ParameterKind::Real, {1e-9, 1e9, false, false}},
};

bool power_of_two(double x) {
  int exponent = 0;
  return std::frexp(x, &exponent) == 0.5;
}

ccd::Scene generate_grazing(const ParameterSet& p) {
  const double r = p.number("radius");
  const double speed = p.number("speed");
  const double gap = p.number("gap");
  const double tick = p.number("tick");
  const double horizon = p.number("horizon");
  for (const char* name : {"radius", "speed", "tick"})
    if (!power_of_two(p.number(name)))
      throw std::invalid_argument(std::string("parameter '") + name +
                                  "': must be a power of two, so that tangent contacts are exact (got " +
                                  format_number(p.number(name)) + ")");
  // Closest-approach times are k tick, k = 1 .. ticks - 1, strictly inside (0, horizon).
  const double ticks = std::floor(horizon / tick);
  if (ticks < 2.0)
    throw std::invalid_argument("tick (" + format_number(tick) + ") must be <= horizon / 2 (" +
                                format_number(horizon / 2) + ")");
  const std::size_t n = p.integer("bodies");
  const std::size_t pairs = (n + 1) / 2;  // an odd last body sits alone in the last cell
  const double R = 2.0 * r;
  // Pairs sit in cells of a square grid in (y, z) of pitch 4R: the passing sphere of a
  // pair is at least 4R - R (1 + gap) - ... > R from every other pair's spheres.
  const double pitch = 4.0 * R;
  std::size_t per_side = 1;
  while (per_side * per_side < pairs) ++per_side;
  // Along x the passing sphere travels from 2r to 2r + speed * horizon; the box leaves one
  // radius of clearance beyond both ends, so nothing reaches a wall.
  const double length = 4.0 * r + speed * horizon;
  const double width = static_cast<double>(per_side) * pitch;

  ccd::Scene scene = box_scene(p, ccd::Vec3(length, width, width));
  Random rng(p.integer("seed"));
  const std::size_t max_k = static_cast<std::size_t>(ticks) - 1;  // k in [1, max_k]
  for (std::size_t q = 0; q < pairs; ++q) {
    // Cell (i, j): the resting sphere at y = R + i pitch, z = R + j pitch (exact: small
    // multiples of a power of two).
    const double y = R + static_cast<double>(q % per_side) * pitch;
    const double z = R + static_cast<double>(q / per_side) * pitch;
    const std::size_t kind = q % 4;          // tangent, ulp beyond, shallow crossing, near miss
    const bool on_grid = (q / 4) % 2 == 0;  // closest approach at k tick, or between ticks
    const double k = static_cast<double>(1 + rng.index(max_k));
    const double u = rng.uniform(0.25, 0.75);
    const double t_close = on_grid ? k * tick : (k - 1.0 + u) * tick;
    // The passing line's y: y + R is exact (a small integer times a power of two), its
    // successor is one ulp beyond, and either minus y is exact (Sterbenz: y <= y + R <=
    // 2y), so the computed closest distance is exactly R or exactly one ulp more.
    double pass_y = y + R;
    if (kind == 1) pass_y = std::nextafter(y + R, std::numeric_limits<double>::infinity());
    if (kind == 2) pass_y = y + R * (1.0 - gap);
    if (kind == 3) pass_y = y + R * (1.0 + gap);
    ccd::Body& rest = scene.bodies[2 * q];
    rest.radius = r;
    rest.position = ccd::Vec3(2.0 * r + speed * t_close, y, z);
    if (2 * q + 1 == n) continue;  // odd body count: the last body rests alone
    ccd::Body& pass = scene.bodies[2 * q + 1];
    pass.radius = r;
    // x: 2r + speed k tick - 2r is exact, so the closest approach is at exactly k tick.
    pass.position = ccd::Vec3(2.0 * r, pass_y, z);
    pass.velocity = ccd::Vec3(speed, 0.0, 0.0);
  }
  return scene;
}

}  // namespace

extern const Generator kGrazingGenerator = {
    "grazing",
    "pairs passing at exactly tangent, one ulp beyond, shallow-crossing or near-miss distance, on or off a time grid",
    kGrazingParameters, generate_grazing};

}  // namespace ccdlab
