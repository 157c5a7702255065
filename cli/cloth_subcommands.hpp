#pragma once
// The subcommands of `ccdlab cloth` (one command family, cli/cloth.cpp
// dispatches): `ccdlab cloth frames` (cloth_frames.cpp) and `ccdlab cloth queries`
// (cloth_queries.cpp).
#include <cloth/sim/cloth_scene.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace ccdlab {

class CommandLine;

int run_cloth_frames(std::span<const std::string> args);
int run_cloth_queries(std::span<const std::string> args);

/// A built-in scene (drape, twist, pile with `n` particles per side) or a ccdlab-cloth/1 file.
ccd::cloth::ClothScene load_cloth_scene(const std::string& arg, int n);
/// The options every cloth form shares: --n N (particles per side of a built-in scene) and
/// --steps K (the scene's step count; not declared when `steps` is null).
void declare_cloth_scene_options(CommandLine& cli, int& n, std::optional<int>* steps);
/// True when `arg` names a built-in scene.
bool is_builtin_cloth_scene(const std::string& arg);

/// Refuses, before the simulation, a cloth run above 1e9 particle-steps (particles x
/// steps) or one that keeps more than 4e9 bytes (`states_kept` states of the mesh at
/// `bytes_per_particle` bytes each) unless `force`: throws ccd::InputError naming `arg`
/// (experiments/work_estimate.hpp).
void check_cloth_work(const ccd::cloth::ClothScene& scene, const std::string& arg, double states_kept,
                      double bytes_per_particle, bool force);

}  // namespace ccdlab
