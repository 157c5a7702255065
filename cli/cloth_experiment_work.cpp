#include "cloth_experiment_work.hpp"

#include "cloth_subcommands.hpp"

#include "../experiments/work_estimate.hpp"

namespace ccdlab {

void check_cloth_experiment_work(const ClothExperiment& e, const ccd::cloth::ClothScene& scene,
                                 const std::string& file, bool force) {
  // The simulation and its frames (every state, 24 bytes a particle), as `cloth frames`.
  check_cloth_work(scene, file, scene.steps + 1.0, 24.0, force);
  const double jobs = static_cast<double>(e.cullers.size() * e.modes.size() * e.k.size());
  const double particle_steps = static_cast<double>(scene.particle_count()) * scene.steps;
  check_work({particle_steps * jobs * e.repeats, kMaxClothCheckWork, "particle-steps of checks",
              std::to_string(scene.nx) + " x " + std::to_string(scene.ny) + " particles, " +
                  std::to_string(scene.steps) + " steps, " + work_number(jobs) + " jobs x " +
                  std::to_string(e.repeats) + " repeats"},
             force, file, e.repeats > 1 ? "repeats" : "k");
}

}  // namespace ccdlab
