#pragma once
// The subcommands of `ccdlab cloth` (one command family, experiments/commands/cloth.cpp
// dispatches): `ccdlab cloth frames` (cloth_frames.cpp) and `ccdlab cloth queries`
// (cloth_queries.cpp).
#include <cloth/sim/cloth_scene.hpp>

#include <span>
#include <string>
#include <string_view>

namespace ccdlab {

int run_cloth_frames(std::span<const std::string> args);
int run_cloth_queries(std::span<const std::string> args);

/// A built-in scene (drape, twist, pile with `n` particles per side) or a ccdlab-cloth/1 file.
ccd::cloth::ClothScene load_cloth_scene(const std::string& arg, int n);
/// True when `arg` names a built-in scene.
bool is_builtin_cloth_scene(const std::string& arg);

}  // namespace ccdlab
