#pragma once
// A cloth scene: a rectangular grid of particles joined by damped springs, pinned or
// spun particles, gravity, static obstacles (spheres, a floor) and a thickness. Units are
// the scene's (metres, kilograms, seconds by convention).
//
// File format `ccdlab-cloth/1` (docs/cloth.md#cloth-scenes), read strictly: every field is
// checked, unknown fields are refused, and errors name the file and the field.
#include <ccd/geometry/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ccd::cloth {

struct SpringParams {
  double stiffness = 0.0;  ///< N/m, >= 0
  double damping = 0.0;    ///< N s/m along the spring, >= 0
};

struct SphereObstacle {
  Vec3 center = Vec3::Zero();
  double radius = 1.0;  ///< > 0
};

/// Particles that rotate rigidly about an axis at a constant rate (the `twist` scene).
struct Spin {
  std::vector<std::uint32_t> particles;
  Vec3 center = Vec3::Zero();
  Vec3 axis = Vec3::UnitX();  ///< normalised when read
  double rate = 0.0;          ///< rad/s
};

struct ClothScene {
  int nx = 2, ny = 2;  ///< particles along du and dv (>= 2 each)
  Vec3 origin = Vec3::Zero(), du = Vec3::UnitX(), dv = Vec3::UnitZ();  ///< particle (i, j) at origin + i du + j dv
  double particle_mass = 1.0;                                          ///< kg, > 0
  SpringParams structural, shear, bend;
  double air_damping = 0.0;           ///< drag on each particle, force = -air_damping v (kg/s), >= 0
  std::vector<std::uint32_t> pinned;  ///< held still (index i + nx j)
  std::optional<Spin> spin;           ///< moved rigidly (not also pinned)
  Vec3 gravity = Vec3(0, -9.81, 0);
  std::vector<SphereObstacle> spheres;
  std::optional<double> floor;  ///< the plane y = floor, when present
  double thickness = 0.0;       ///< kept from obstacles; self-contact distance, >= 0
  double step = 0.01;           ///< integrator step h, s, > 0
  int steps = 100;              ///< number of steps

  std::uint32_t particle(int i, int j) const { return static_cast<std::uint32_t>(i + nx * j); }
  std::size_t particle_count() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
};

/// The built-in scenes: "drape" (a sheet falling over a sphere onto the floor), "twist" (a
/// sheet held at both ends, one end turning about the sheet's axis), "pile" (a hanging sheet
/// dropped onto the floor, folding onto itself). `n` particles per side (>= 4).
ClothScene builtin_cloth_scene(const std::string& name, int n = 32);
/// "drape", "twist", "pile".
std::vector<std::string> builtin_cloth_scene_names();

/// Reads a ccdlab-cloth/1 file. Throws InputError naming the file and field.
ClothScene read_cloth_scene(const std::string& path);
ClothScene parse_cloth_scene(const std::string& text, const std::string& file);

}  // namespace ccd::cloth
