// `tumble`: spinning rigid bodies (crates, sticks, plates and rocks in turn) falling under
// gravity onto static scenery: a floor polygon a little above the box floor and a tilted
// ramp across half of the box. Scenery does not push bodies (docs/scenery.md): the bodies
// bounce off the box walls (as their enclosing spheres) and pass through the ramp, so the
// static contacts are where a spinning shape, not its enclosing sphere, meets a polygon:
// whether a body touches the floor at a bounce depends on its orientation then. y is up.
#include <generators/box_scene.hpp>
#include <generators/placement.hpp>
#include <generators/registry.hpp>
#include <generators/sampling.hpp>

#include <ccd/scene/scenery.hpp>
#include <ccd/shape/shape.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace ccdlab {
namespace {

constexpr ParameterSpec kTumbleParameters[] = {
    kSeedParameter,
    kBodiesParameter,
    kHorizonParameter,
    kOffsetParameter,
    {"size", 0.25, "largest half extent of every shape", ParameterKind::Real, kPositiveLength, "m"},
    {"speed_max", 2.0, "velocity uniform in the ball of this radius", ParameterKind::Real, kNonNegativeRate, "m/s"},
    {"spin_max", 8.0, "spin rates uniform in [0, spin_max] about uniform axes", ParameterKind::Real,
     kNonNegativeRate, "rad/s"},
    {"gravity", 9.81, "gravity magnitude; the scene's gravity is [0, -gravity, 0]", ParameterKind::Real,
     {0.0, kMaxRate, true, false}, "m/s^2"},
    kOverlapParameter,
};

ccd::Scene generate_tumble(const ParameterSet& p) {
  const double size = p.number("size");
  const std::size_t n = p.integer("bodies");
  std::vector<ccd::Shape> shapes;
  shapes.push_back(ccd::make_box_shape(ccd::Vec3(size, 0.5 * size, 0.25 * size), "crate"));
  shapes.push_back(ccd::make_capsule_shape(size, 0.125 * size, "stick"));
  shapes.push_back(ccd::make_box_shape(ccd::Vec3(size, size, 0.0625 * size), "plate"));
  shapes.push_back(ccd::make_hull_shape({ccd::Vec3(size, 0, 0), ccd::Vec3(-0.5 * size, 0.75 * size, 0),
                                         ccd::Vec3(-0.5 * size, -0.5 * size, 0.5 * size),
                                         ccd::Vec3(0, -0.25 * size, -0.75 * size), ccd::Vec3(0, 0.5 * size, 0.5 * size)},
                                        "rock"));
  double r_max = 0.0;
  for (const ccd::Shape& s : shapes) r_max = std::max(r_max, s.enclosing_radius());
  // A cube with room for about one body per (4 r_max)^2 of floor.
  const double side = std::max(8.0, 4.0 * std::ceil(std::sqrt(static_cast<double>(n)))) * r_max;
  ccd::Scene scene = box_scene(p, ccd::Vec3::Constant(side));
  scene.gravity = ccd::Vec3(0.0, -p.number("gravity"), 0.0);
  scene.shapes = shapes;
  const double y_floor = 0.25 * r_max;
  scene.scenery.push_back(ccd::polygon_from_vertices({ccd::Vec3(0, y_floor, 0), ccd::Vec3(side, y_floor, 0),
                                                      ccd::Vec3(side, y_floor, side), ccd::Vec3(0, y_floor, side)}));
  scene.scenery.push_back(ccd::polygon_from_vertices({ccd::Vec3(0, 0.75 * side, 0), ccd::Vec3(0.5 * side, 0.25 * side, 0),
                                                      ccd::Vec3(0.5 * side, 0.25 * side, side),
                                                      ccd::Vec3(0, 0.75 * side, side)}));
  std::vector<ccd::Body> bodies = std::move(scene.bodies);
  scene.bodies.clear();
  Placement placement(r_max, p.integer("overlap") == 1);
  Random rng(p.integer("seed"));
  for (std::size_t i = 0; i < n; ++i) {
    ccd::Body b = bodies[i];
    ccd::RigidBody r;
    r.shape = static_cast<std::int32_t>(i % shapes.size());
    b.radius = shapes[i % shapes.size()].enclosing_radius();
    b.position = placement.place(b.radius, [&] {
      // Above the ramp's top edge (3/4 side), below the ceiling.
      // z, then y, then x (one statement each: the order of arguments is unspecified).
      const double z = rng.uniform(b.radius, side - b.radius);
      const double y = rng.uniform(0.75 * side + b.radius, side - b.radius);
      const double x = rng.uniform(b.radius, side - b.radius);
      return ccd::Vec3(x, y, z);
    });
    b.velocity = rng.in_ball(p.number("speed_max"));
    const ccd::Vec3 q = rng.in_ball(1.0);
    const double w = rng.uniform(-1.0, 1.0);
    const Eigen::Quaterniond quat(w, q.x(), q.y(), q.z());
    r.orientation = quat.norm() > 1e-3 ? quat.normalized() : Eigen::Quaterniond::Identity();
    const double spin = rng.uniform(0.0, p.number("spin_max"));  // the rate, then the axis
    r.angular_velocity = rng.direction() * spin;
    scene.add_rigid_body(b, r);
  }
  return scene;
}

}  // namespace

extern const Generator kTumbleGenerator = {
    "tumble",
    "spinning crates, sticks, plates and rocks falling onto a floor polygon and through a ramp (rigid bodies "
    "against static scenery)",
    kTumbleParameters, generate_tumble};

}  // namespace ccdlab
