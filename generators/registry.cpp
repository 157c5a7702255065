#include <generators/registry.hpp>
#include <ccd/util/nearest_name.hpp>

#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_io.hpp>

#include <stdexcept>
#include <string>

namespace ccdlab {

// Each generator's table and function live in its own file.
extern const Generator kGasGenerator;
extern const Generator kRainGenerator;
extern const Generator kBulletsGenerator;
extern const Generator kSwarmGenerator;
extern const Generator kLatticeGenerator;
extern const Generator kMixedGenerator;
extern const Generator kGrazingGenerator;
extern const Generator kSticksGenerator;
extern const Generator kPlatesGenerator;
extern const Generator kCratesGenerator;
extern const Generator kRocksGenerator;
extern const Generator kFloorRampGenerator;
extern const Generator kBowlGenerator;
extern const Generator kPinballGenerator;
extern const Generator kTumbleGenerator;

std::span<const Generator> generators() {
  static const Generator table[] = {kGasGenerator,     kRainGenerator,    kBulletsGenerator, kSwarmGenerator,
                                    kLatticeGenerator, kMixedGenerator,   kGrazingGenerator, kSticksGenerator,
                                    kPlatesGenerator,  kCratesGenerator,  kRocksGenerator,  kFloorRampGenerator,
                                    kBowlGenerator,    kPinballGenerator, kTumbleGenerator};
  return table;
}

const Generator& generator_named(std::string_view name) {
  for (const Generator& g : generators())
    if (g.name == name) return g;
  std::string valid;
  for (const Generator& g : generators()) valid += (valid.empty() ? "" : ", ") + std::string(g.name);
  std::vector<std::string_view> names;
  for (const Generator& g : generators()) names.push_back(g.name);
  throw std::invalid_argument("unknown generator '" + std::string(name) + "'" +
                              ccd::did_you_mean(name, names) + "; valid generators: " + valid);
}

namespace {

// Adds the offset to every position and to the box, then moves a wall out to any body
// that rounding put outside it (fl(p - r) < min or fl(p + r) > max), so that the scene
// passes ccd::validate_scene. With a zero offset nothing moves.
void apply_offset(ccd::Scene& scene, const ccd::Vec3& offset) {
  if (offset.isZero(0.0)) return;
  for (ccd::Body& b : scene.bodies) b.position += offset;
  // Scenery moves by the same additions (its planes derived again); the mesh's vertices
  // too, so that the scene writes back what it holds.
  for (ccd::StaticPolygon& poly : scene.scenery) {
    std::vector<ccd::Vec3> vs = poly.vertices;
    for (ccd::Vec3& x : vs) x += offset;
    poly = ccd::polygon_from_vertices(std::move(vs));
  }
  if (scene.scenery_mesh)
    for (ccd::Vec3& x : scene.scenery_mesh->vertices) x += offset;
  if (!scene.box) return;
  scene.box->min += offset;
  scene.box->max += offset;
  for (const ccd::Body& b : scene.bodies) {
    for (int a = 0; a < 3; ++a) {
      if (b.position[a] - b.radius < scene.box->min[a]) scene.box->min[a] = b.position[a] - b.radius;
      if (b.position[a] + b.radius > scene.box->max[a]) scene.box->max[a] = b.position[a] + b.radius;
    }
  }
}

}  // namespace

ccd::Scene generate_scene(const Generator& gen, const ParameterSet& params) {
  ccd::Scene scene = gen.generate(params);
  apply_offset(scene, params.vector("offset"));
  if (scene.bodies.size() != params.integer("bodies"))
    throw std::logic_error("generator " + std::string(gen.name) + " made the wrong number of bodies");
  try {
    ccd::validate_scene(scene, "generator " + std::string(gen.name));
  } catch (const ccd::InputError& e) {
    throw std::logic_error(std::string("invalid generated scene: ") + e.what());
  }
  return scene;
}

ccd::Scene generate_scene(std::string_view name, std::span<const ParameterValue> given) {
  const Generator& gen = generator_named(name);
  return generate_scene(gen, resolve_parameters(gen.parameters, given));
}

ccd::Scene generate_scene(std::string_view name, const nlohmann::json& params) {
  const Generator& gen = generator_named(name);
  const std::vector<ParameterValue> given = parameter_values_from_json(params);
  return generate_scene(gen, resolve_parameters(gen.parameters, given));
}

}  // namespace ccdlab
