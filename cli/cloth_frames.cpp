// `ccdlab cloth frames SCENE -o DIR`: the vertex positions at every integrator step, the
// triangles, the edges and the springs, so any tool can replay the motion
// (docs/cloth.md#cloth-frames-and-queries-out).
#include "cloth_subcommands.hpp"
#include "command.hpp"
#include "command_line.hpp"

#include "../experiments/work_estimate.hpp"

#include <cloth/sim/cloth_simulator.hpp>
#include <cloth/truth/mesh_truth_file.hpp>
#include <ccd/io/utf8_text.hpp>
#include <ccd/io/output_directory.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/util/integer_text.hpp>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

namespace ccdlab {

static_assert(std::endian::native == std::endian::little, "positions.f64 is written little-endian");

bool is_builtin_cloth_scene(const std::string& arg) {
  const auto names = ccd::cloth::builtin_cloth_scene_names();
  return std::find(names.begin(), names.end(), arg) != names.end();
}

ccd::cloth::ClothScene load_cloth_scene(const std::string& arg, int n) {
  return is_builtin_cloth_scene(arg) ? ccd::cloth::builtin_cloth_scene(arg, n) : ccd::cloth::read_cloth_scene(arg);
}

void check_cloth_work(const ccd::cloth::ClothScene& scene, const std::string& arg, double states_kept,
                      double bytes_per_particle, bool force) {
  const auto particles = static_cast<double>(scene.particle_count());
  const std::string size = std::to_string(scene.nx) + " x " + std::to_string(scene.ny) + " particles";
  const std::string field = is_builtin_cloth_scene(arg) ? "--n" : "steps";
  check_work({particles * scene.steps, 1e9, "particle-steps", size + ", " + std::to_string(scene.steps) + " steps"},
             force, arg, field);
  check_work({particles * states_kept * bytes_per_particle, 4e9, "bytes of memory",
              size + ", " + work_number(states_kept) + " states kept"},
             force, arg, field);
}

void declare_cloth_scene_options(CommandLine& cli, int& n, std::optional<int>* steps) {
  cli.integer("--n", 4, 1000, "N", "particles per side of a built-in scene (default 32)",
              [&n](std::uint64_t v) { n = static_cast<int>(v); });
  if (steps)
    cli.integer("--steps", 1, 1000000, "K", "override the scene's step count",
                [steps](std::uint64_t v) { *steps = static_cast<int>(v); });
}

int run_cloth_frames(std::span<const std::string> args) {
  std::string scene_arg, out_path;
  int n = 32;
  bool force = false;
  std::optional<int> steps;
  CommandLine cli("cloth frames",
                  "Simulates the cloth and writes the folder DIR (atomically: a temporary folder renamed):\n"
                  "  cloth.json     ccdlab-cloth-motion/1: triangles, edges, springs, obstacles, step, the\n"
                  "                 times of the states and the motion's digest\n"
                  "  positions.f64  the positions at every integrator step: little-endian IEEE-754 doubles,\n"
                  "                 [steps + 1][particles][3] (x, y, z), state 0 first\n"
                  "Reader: /usr/bin/python3 scripts/cloth_frames.py DIR.\n",
                  "cloth");
  cli.footer("A run above 1e9 particle-steps or 4e9 bytes of states is refused before the simulation\n"
             "with the estimate unless --force.\n"
             "\n"
             "Exit status: 0 success, 1 runtime failure, 2 bad input or usage (nothing written).");
  cli.positional("SCENE", scene_arg, "drape, twist, pile or a ccdlab-cloth/1 file");
  cli.text("-o,--output", out_path, "DIR",
           "the folder; an existing DIR is replaced only when it is empty or holds\n"
           "a cloth.json",
           "-o needs a folder name");
  declare_cloth_scene_options(cli, n, &steps);
  cli.flag("--force", force, "run past the work limits");
  try {
    if (!cli.parse(args)) return 0;
    if (scene_arg.empty() || out_path.empty()) cli.fail("need a scene (drape, twist, pile or FILE.json) and -o DIR");
  } catch (...) {
    return command_failed("cloth frames");
  }
  try {
    ccd::cloth::ClothScene scene = load_cloth_scene(scene_arg, n);
    if (steps) scene.steps = *steps;
    // Every state is kept for the digest (24 bytes a particle) while it is written.
    check_cloth_work(scene, scene_arg, scene.steps + 1.0, 24.0, force);
    ccd::OutputDirectory output(out_path, "cloth.json");
    const auto start = std::chrono::steady_clock::now();
    ccd::cloth::ClothSimulator sim(scene);
    std::vector<std::vector<ccd::Vec3>> frames{sim.positions()};
    std::vector<double> times{sim.time()};
    {
      std::ofstream pos(output.file("positions.f64"), std::ios::binary);
      auto put = [&](const std::vector<ccd::Vec3>& x) {
        for (const ccd::Vec3& p : x) {
          const double xyz[3] = {p.x(), p.y(), p.z()};
          pos.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
        }
      };
      put(frames.back());
      for (int k = 1; k <= scene.steps; ++k) {
        sim.step();
        frames.push_back(sim.positions());
        times.push_back(sim.time());
        put(frames.back());
      }
      pos.close();
      if (!pos) throw std::runtime_error(out_path + ": cannot write positions.f64");
    }
    const ccd::cloth::ClothMesh& mesh = sim.mesh();
    nlohmann::json j;
    j["format"] = "ccdlab-cloth-motion/1";
    j["scene"] = ccd::escape_invalid_utf8(scene_arg);
    j["nx"] = scene.nx;
    j["ny"] = scene.ny;
    j["particles"] = scene.particle_count();
    j["step"] = scene.step;
    j["steps"] = scene.steps;
    j["thickness"] = scene.thickness;
    j["times"] = times;
    j["digest"] = ccd::cloth::motion_digest(mesh, frames, scene.thickness);
    j["positions"] = {{"file", "positions.f64"},
                      {"layout", "little-endian float64 [steps + 1][particles][3]"}};
    j["triangles"] = mesh.triangles;
    j["edges"] = mesh.edges;
    nlohmann::json sa = nlohmann::json::array(), sb = nlohmann::json::array(), rest = nlohmann::json::array(),
                   kind = nlohmann::json::array();
    for (const auto& s : mesh.springs) {
      sa.push_back(s.a);
      sb.push_back(s.b);
      rest.push_back(s.rest);
      kind.push_back(s.kind == ccd::cloth::SpringKind::Structural ? "structural"
                     : s.kind == ccd::cloth::SpringKind::Shear    ? "shear"
                                                                  : "bend");
    }
    j["springs"] = {{"a", sa}, {"b", sb}, {"rest", rest}, {"kind", kind}};
    nlohmann::json spheres = nlohmann::json::array();
    for (const auto& s : scene.spheres)
      spheres.push_back({{"center", {s.center.x(), s.center.y(), s.center.z()}}, {"radius", s.radius}});
    j["spheres"] = spheres;
    j["floor"] = scene.floor ? nlohmann::json(*scene.floor) : nlohmann::json(nullptr);
    output.write("cloth.json", j.dump() + "\n");
    output.commit();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "particles: " << scene.particle_count() << ", triangles: " << mesh.triangles.size()
              << ", springs: " << mesh.springs.size() << ", states: " << frames.size() << "\n"
              << "written to " << out_path << " in " << seconds << " s\n";
  } catch (...) {
    return command_failed("cloth frames", "simulating " + scene_arg);
  }
  return 0;
}

}  // namespace ccdlab
