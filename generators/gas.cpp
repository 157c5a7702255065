// `gas`: spheres in a box moving in straight lines (no gravity, elastic walls, or with
// wrap=1 a box that loops around on every axis).
#include <generators/box_scene.hpp>
#include <generators/registry.hpp>
#include <generators/placement.hpp>
#include <generators/sampling.hpp>

namespace ccdlab {
namespace {

constexpr ParameterSpec kGasParameters[] = {
    kSeedParameter,
    kBodiesParameter,
    kHorizonParameter,
    kOffsetParameter,
    uniform_r_min_parameter(0.5),
    r_max_parameter(1.5),
    {"speed_max", 10.0, "speeds uniform in [0, speed_max], directions uniform", ParameterKind::Real,
     kNonNegativeRate},
    kBoxFractionParameter,
    kOverlapParameter,
    {"wrap", 0.0, "1: the box wraps around on every axis (periodic, no walls); 0: elastic walls",
     ParameterKind::Integer, {0.0, 1.0, false, false}},
};

ccd::Scene generate_gas(const ParameterSet& p) {
  require_not_greater(p, "r_min", "r_max");
  const double r_min = p.number("r_min");
  const double r_max = p.number("r_max");
  const double speed_max = p.number("speed_max");
  const std::size_t n = p.integer("bodies");
  const double side = cube_side(n, mean_cube_uniform(r_min, r_max), p.number("fraction"), r_max);

  ccd::Scene scene = box_scene(p, ccd::Vec3::Constant(side));
  Random rng(p.integer("seed"));
  Placement placement(r_max, p.integer("overlap") == 1);
  for (ccd::Body& b : scene.bodies) {
    b.radius = rng.uniform(r_min, r_max);
    b.position = placement.place(b.radius, [&] { return rng.position_in_cube(side, b.radius); });
    b.velocity = rng.velocity(speed_max);
  }
  // The side is at least 4 r_max (cube_side): twice the largest diameter, as wrapping needs.
  if (p.integer("wrap") == 1) scene.box->boundary.fill(ccd::Boundary::Wrap);
  return scene;
}

}  // namespace

extern const Generator kGasGenerator = {
    "gas", "spheres in a box [0, L]^3, straight-line motion, elastic walls (or wrap=1: periodic), no gravity", kGasParameters,
    generate_gas};

}  // namespace ccdlab
