// `swarm`: Hubbard's setting. Bodies in a box with bounded, piecewise-constant random
// accelerations: |a| <= max_acceleration at all times, changing at known times.
#include <generators/box_scene.hpp>
#include <generators/registry.hpp>
#include <generators/placement.hpp>
#include <generators/sampling.hpp>

#include <algorithm>
#include <vector>

namespace ccdlab {
namespace {

constexpr ParameterSpec kSwarmParameters[] = {
    kSeedParameter,
    kBodiesParameter,
    kHorizonParameter,
    kOffsetParameter,
    uniform_r_min_parameter(0.5),
    r_max_parameter(1.5),
    kBoxFractionParameter,
    {"speed_max", 5.0, "initial speeds uniform in [0, speed_max], directions uniform", ParameterKind::Real,
     kNonNegativeRate},
    {"max_acceleration", 20.0, "every acceleration is uniform in the ball of this radius", ParameterKind::Real,
     kNonNegativeRate},
    {"changes", 4.0, "acceleration changes per body, at times in (0, horizon)", ParameterKind::Integer,
     {0.0, 1000.0, false, false}},
    {"regular", 0.0, "1: changes at horizon k / (changes + 1); 0: at sorted uniform random times",
     ParameterKind::Integer, {0.0, 1.0, false, false}},
    kOverlapParameter,
};

// `count` sorted times uniform in (0, horizon), strictly increasing; the whole set is
// drawn again in the (rare) case of a time at 0 or horizon or two equal times.
void random_times(Random& rng, double horizon, std::vector<double>& t) {
  while (true) {
    for (double& x : t) x = horizon * rng.uniform();
    std::sort(t.begin(), t.end());
    const bool inside = t.empty() || (t.front() > 0.0 && t.back() < horizon);
    if (inside && std::adjacent_find(t.begin(), t.end()) == t.end()) return;
  }
}

ccd::Scene generate_swarm(const ParameterSet& p) {
  require_not_greater(p, "r_min", "r_max");
  const double r_min = p.number("r_min");
  const double r_max = p.number("r_max");
  const double speed_max = p.number("speed_max");
  const double max_acc = p.number("max_acceleration");
  const double horizon = p.number("horizon");
  const std::size_t changes = p.integer("changes");
  const bool regular = p.integer("regular") == 1;
  const std::size_t n = p.integer("bodies");
  const double side = cube_side(n, mean_cube_uniform(r_min, r_max), p.number("fraction"), r_max);

  std::vector<double> times(changes);
  for (std::size_t k = 0; k < changes; ++k)
    times[k] = horizon * (static_cast<double>(k + 1) / static_cast<double>(changes + 1));

  ccd::Scene scene = box_scene(p, ccd::Vec3::Constant(side));
  Random rng(p.integer("seed"));
  Placement placement(r_max, p.integer("overlap") == 1);
  for (ccd::Body& b : scene.bodies) {
    b.radius = rng.uniform(r_min, r_max);
    b.position = placement.place(b.radius, [&] { return rng.position_in_cube(side, b.radius); });
    b.velocity = rng.velocity(speed_max);
    b.acceleration = rng.in_ball(max_acc);
    if (!regular) random_times(rng, horizon, times);
    b.acceleration_changes.resize(changes);
    for (std::size_t k = 0; k < changes; ++k) {
      b.acceleration_changes[k].t = times[k];
      b.acceleration_changes[k].acceleration = rng.in_ball(max_acc);
    }
  }
  return scene;
}

}  // namespace

extern const Generator kSwarmGenerator = {
    "swarm", "Hubbard's setting: bounded piecewise-constant random accelerations (|a| <= max_acceleration) in a box",
    kSwarmParameters, generate_swarm};

}  // namespace ccdlab
