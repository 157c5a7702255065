// `lattice`: spheres on a cubic lattice, each exactly touching its neighbours: every
// centre is (2i + 2) r on every axis, with r a power of two, so all coordinates, gaps and
// distances are exact (neighbour distance == 2r). Degenerate on purpose: equal
// coordinates everywhere and tangent contacts at t = 0.
#include <generators/box_scene.hpp>
#include <generators/registry.hpp>
#include <generators/sampling.hpp>

#include <cmath>
#include <stdexcept>

namespace ccdlab {
namespace {

constexpr ParameterSpec kLatticeParameters[] = {
    kSeedParameter,
    kBodiesParameter,
    kHorizonParameter,
    kOffsetParameter,
    {"radius", 0.5, "radius of every sphere; a power of two (lattice spacing 2 radius)", ParameterKind::Real,
     {1e-9, 1e4, false, false}},
    {"speed", 0.0, "each body moves at this speed along a random axis, random sign (0: at rest)",
     ParameterKind::Real, kNonNegativeRate},
};

ccd::Scene generate_lattice(const ParameterSet& p) {
  const double r = p.number("radius");
  int exponent = 0;
  if (std::frexp(r, &exponent) != 0.5)
    throw std::invalid_argument("parameter 'radius': must be a power of two, so that the lattice is exact (got " +
                                format_number(r) + ")");
  const double speed = p.number("speed");
  const std::size_t n = p.integer("bodies");
  std::size_t per_side = 1;  // smallest m with m^3 >= n
  while (per_side * per_side * per_side < n) ++per_side;
  // Centres (2i + 2) r, i < per_side: one radius of clearance to every wall.
  const double side = 2.0 * static_cast<double>(per_side + 1) * r;

  ccd::Scene scene = box_scene(p, ccd::Vec3::Constant(side));
  Random rng(p.integer("seed"));
  for (std::size_t k = 0; k < n; ++k) {
    ccd::Body& b = scene.bodies[k];
    const std::size_t i = k % per_side;
    const std::size_t j = (k / per_side) % per_side;
    const std::size_t l = k / (per_side * per_side);
    auto centre = [&](std::size_t index) { return static_cast<double>(2 * index + 2) * r; };
    b.radius = r;
    b.position = ccd::Vec3(centre(i), centre(j), centre(l));
    const std::size_t axis = rng.index(3);
    const bool positive = rng.uniform() < 0.5;
    if (speed > 0.0) b.velocity[static_cast<Eigen::Index>(axis)] = positive ? speed : -speed;
  }
  return scene;
}

}  // namespace

extern const Generator kLatticeGenerator = {
    "lattice", "spheres on a cubic lattice exactly touching their neighbours (spacing 2r), optional axis velocities",
    kLatticeParameters, generate_lattice};

}  // namespace ccdlab
