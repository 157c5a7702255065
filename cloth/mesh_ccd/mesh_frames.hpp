#pragma once
// Generated frame pairs for mesh CCD (tests, benchmarks and `ccdlab mesh-frames`): one
// triangle mesh at t = 0 and at t = 1, every vertex moving linearly in between.
//
//   sheet_on_sphere  a square sheet above a sphere falls onto it; at t = 1 its middle has
//                    sunk into the sphere (collisions between the sheet and the sphere)
//   tori             two linked tori, apart at t = 0, each twisted about its own axis and
//                    turned towards the other until they cut through each other by t = 1
//   crumpled         a square sheet crumpled by random bumps at both frames, folding
//                    through itself (a fixed seed)
//
// `faces` is about the number of triangles asked for (each generator rounds its grid).
// Every coordinate is a multiple of 2^-20 (rounded so), so the exact reference reads the
// same numbers the kernel does, and the frames are the same on every machine.
#include <ccd/geometry/vec3.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ccd::cloth {

struct MeshFramePair {
  std::vector<Vec3> x0, x1;
  std::vector<std::array<std::uint32_t, 3>> faces;
};

/// The generators' names.
std::span<const std::string_view> mesh_frame_generators();
/// Throws std::invalid_argument for an unknown name (listing the known ones) or faces < 8
/// or > 2^26.
MeshFramePair generate_mesh_frames(std::string_view name, std::size_t faces, std::uint64_t seed = 1);

}  // namespace ccd::cloth
