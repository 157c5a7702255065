// The cloth scene reader (`ccdlab-cloth/1`, cloth/sim/cloth_scene.hpp) and, for a small
// accepted scene (at most 36 particles), its mesh and three integrator steps.
//
// Invariants: the accepted values are in their documented ranges (grid 2..1000 per side,
// indices below nx ny, a unit spin axis, a positive step); the mesh indexes only the
// scene's particles; the simulator keeps one position per particle and pinned particles
// where they were.
#include "fuzz_support.hpp"

#include <ccd/io/input_error.hpp>
#include <cloth/sim/cloth_mesh.hpp>
#include <cloth/sim/cloth_scene.hpp>
#include <cloth/sim/cloth_simulator.hpp>

#include <cmath>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  using namespace ccd::cloth;
  ClothScene scene;
  try {
    scene = parse_cloth_scene(std::string(ccdfuzz::as_text(data, size)), "fuzz.json");
  } catch (const ccd::InputError&) {
    return 0;
  }
  const std::size_t n = scene.particle_count();
  FUZZ_CHECK(scene.nx >= 2 && scene.nx <= 1000 && scene.ny >= 2 && scene.ny <= 1000);
  FUZZ_CHECK(scene.step > 0.0 && scene.steps >= 1 && scene.thickness >= 0.0 && scene.particle_mass > 0.0);
  for (std::uint32_t p : scene.pinned) FUZZ_CHECK(p < n);
  if (scene.spin) {
    for (std::uint32_t p : scene.spin->particles) FUZZ_CHECK(p < n);
    FUZZ_CHECK(std::abs(scene.spin->axis.norm() - 1.0) < 1e-12);
  }
  if (n > 36) return 0;
  const ClothMesh mesh = make_grid_mesh(scene);
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t) FUZZ_CHECK(v < n);
  for (const auto& e : mesh.edges) FUZZ_CHECK(e[0] < e[1] && e[1] < n);
  ClothSimulator sim(scene);
  const std::vector<ccd::Vec3> start = sim.positions();
  FUZZ_CHECK(start.size() == n);
  for (int k = 0; k < 3; ++k) sim.step();
  FUZZ_CHECK(sim.positions().size() == n);
  for (std::uint32_t p : scene.pinned) FUZZ_CHECK(sim.positions()[p] == start[p]);
  return 0;
}
