// `mixed`: moving spheres whose radii span orders of magnitude (log-uniform), in a box:
// the case that defeats a single grid cell size.
#include <generators/box_scene.hpp>
#include <generators/registry.hpp>
#include <generators/placement.hpp>
#include <generators/sampling.hpp>

#include <algorithm>
#include <cmath>

namespace ccdlab {
namespace {

constexpr ParameterSpec kMixedParameters[] = {
    kSeedParameter,
    kBodiesParameter,
    kHorizonParameter,
    kOffsetParameter,
    {"r_min", 0.01, "smallest radius (log r uniform in [log r_min, log r_max]; body 0 gets r_min)",
     ParameterKind::Real, kPositiveLength},
    {"r_max", 10.0, "largest radius (body 1 gets r_max)", ParameterKind::Real, kPositiveLength},
    {"speed_max", 10.0, "speeds uniform in [0, speed_max], directions uniform", ParameterKind::Real,
     kNonNegativeRate},
    kBoxFractionParameter,
    kOverlapParameter,
};

ccd::Scene generate_mixed(const ParameterSet& p) {
  require_not_greater(p, "r_min", "r_max");
  const double r_min = p.number("r_min");
  const double r_max = p.number("r_max");
  const double log_ratio = std::log(r_max / r_min);
  const double speed_max = p.number("speed_max");
  const std::size_t n = p.integer("bodies");
  const double side = cube_side(n, mean_cube_log_uniform(r_min, r_max), p.number("fraction"), r_max);

  ccd::Scene scene = box_scene(p, ccd::Vec3::Constant(side));
  Random rng(p.integer("seed"));
  Placement placement(r_max, p.integer("overlap") == 1);
  for (std::size_t i = 0; i < n; ++i) {
    ccd::Body& b = scene.bodies[i];
    // Bodies 0 and 1 take the extremes exactly (no draw), so every scene of two or more
    // bodies spans the whole range.
    if (i == 0)
      b.radius = r_min;
    else if (i == 1)
      b.radius = r_max;
    else
      b.radius = std::clamp(r_min * std::exp(log_ratio * rng.uniform()), r_min, r_max);
    b.position = placement.place(b.radius, [&] { return rng.position_in_cube(side, b.radius); });
    b.velocity = rng.velocity(speed_max);
  }
  return scene;
}

}  // namespace

extern const Generator kMixedGenerator = {
    "mixed", "moving spheres with log-uniform radii over orders of magnitude (default 0.01..10) in a box",
    kMixedParameters, generate_mixed};

}  // namespace ccdlab
