// `pinball`: fast small balls among many small thin obstacles: upright rectangles (static
// scenery, docs/scenery.md) at random places and headings. A ball moves much further in a
// step than its diameter, so a method that samples positions tunnels through obstacles.
// Scenery does not push bodies: the balls bounce off the box walls only. y is up.
#include <generators/box_scene.hpp>
#include <generators/placement.hpp>
#include <generators/registry.hpp>
#include <generators/sampling.hpp>

#include <ccd/scene/scenery.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ccdlab {
namespace {

constexpr ParameterSpec kPinballParameters[] = {
    kSeedParameter,
    kBodiesParameter,
    kHorizonParameter,
    kOffsetParameter,
    uniform_r_min_parameter(0.02),
    r_max_parameter(0.05),
    {"speed", 20.0, "speed of every ball, mostly horizontal (vertical part uniform in +-0.1 speed)",
     ParameterKind::Real, kNonNegativeRate, "m/s"},
    {"obstacles", 200.0, "number of obstacles", ParameterKind::Integer, {0.0, 1e6, false, false}},
    {"size", 0.5, "width of every obstacle (its height is 0.8 height)", ParameterKind::Real, kPositiveLength, "m"},
    {"side", 10.0, "the box is [0, side] x [0, height] x [0, side]", ParameterKind::Real, kPositiveLength, "m"},
    {"height", 1.0, "height of the box", ParameterKind::Real, kPositiveLength, "m"},
    kOverlapParameter,
};

ccd::Scene generate_pinball(const ParameterSet& p) {
  require_not_greater(p, "r_min", "r_max");
  const double r_min = p.number("r_min"), r_max = p.number("r_max");
  const double speed = p.number("speed");
  const double size = p.number("size"), side = p.number("side"), height = p.number("height");
  if (side < 2.0 * size + 4.0 * r_max)
    throw std::invalid_argument("side (" + format_number(side) + ") must be >= 2 size + 4 r_max (" +
                                format_number(2.0 * size + 4.0 * r_max) + ")");
  if (height < 4.0 * r_max)
    throw std::invalid_argument("height (" + format_number(height) + ") must be >= 4 r_max (" +
                                format_number(4.0 * r_max) + ")");
  ccd::Scene scene = box_scene(p, ccd::Vec3(side, height, side));
  Random rng(p.integer("seed"));
  const double y0 = 0.1 * height, y1 = 0.9 * height, half = 0.5 * size;
  for (std::size_t k = 0; k < p.integer("obstacles"); ++k) {
    const double x = rng.uniform(size, side - size), z = rng.uniform(size, side - size);
    const double a = rng.uniform(0.0, std::numbers::pi);
    const double dx = half * std::cos(a), dz = half * std::sin(a);
    // Two bottom and two top corners over the same (x, z) pairs: exactly planar.
    scene.scenery.push_back(ccd::polygon_from_vertices({ccd::Vec3(x - dx, y0, z - dz), ccd::Vec3(x + dx, y0, z + dz),
                                                        ccd::Vec3(x + dx, y1, z + dz), ccd::Vec3(x - dx, y1, z - dz)}));
  }
  Placement placement(r_max, p.integer("overlap") == 1);
  for (ccd::Body& b : scene.bodies) {
    b.radius = rng.uniform(r_min, r_max);
    b.position = placement.place(b.radius, [&] {
      const double x = rng.coordinate(0.0, side, b.radius);
      const double y = rng.coordinate(0.0, height, b.radius);
      const double z = rng.coordinate(0.0, side, b.radius);
      return ccd::Vec3(x, y, z);
    });
    const double a = rng.uniform(0.0, 2.0 * std::numbers::pi);
    b.velocity = speed * ccd::Vec3(std::cos(a), rng.uniform(-0.1, 0.1), std::sin(a));
  }
  return scene;
}

}  // namespace

extern const Generator kPinballGenerator = {
    "pinball", "fast small balls among many thin upright obstacles (static scenery): tunnelling", kPinballParameters,
    generate_pinball};

}  // namespace ccdlab
