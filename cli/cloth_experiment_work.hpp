#pragma once
// The work of a cloth experiment (`ccdlab run` of a ccdlab-cloth-experiment/1 file),
// estimated before the simulation and refused past its limits unless --force
// (experiments/work_estimate.hpp, docs/formats.md "Work estimates and `--force`").
#include "../experiments/cloth_experiment.hpp"

#include <cloth/sim/cloth_scene.hpp>

#include <string>

namespace ccdlab {

/// The particle-steps of checks the experiment's jobs make without --force: every job
/// (culler x mode x k, each repeated) passes over every state of the run.
inline constexpr double kMaxClothCheckWork = 1e10;

/// Refuses, before anything is simulated or allocated, an experiment whose run is above
/// the limits of `ccdlab cloth frames` (1e9 particle-steps, 4e9 bytes for the steps + 1
/// states kept) or whose jobs make more than kMaxClothCheckWork particle-steps of checks
/// (particles x steps x jobs x repeats), unless `force`. Throws ccd::InputError naming
/// `file` and the field that makes it large.
void check_cloth_experiment_work(const ClothExperiment& e, const ccd::cloth::ClothScene& scene,
                                 const std::string& file, bool force);

}  // namespace ccdlab
