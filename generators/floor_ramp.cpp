// `floor_ramp`: balls rolling down ramps onto a floor. Static scenery (docs/scenery.md)
// does not push bodies, so the rolling is built into the motion: on its ramp a ball's own
// acceleration cancels the normal part of gravity, so its centre slides down the slope
// pressed 2^-10 r into the ramp (a sustained contact, not a tangency), and at the time it
// passes the ramp's lower edge an acceleration change leaves it to gravity: it drops onto
// the floor polygon (a little above the box floor, so every bounce is a real contact) and
// bounces on between the walls. y is up.
#include <generators/box_scene.hpp>
#include <generators/registry.hpp>
#include <generators/sampling.hpp>

#include <ccd/scene/scenery.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ccdlab {
namespace {

constexpr ParameterSpec kFloorRampParameters[] = {
    kSeedParameter,
    kBodiesParameter,
    kHorizonParameter,
    kOffsetParameter,
    {"radius", 0.1, "radius of every ball", ParameterKind::Real, kPositiveLength, "m"},
    {"ramps", 4.0, "number of ramps, side by side along z", ParameterKind::Integer, {1.0, 1000.0, false, false}},
    {"slope", 0.5, "tangent of the ramps' angle", ParameterKind::Real, {0.0, 4.0, true, false}},
    {"speed_max", 1.0, "start speed down the slope, uniform in [0, speed_max]", ParameterKind::Real,
     kNonNegativeRate, "m/s"},
    {"run_out", 8.0, "length of floor beyond the ramps' lower edges", ParameterKind::Real, kPositiveLength, "m"},
    {"gravity", 9.81, "gravity magnitude; the scene's gravity is [0, -gravity, 0]", ParameterKind::Real,
     {0.0, kMaxRate, true, false}, "m/s^2"},
};

ccd::Scene generate_floor_ramp(const ParameterSet& p) {
  const double r = p.number("radius");
  const std::size_t ramps = p.integer("ramps");
  const double slope = p.number("slope");
  const double speed_max = p.number("speed_max");
  const double g = p.number("gravity");
  const std::size_t n = p.integer("bodies");
  if (p.number("run_out") < 4.0 * r)
    throw std::invalid_argument("run_out (" + format_number(p.number("run_out")) + ") must be >= 4 radius (" +
                                format_number(4.0 * r) + ")");
  // Balls sit on a grid of pitch 2.5 r on each ramp (jittered by at most 0.2 r: apart at t = 0).
  const double pitch = 2.5 * r;
  const std::size_t per_ramp = (n + ramps - 1) / ramps;
  const auto cols = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(std::sqrt(per_ramp / 3.0))));
  const std::size_t rows = (per_ramp + cols - 1) / cols;
  const double width = static_cast<double>(cols) * pitch;
  const double length = static_cast<double>(rows + 1) * pitch;  // along the slope, one free pitch at the bottom
  const double theta = std::atan(slope);
  const double c = std::cos(theta), s = std::sin(theta);
  const double run = length * c;
  const double y_bottom = r;  // lower edge: the centre stays above the floor wall y = r on the ramp
  const double y_top = y_bottom + length * s;
  const double y_floor = r / 8.0;
  const double lane = width + pitch;
  const double x_size = run + p.number("run_out");
  const double z_size = static_cast<double>(ramps) * lane;
  // Own acceleration does no work on the ramp (normal to the velocity), so no ball rises
  // above its start height + speed_max^2 / (2 g).
  const double y_size = y_top + 3.0 * r + speed_max * speed_max / (2.0 * g);

  ccd::Scene scene = box_scene(p, ccd::Vec3(x_size, y_size, z_size));
  scene.gravity = ccd::Vec3(0.0, -g, 0.0);
  scene.scenery.push_back(ccd::polygon_from_vertices({ccd::Vec3(0, y_floor, 0), ccd::Vec3(x_size, y_floor, 0),
                                                      ccd::Vec3(x_size, y_floor, z_size),
                                                      ccd::Vec3(0, y_floor, z_size)}));
  for (std::size_t k = 0; k < ramps; ++k) {
    const double z0 = static_cast<double>(k) * lane + 0.5 * pitch, z1 = z0 + width;
    scene.scenery.push_back(ccd::polygon_from_vertices({ccd::Vec3(0, y_top, z0), ccd::Vec3(run, y_bottom, z0),
                                                        ccd::Vec3(run, y_bottom, z1), ccd::Vec3(0, y_top, z1)}));
  }
  const ccd::Vec3 normal(s, c, 0.0);     // the ramps' upward unit normal
  const ccd::Vec3 downhill(c, -s, 0.0);  // unit, in the ramp's plane
  const double press = r * (1.0 - 0x1p-10);
  Random rng(p.integer("seed"));
  for (std::size_t i = 0; i < n; ++i) {
    ccd::Body& b = scene.bodies[i];
    const std::size_t ramp = i % ramps, j = i / ramps;
    const double along = (static_cast<double>(j / cols) + 0.5) * pitch + rng.uniform(-0.2, 0.2) * r;
    const double across = static_cast<double>(ramp) * lane + 0.5 * pitch +
                          (static_cast<double>(j % cols) + 0.5) * pitch + rng.uniform(-0.2, 0.2) * r;
    const double v0 = rng.uniform(0.0, speed_max);
    b.radius = r;
    b.position = ccd::Vec3(along * c, y_top - along * s, across) + press * normal;
    b.velocity = v0 * downhill;
    b.acceleration = (g * c) * normal;  // cancels gravity's normal part: net g sin(theta) downhill
    // Leaves the ramp when it has slid the remaining length D: D = v0 t + g s t^2 / 2.
    const double D = length - along, a = g * s;
    const double t_end = 2.0 * D / (v0 + std::sqrt(v0 * v0 + 2.0 * a * D));
    if (t_end > 0.0 && t_end < scene.horizon) b.acceleration_changes.push_back({t_end, ccd::Vec3::Zero()});
  }
  return scene;
}

}  // namespace

extern const Generator kFloorRampGenerator = {
    "floor_ramp", "balls rolling down ramps onto a floor (static scenery: ramps and a floor polygon)", kFloorRampParameters,
    generate_floor_ramp};

}  // namespace ccdlab
