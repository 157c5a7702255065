// `bowl`: balls under gravity bouncing inside a polygon bowl. The bowl is static scenery
// (docs/scenery.md): a regular polygon floor a little above the box floor (so every
// bounce is a real contact) and slanted sides given as a triangle mesh up to a wider rim.
// Scenery does not push bodies: the balls bounce off the box walls and cross the bowl's
// sides, which is what the contacts count. y is up.
#include <generators/box_scene.hpp>
#include <generators/placement.hpp>
#include <generators/registry.hpp>
#include <generators/sampling.hpp>

#include <ccd/scene/scenery.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ccdlab {
namespace {

constexpr ParameterSpec kBowlParameters[] = {
    kSeedParameter,
    kBodiesParameter,
    kHorizonParameter,
    kOffsetParameter,
    uniform_r_min_parameter(0.05),
    r_max_parameter(0.1),
    {"fraction", 0.02, "volume fraction of the start region (a cylinder inside the bowl) filled by the balls",
     ParameterKind::Real, kVolumeFraction},
    {"sides", 8.0, "sides of the bowl's regular polygon floor", ParameterKind::Integer, {3.0, 256.0, false, false}},
    {"speed_max", 2.0, "velocity uniform in the ball of this radius", ParameterKind::Real, kNonNegativeRate, "m/s"},
    {"gravity", 9.81, "gravity magnitude; the scene's gravity is [0, -gravity, 0]", ParameterKind::Real,
     {0.0, kMaxRate, true, false}, "m/s^2"},
    kOverlapParameter,
};

ccd::Scene generate_bowl(const ParameterSet& p) {
  require_not_greater(p, "r_min", "r_max");
  const double r_min = p.number("r_min"), r_max = p.number("r_max");
  const std::size_t n = p.integer("bodies");
  const std::size_t sides = p.integer("sides");
  const double speed_max = p.number("speed_max");
  const double g = p.number("gravity");
  // Start region: a cylinder of radius 0.45 R and height R over the floor (R the floor's
  // circumradius), volume 0.2025 pi R^3, filled to `fraction`.
  const double volume = static_cast<double>(n) * (4.0 / 3.0) * std::numbers::pi *
                        mean_cube_uniform(r_min, r_max) / p.number("fraction");
  const double R = std::max(std::cbrt(volume / (0.2025 * std::numbers::pi)), 8.0 * r_max);
  const double rim = 1.5 * R;
  const double centre = rim + 2.0 * r_max;
  const double y_floor = 0.5 * r_max;
  const double y_rim = y_floor + R;
  const double y_size = y_rim + R + 2.0 * r_max + speed_max * speed_max / (2.0 * g);

  ccd::Scene scene = box_scene(p, ccd::Vec3(2.0 * centre, y_size, 2.0 * centre));
  scene.gravity = ccd::Vec3(0.0, -g, 0.0);
  std::vector<ccd::Vec3> floor;
  ccd::SceneryMesh mesh;
  for (std::size_t k = 0; k < sides; ++k) {
    const double a = 2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(sides);
    floor.emplace_back(centre + R * std::cos(a), y_floor, centre + R * std::sin(a));
  }
  for (std::size_t k = 0; k < sides; ++k) mesh.vertices.push_back(floor[k]);
  for (std::size_t k = 0; k < sides; ++k) {
    const double a = 2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(sides);
    mesh.vertices.emplace_back(centre + rim * std::cos(a), y_rim, centre + rim * std::sin(a));
  }
  scene.scenery.push_back(ccd::polygon_from_vertices(std::move(floor)));
  for (std::size_t k = 0; k < sides; ++k) {
    const auto f0 = static_cast<std::uint32_t>(k), f1 = static_cast<std::uint32_t>((k + 1) % sides);
    const auto r0 = static_cast<std::uint32_t>(sides + k), r1 = static_cast<std::uint32_t>(sides + (k + 1) % sides);
    mesh.triangles.push_back({f0, f1, r1});
    mesh.triangles.push_back({f0, r1, r0});
  }
  for (const auto& t : mesh.triangles)
    scene.scenery.push_back(ccd::polygon_from_vertices({mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]}));
  scene.scenery_mesh = std::move(mesh);

  Random rng(p.integer("seed"));
  Placement placement(r_max, p.integer("overlap") == 1);
  const double half = 0.45 * R;
  for (ccd::Body& b : scene.bodies) {
    b.radius = rng.uniform(r_min, r_max);
    b.position = placement.place(b.radius, [&] {
      double x = 0.0, z = 0.0;
      do {  // uniform in the disc of radius 0.45 R (two outputs per try)
        x = rng.uniform(-half, half);
        z = rng.uniform(-half, half);
      } while (x * x + z * z > half * half);
      const double y = rng.uniform(y_floor + b.radius + R / 8.0, y_floor + R);
      return ccd::Vec3(centre + x, y, centre + z);
    });
    b.velocity = rng.in_ball(speed_max);
  }
  return scene;
}

}  // namespace

extern const Generator kBowlGenerator = {
    "bowl", "balls bouncing inside a polygon bowl (static scenery: floor polygon and a triangle mesh of sides)",
    kBowlParameters, generate_bowl};

}  // namespace ccdlab
