// `ccdlab mesh-frames NAME -o DIR [--faces N] [--seed S] [--n N] [--step K] [--ascii] [--force]`: a
// pair of mesh frames as PLY files DIR/frame0.ply and DIR/frame1.ply, for `ccdlab ccd
// FRAME0 FRAME1` (docs/mesh-ccd.md). NAME is a generator of cloth/mesh_ccd/mesh_frames.hpp
// (sheet_on_sphere, tori, crumpled; about N faces) or a cloth scene (drape, twist, pile or
// a ccdlab-cloth/1 file, N particles per side): its states K and K + 1.
#include "cloth_subcommands.hpp"
#include "command.hpp"
#include "command_line.hpp"

#include "../experiments/work_estimate.hpp"

#include <cloth/io/ply_writer.hpp>
#include <cloth/mesh_ccd/mesh_frames.hpp>
#include <cloth/sim/cloth_mesh.hpp>
#include <cloth/sim/cloth_simulator.hpp>
#include <ccd/io/output_directory.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/util/integer_text.hpp>

#include <algorithm>
#include <iostream>
#include <optional>

namespace ccdlab {
namespace {

bool is_generator(const std::string& name) {
  const auto names = ccd::cloth::mesh_frame_generators();
  return std::find(names.begin(), names.end(), name) != names.end();
}

// The faces a generator writes without --force (two frames of them, as PLY).
constexpr double kMaxGeneratedFaces = 1e7;

// States K and K + 1 of a cloth run; refused past 1e9 particle-steps (as `ccdlab cloth`)
// before the simulation unless `force`.
ccd::cloth::MeshFramePair cloth_frames(const std::string& scene_arg, int n, int step, bool force) {
  ccd::cloth::ClothScene scene = load_cloth_scene(scene_arg, n);
  scene.steps = step + 1;
  check_work({static_cast<double>(scene.particle_count()) * scene.steps, 1e9, "particle-steps",
              std::to_string(scene.nx) + " x " + std::to_string(scene.ny) + " particles, " +
                  std::to_string(scene.steps) + " steps"},
             force, scene_arg, "--step");
  ccd::cloth::ClothSimulator sim(scene);
  for (int k = 0; k < step; ++k) sim.step();
  ccd::cloth::MeshFramePair m;
  m.x0 = sim.positions();
  sim.step();
  m.x1 = sim.positions();
  m.faces = sim.mesh().triangles;
  return m;
}

constexpr const char* kMeshFramesDescription =
    "Writes DIR/frame0.ply and DIR/frame1.ply (binary little-endian, double coordinates; --ascii\n"
    "for text), one triangle mesh at t = 0 and t = 1, for `ccdlab ccd DIR/frame0.ply DIR/frame1.ply`\n"
    "(docs/mesh-ccd.md). The folder appears whole or not at all; an existing one is replaced only\n"
    "when it is empty or was written by this command.\n"
    "\n"
    "NAME is a generator:\n"
    "  sheet_on_sphere  a sheet falling into a sphere\n"
    "  tori             two linked tori, apart at t = 0, twisting and cutting through each other\n"
    "  crumpled         a bumpy sheet folding through itself (--seed S, default 1)\n"
    "or a cloth run (drape, twist, pile, SCENE.json; docs/cloth.md) with N particles per side\n"
    "(--n, default 32): the frames are its states K and K + 1 (--step K, default 0).\n";

int run_mesh_frames(std::span<const std::string> args) {
  std::string name, out_path;
  std::uint64_t faces = 1000, seed = 1;
  int n = 32, step = 0;
  bool force = false, ascii = false;
  ccd::cloth::PlyEncoding encoding;
  CommandLine cli("mesh-frames", kMeshFramesDescription, "mesh-frames");
  cli.footer("Exit status: 0 success, 1 runtime failure, 2 bad input or usage (nothing written).");
  cli.positional("NAME", name, "a generator (sheet_on_sphere, tori, crumpled) or a cloth scene");
  cli.text("-o,--output", out_path, "DIR", "the folder of frame0.ply and frame1.ply", "-o needs a folder name");
  cli.integer("--faces", 8, std::uint64_t{1} << 26, "N", "generators: about N faces (default 1000)",
              [&faces](std::uint64_t v) { faces = v; });
  cli.integer("--seed", 0, ~std::uint64_t{0}, "S", "generators: the random seed (default 1)",
              [&seed](std::uint64_t v) { seed = v; });
  cli.integer("--n", 4, 1000, "N", "cloth runs: particles per side of a built-in scene (default 32)",
              [&n](std::uint64_t v) { n = static_cast<int>(v); });
  cli.integer("--step", 0, 1000000, "K", "cloth runs: the frames are states K and K + 1 (default 0)",
              [&step](std::uint64_t v) { step = static_cast<int>(v); });
  cli.flag("--ascii", ascii, "write text PLY files");
  cli.flag("--force", force,
           "write more than 1e7 faces, or simulate more than 1e9 particle-steps\n"
           "(particles x (K + 1)); without it such work is refused up front");
  try {
    if (!cli.parse(args)) return 0;
    if (name.empty() || out_path.empty())
      cli.fail("need a generator (sheet_on_sphere, tori, crumpled) or a cloth scene, and -o DIR");
  } catch (...) {
    return command_failed("mesh-frames");
  }
  if (ascii) encoding.format = ccd::cloth::PlyFormat::Ascii;
  try {
    ccd::OutputDirectory output(out_path, "frame0.ply");
    if (is_generator(name))
      check_work({static_cast<double>(faces), kMaxGeneratedFaces, "faces", "--faces " + std::to_string(faces)}, force,
                 name, "--faces");
    const ccd::cloth::MeshFramePair m =
        is_generator(name) ? ccd::cloth::generate_mesh_frames(name, faces, seed) : cloth_frames(name, n, step, force);
    output.write("frame0.ply", ccd::cloth::format_ply({m.x0, m.faces}, encoding));
    output.write("frame1.ply", ccd::cloth::format_ply({m.x1, m.faces}, encoding));
    output.commit();
    std::cout << "vertices: " << m.x0.size() << ", faces: " << m.faces.size() << "\n"
              << "written: " << out_path << "/frame0.ply, " << out_path << "/frame1.ply\n";
  } catch (...) {
    return command_failed("mesh-frames");
  }
  return 0;
}

}  // namespace

extern const Command kMeshFramesCommand = {
    "mesh-frames", "write a pair of mesh frames (PLY) for ccdlab ccd FRAME0 FRAME1", run_mesh_frames};

}  // namespace ccdlab
