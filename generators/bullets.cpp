// `bullets`: a slow field of larger spheres and a few small fast spheres aimed at field
// bodies: the case where a discrete check at a coarse timestep tunnels through contacts.
#include <generators/box_scene.hpp>
#include <generators/registry.hpp>
#include <generators/placement.hpp>
#include <generators/sampling.hpp>

#include <algorithm>

namespace ccdlab {
namespace {

constexpr ParameterSpec kBulletsParameters[] = {
    kSeedParameter,
    kBodiesParameter,
    kHorizonParameter,
    kOffsetParameter,
    {"bullets", 10.0, "how many of the bodies are bullets (at most bodies; the last ones)", ParameterKind::Integer,
     {0.0, kMaxBodies, false, false}},
    {"r_min", 0.5, "smallest field radius (field radii uniform in [r_min, r_max])", ParameterKind::Real,
     kPositiveLength},
    {"r_max", 1.5, "largest field radius", ParameterKind::Real, kPositiveLength},
    {"speed_max", 1.0, "field speeds uniform in [0, speed_max], directions uniform", ParameterKind::Real,
     kNonNegativeRate},
    {"fraction", 0.02, "volume fraction of the box [0, L]^3 filled by the field", ParameterKind::Real,
     kVolumeFraction},
    {"bullet_radius", 0.05, "radius of every bullet", ParameterKind::Real, kPositiveLength},
    {"bullet_speed", 200.0, "speed of every bullet", ParameterKind::Real, kNonNegativeRate},
    kOverlapParameter,
};

ccd::Scene generate_bullets(const ParameterSet& p) {
  require_not_greater(p, "r_min", "r_max");
  const double r_min = p.number("r_min");
  const double r_max = p.number("r_max");
  const double speed_max = p.number("speed_max");
  const double bullet_radius = p.number("bullet_radius");
  const double bullet_speed = p.number("bullet_speed");
  const std::size_t n = p.integer("bodies");
  const std::size_t n_bullets = std::min<std::size_t>(p.integer("bullets"), n);
  const std::size_t n_field = n - n_bullets;
  const double side =
      cube_side(n_field, mean_cube_uniform(r_min, r_max), p.number("fraction"), std::max(r_max, bullet_radius));

  ccd::Scene scene = box_scene(p, ccd::Vec3::Constant(side));
  Random rng(p.integer("seed"));
  Placement placement(std::max(r_max, bullet_radius), p.integer("overlap") == 1);
  for (std::size_t i = 0; i < n_field; ++i) {
    ccd::Body& b = scene.bodies[i];
    b.radius = rng.uniform(r_min, r_max);
    b.position = placement.place(b.radius, [&] { return rng.position_in_cube(side, b.radius); });
    b.velocity = rng.velocity(speed_max);
  }
  for (std::size_t i = n_field; i < n; ++i) {
    ccd::Body& b = scene.bodies[i];
    b.radius = bullet_radius;
    b.position = placement.place(b.radius, [&] { return rng.position_in_cube(side, b.radius); });
    // Aim at a random field body's centre at t = 0 (or a random point without a field).
    const ccd::Vec3 target = n_field > 0 ? scene.bodies[rng.index(n_field)].position
                                         : rng.position_in_cube(side, bullet_radius);
    const ccd::Vec3 towards = target - b.position;
    const double length = towards.norm();
    const ccd::Vec3 dir = length > 0.0 ? ccd::Vec3(towards / length) : rng.direction();
    b.velocity = bullet_speed * dir;
  }
  return scene;
}

}  // namespace

extern const Generator kBulletsGenerator = {
    "bullets", "a slow field of spheres and small fast bullets aimed at field bodies (tunnelling)", kBulletsParameters,
    generate_bullets};

}  // namespace ccdlab
