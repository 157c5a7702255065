// `rain`: balls falling under gravity in a tall column onto the floor of a box; every
// wall (the floor too) is elastic, so the balls bounce back up. Everything moves along y,
// the worst axis for sweep and prune.
#include <generators/box_scene.hpp>
#include <generators/registry.hpp>
#include <generators/placement.hpp>
#include <generators/sampling.hpp>

namespace ccdlab {
namespace {

constexpr ParameterSpec kRainParameters[] = {
    kSeedParameter,
    kBodiesParameter,
    kHorizonParameter,
    kOffsetParameter,
    uniform_r_min_parameter(0.5),
    r_max_parameter(1.0),
    {"fraction", 0.02, "volume fraction of the column filled by the balls", ParameterKind::Real,
     kVolumeFraction},
    {"aspect", 4.0, "column height / width: the box is [0, W] x [0, aspect W] x [0, W]", ParameterKind::Real,
     {1.0, 1000.0, false, false}},
    {"speed_max", 1.0, "horizontal velocity uniform in the disc of this radius (vertical: 0)",
     ParameterKind::Real, kNonNegativeRate},
    {"gravity", 9.81, "gravity magnitude; the scene's gravity is [0, -gravity, 0]", ParameterKind::Real,
     kNonNegativeRate},
    kOverlapParameter,
};

ccd::Scene generate_rain(const ParameterSet& p) {
  require_not_greater(p, "r_min", "r_max");
  const double r_min = p.number("r_min");
  const double r_max = p.number("r_max");
  const double aspect = p.number("aspect");
  const double speed_max = p.number("speed_max");
  const std::size_t n = p.integer("bodies");
  // W^3 aspect = N (4/3) pi E[r^3] / fraction, and W >= 4 r_max (so H = aspect W >= 4 r_max too).
  const double width = cube_side(n, mean_cube_uniform(r_min, r_max), p.number("fraction") * aspect, r_max);
  const double height = aspect * width;

  ccd::Scene scene = box_scene(p, ccd::Vec3(width, height, width));
  scene.gravity = ccd::Vec3(0.0, -p.number("gravity"), 0.0);
  Random rng(p.integer("seed"));
  Placement placement(r_max, p.integer("overlap") == 1);
  for (ccd::Body& b : scene.bodies) {
    b.radius = rng.uniform(r_min, r_max);
    b.position = placement.place(b.radius, [&] {
      const double x = rng.coordinate(0.0, width, b.radius);
      const double y = rng.coordinate(0.0, height, b.radius);
      const double z = rng.coordinate(0.0, width, b.radius);
      return ccd::Vec3(x, y, z);
    });
    b.velocity = rng.in_horizontal_disc(speed_max);
  }
  return scene;
}

}  // namespace

extern const Generator kRainGenerator = {
    "rain", "balls falling under gravity [0, -g, 0] in a tall column onto the floor of a box; elastic walls",
    kRainParameters, generate_rain};

}  // namespace ccdlab
