// `sticks`, `plates`, `crates`, `rocks`: rigid bodies spinning in a box (docs/rigid_bodies.md),
// optionally mixed with spheres. Centres move in straight lines with elastic walls (on the
// enclosing sphere), no gravity; each body spins at a constant rate about a random axis
// from a random orientation.
//   sticks: capsules, half_length = size, radius = size / elongation;
//   plates: boxes size x size x size / elongation (half extents);
//   crates: boxes size x size / sqrt(elongation) x size / elongation (half extents);
//   rocks:  8 random hulls of 8 points each, in the ellipsoid of semi-axes
//           size x size / sqrt(elongation) x size / elongation.
// Draw order per body: sphere or not (when spheres > 0), the shape (rocks), the position,
// the velocity, the orientation (4 normal numbers), the spin axis and rate. With free = 1
// the same bodies tumble torque-free from that angular velocity (docs/rigid_bodies.md); with
// wrap = 1 the box loops around on every axis (docs/periodic.md).
#include <generators/box_scene.hpp>
#include <generators/placement.hpp>
#include <generators/registry.hpp>
#include <generators/sampling.hpp>

#include <ccd/shape/mass_properties.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace ccdlab {
namespace {

constexpr ParameterSpec kSpinningParameters[] = {
    kSeedParameter,
    kBodiesParameter,
    kHorizonParameter,
    kOffsetParameter,
    {"size", 1.0, "the shape's largest half extent", ParameterKind::Real, kPositiveLength, "m"},
    {"elongation", 10.0, "largest over smallest half extent of the shape (>= 1)", ParameterKind::Real,
     {1.0, 1e6, false, false}},
    {"speed_max", 2.0, "speeds uniform in [0, speed_max], directions uniform", ParameterKind::Real, kNonNegativeRate,
     "m/s"},
    {"spin_max", 10.0, "spin rates uniform in [0, spin_max] about uniform axes", ParameterKind::Real,
     kNonNegativeRate, "rad/s"},
    {"spheres", 0.0, "fraction of the bodies that are spheres of radius size / 2", ParameterKind::Real,
     {0.0, 1.0, false, false}},
    {"fraction", 0.02, "volume fraction of the box filled by the enclosing spheres", ParameterKind::Real,
     kVolumeFraction},
    kOverlapParameter,
    {"free", 0.0, "1: torque-free spin (\"spin\": \"free\", the same draws; rocks centred on their centre of mass)",
     ParameterKind::Integer, {0.0, 1.0, false, false}},
    {"wrap", 0.0, "1: the box wraps around on every axis (periodic, no walls); 0: elastic walls",
     ParameterKind::Integer, {0.0, 1.0, false, false}},
};

enum class Kind { Sticks, Plates, Crates, Rocks };

ccd::Scene generate(const ParameterSet& p, Kind kind) {
  const double size = p.number("size");
  const double e = p.number("elongation");
  const std::size_t n = p.integer("bodies");
  Random rng(p.integer("seed"));
  std::vector<ccd::Shape> shapes;
  switch (kind) {
    case Kind::Sticks: shapes.push_back(ccd::make_capsule_shape(size, size / e, "stick")); break;
    case Kind::Plates: shapes.push_back(ccd::make_box_shape(ccd::Vec3(size, size, size / e), "plate")); break;
    case Kind::Crates: shapes.push_back(ccd::make_box_shape(ccd::Vec3(size, size / std::sqrt(e), size / e), "crate")); break;
    case Kind::Rocks:
      for (int k = 0; k < 8; ++k) {
        std::vector<ccd::Vec3> pts;
        for (int i = 0; i < 8; ++i) {
          const ccd::Vec3 d = rng.in_ball(1.0);
          pts.emplace_back(size * d.x(), size / std::sqrt(e) * d.y(), size / e * d.z());
        }
        shapes.push_back(ccd::make_hull_shape(std::move(pts), "rock" + std::to_string(k)));
      }
      break;
  }
  const bool free = p.integer("free") == 1;
  if (free && kind == Kind::Rocks)
    for (ccd::Shape& s : shapes) {  // a free body turns about its centre of mass
      const ccd::Vec3 c = ccd::mass_properties(s, 1.0).centre;
      for (ccd::Vec3& q : s.points) q -= c;
    }
  double r_max = 0.5 * size;
  for (const ccd::Shape& s : shapes) r_max = std::max(r_max, s.enclosing_radius());
  const double side = cube_side(n, r_max * r_max * r_max, p.number("fraction"), r_max);
  ccd::Scene scene = box_scene(p, ccd::Vec3::Constant(side));
  scene.shapes = shapes;
  std::vector<ccd::Body> bodies = std::move(scene.bodies);
  scene.bodies.clear();
  Placement placement(r_max, p.integer("overlap") == 1);
  const double spheres = p.number("spheres");
  for (std::size_t i = 0; i < n; ++i) {
    ccd::Body b = bodies[i];
    ccd::RigidBody r;
    const bool sphere = spheres > 0.0 && rng.uniform() < spheres;
    if (sphere) {
      b.radius = 0.5 * size;
    } else {
      r.shape = static_cast<std::int32_t>(kind == Kind::Rocks ? rng.index(shapes.size()) : 0);
      b.radius = shapes[static_cast<std::size_t>(r.shape)].enclosing_radius();
    }
    b.position = placement.place(b.radius, [&] { return rng.position_in_cube(side, b.radius); });
    b.velocity = rng.velocity(p.number("speed_max"));
    if (!sphere) {
      const ccd::Vec3 q = rng.in_ball(1.0);
      const double w = rng.uniform(-1.0, 1.0);
      Eigen::Quaterniond quat(w, q.x(), q.y(), q.z());
      r.orientation = quat.norm() > 1e-3 ? quat.normalized() : Eigen::Quaterniond::Identity();
      const double spin = rng.uniform(0.0, p.number("spin_max"));  // the rate, then the axis
      r.angular_velocity = rng.direction() * spin;
      if (free) r.spin = ccd::SpinModel::Free;
    }
    scene.add_rigid_body(b, r);
  }
  // The side is at least 4 x the largest enclosing radius (cube_side): twice the largest
  // enclosing diameter, as wrapping needs. The draws do not change.
  if (p.integer("wrap") == 1) scene.box->boundary.fill(ccd::Boundary::Wrap);
  return scene;
}

ccd::Scene generate_sticks(const ParameterSet& p) { return generate(p, Kind::Sticks); }
ccd::Scene generate_plates(const ParameterSet& p) { return generate(p, Kind::Plates); }
ccd::Scene generate_crates(const ParameterSet& p) { return generate(p, Kind::Crates); }
ccd::Scene generate_rocks(const ParameterSet& p) { return generate(p, Kind::Rocks); }

}  // namespace

extern const Generator kSticksGenerator = {
    "sticks", "spinning capsules (long and thin) in a box, straight-line motion, elastic walls", kSpinningParameters,
    generate_sticks};
extern const Generator kPlatesGenerator = {
    "plates", "spinning flat boxes in a box, straight-line motion, elastic walls", kSpinningParameters, generate_plates};
extern const Generator kCratesGenerator = {
    "crates", "spinning boxes in a box, straight-line motion, elastic walls", kSpinningParameters, generate_crates};
extern const Generator kRocksGenerator = {
    "rocks", "spinning random convex hulls in a box, straight-line motion, elastic walls", kSpinningParameters,
    generate_rocks};

}  // namespace ccdlab
