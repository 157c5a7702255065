// `ccdlab mesh-frames NAME -o DIR [--faces N] [--seed S] [--n N] [--step K] [--ascii] [--force]`: a
// pair of mesh frames as PLY files DIR/frame0.ply and DIR/frame1.ply, for `ccdlab ccd
// FRAME0 FRAME1` (docs/mesh-ccd.md). NAME is a generator of cloth/mesh_ccd/mesh_frames.hpp
// (sheet_on_sphere, tori, crumpled; about N faces) or a cloth scene (drape, twist, pile or
// a ccdlab-cloth/1 file, N particles per side): its states K and K + 1.
#include "cloth_subcommands.hpp"
#include "command.hpp"

#include "../work_estimate.hpp"

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

int run_mesh_frames(std::span<const std::string> args) {
  auto usage_error = [](const std::string& msg) {
    std::cerr << "ccdlab mesh-frames: " << msg << " (see ccdlab mesh-frames --help)\n";
    return kExitBadInput;
  };
  std::string name, out_path;
  std::uint64_t faces = 1000, seed = 1;
  int n = 32, step = 0;
  bool force = false;
  ccd::cloth::PlyEncoding encoding;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool has_value = i + 1 < args.size();
    if (a == "-o" || a == "--output") {
      if (!has_value) return usage_error("-o needs a folder name");
      out_path = args[++i];
    } else if (a == "--faces") {
      const auto v = has_value ? ccd::parse_integer(args[++i], 8, std::uint64_t{1} << 26) : std::nullopt;
      if (!v) return usage_error("--faces needs an integer in [8, 2^26]");
      faces = *v;
    } else if (a == "--seed") {
      const auto v = has_value ? ccd::parse_integer(args[++i], 0, ~std::uint64_t{0}) : std::nullopt;
      if (!v) return usage_error("--seed needs an integer >= 0");
      seed = *v;
    } else if (a == "--n") {
      const auto v = has_value ? ccd::parse_integer(args[++i], 4, 1000) : std::nullopt;
      if (!v) return usage_error("--n needs an integer in [4, 1000]");
      n = static_cast<int>(*v);
    } else if (a == "--step") {
      const auto v = has_value ? ccd::parse_integer(args[++i], 0, 1000000) : std::nullopt;
      if (!v) return usage_error("--step needs an integer in [0, 1000000]");
      step = static_cast<int>(*v);
    } else if (a == "--force") {
      force = true;
    } else if (a == "--ascii") {
      encoding.format = ccd::cloth::PlyFormat::Ascii;
    } else if (a.size() > 1 && a[0] == '-') {
      return usage_error("unknown option '" + a + "'");
    } else if (name.empty()) {
      name = a;
    } else {
      return usage_error("one generator or scene only");
    }
  }
  if (name.empty() || out_path.empty())
    return usage_error("need a generator (sheet_on_sphere, tori, crumpled) or a cloth scene, and -o DIR");
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
    "mesh-frames", "write a pair of mesh frames (PLY) for ccdlab ccd FRAME0 FRAME1",
    "usage: ccdlab mesh-frames sheet_on_sphere|tori|crumpled -o DIR [--faces N] [--seed S] [--ascii] [--force]\n"
    "       ccdlab mesh-frames drape|twist|pile|SCENE.json -o DIR [--n N] [--step K] [--ascii] [--force]\n"
    "\n"
    "Writes DIR/frame0.ply and DIR/frame1.ply (binary little-endian, double coordinates; --ascii\n"
    "for text), one triangle mesh at t = 0 and t = 1, for `ccdlab ccd DIR/frame0.ply DIR/frame1.ply`\n"
    "(docs/mesh-ccd.md). The folder appears whole or not at all; an existing one is replaced only\n"
    "when it is empty or was written by this command.\n"
    "sheet_on_sphere  a sheet falling into a sphere\n"
    "tori             two linked tori, apart at t = 0, twisting and cutting through each other\n"
    "crumpled         a bumpy sheet folding through itself (--seed S, default 1)\n"
    "--faces N        about N faces (default 1000; 8 to 2^26)\n"
    "drape, twist, pile, SCENE.json: a cloth run (docs/cloth.md) with N particles per side\n"
    "(--n, default 32); the frames are its states K and K + 1 (--step K, default 0).\n"
    "--force          write more than 1e7 faces, or simulate more than 1e9 particle-steps\n"
    "                 (particles x (K + 1)); without it such work is refused up front\n"
    "\n"
    "Exit status: 0 success, 1 runtime failure, 2 bad input or usage (nothing written).\n",
    run_mesh_frames};

}  // namespace ccdlab
