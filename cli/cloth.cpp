// `ccdlab cloth SCENE -o FRAMES.json`: simulates a cloth scene (built-in or a
// ccdlab-cloth/1 file) and writes its frames (every E-th state, for pictures and the
// viewer). The family's other members: `ccdlab cloth frames` (every state, for replay) and
// `ccdlab cloth queries` (benchmark-format CCD queries), in cloth_frames.cpp and
// cloth_queries.cpp.
#include "cloth_subcommands.hpp"
#include "command.hpp"
#include "command_line.hpp"

#include <cloth/cull/cullers.hpp>
#include <cloth/sim/cloth_simulator.hpp>
#include <ccd/io/utf8_text.hpp>
#include <ccd/io/atomic_file.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/util/integer_text.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

namespace ccdlab {
namespace {

constexpr const char* kClothDescription =
    "Simulates the mass-spring cloth with implicit Euler (docs/cloth.md) and writes every E-th\n"
    "state (default 10, and the last) as JSON: triangles, obstacles and per frame the time and\n"
    "the particle positions (x, y, z per particle).\n"
    "Pictures: /usr/bin/python3 scripts/plot_cloth.py FRAMES.json -o PICTURE.png\n";

constexpr const char* kClothFooter =
    "Every form refuses, before the simulation, a run above 1e9 particle-steps (particles x\n"
    "steps; `queries` simulates the scene's whole run whatever A:B) or one that would keep\n"
    "more than 4e9 bytes of states, with the estimate; --force runs it anyway.\n"
    "\n"
    "The other forms (each with its --help):\n"
    "  ccdlab cloth frames SCENE -o DIR        every state, for replay (cloth.json, positions.f64)\n"
    "  ccdlab cloth queries SCENE --steps A:B -o DIR\n"
    "                                          the CCD queries of steps A to B-1 with exact answers\n"
    "\n"
    "Exit status: 0 success, 1 runtime failure, 2 bad input or usage (nothing written).";

int run_cloth(std::span<const std::string> args) {
  if (!args.empty() && args[0] == "frames") return run_cloth_frames(args.subspan(1));
  if (!args.empty() && args[0] == "queries") return run_cloth_queries(args.subspan(1));
  std::string scene_arg, out_path;
  int n = 32, every = 10;
  bool cull = false, force = false;
  std::optional<int> steps;
  CommandLine cli("cloth", kClothDescription, "cloth");
  cli.footer(kClothFooter);
  cli.positional("SCENE", scene_arg, "drape, twist, pile or a ccdlab-cloth/1 file");
  cli.text("-o,--output", out_path, "FRAMES.json", "the frames (written atomically)", "-o needs a file name");
  declare_cloth_scene_options(cli, n, &steps);
  cli.integer("--every", 1, 1000000, "E", "keep every E-th state (default 10) and the last",
              [&every](std::uint64_t v) { every = static_cast<int>(v); });
  cli.flag("--cull", cull,
           "also run the bvh and bvh_cones cullers on every step interval (continuous,\n"
           "separation = thickness) and print their candidates and time per step");
  cli.flag("--force", force, "run past the work limits (below)");
  try {
    if (!cli.parse(args)) return 0;
    if (scene_arg.empty() || out_path.empty()) cli.fail("need a scene (drape, twist, pile or FILE.json) and -o FILE");
  } catch (...) {
    return command_failed("cloth");
  }
  try {
    const auto names = ccd::cloth::builtin_cloth_scene_names();
    const bool builtin = std::find(names.begin(), names.end(), scene_arg) != names.end();
    std::vector<std::string> inputs;
    if (!builtin) inputs.push_back(scene_arg);
    ccd::OutputFile output(out_path, inputs);
    ccd::cloth::ClothScene scene =
        builtin ? ccd::cloth::builtin_cloth_scene(scene_arg, n) : ccd::cloth::read_cloth_scene(scene_arg);
    if (steps) scene.steps = *steps;
    // Every E-th state is kept as JSON numbers and then as text: about 110 bytes a particle.
    check_cloth_work(scene, scene_arg, std::floor(scene.steps / static_cast<double>(every)) + 2.0, 110.0, force);
    ccd::cloth::ClothSimulator sim(scene);
    nlohmann::json frames = nlohmann::json::array();
    auto record = [&] {
      std::vector<double> flat;
      for (const ccd::Vec3& x : sim.positions()) flat.insert(flat.end(), {x.x(), x.y(), x.z()});
      frames.push_back({{"t", sim.time()}, {"x", flat}});
    };
    record();
    long iterations = 0;
    double seconds = 0.0;
    // --cull: per step interval, the bvh and bvh_cones candidates (continuous mode, the
    // scene's thickness as separation) and their time.
    const std::vector<std::string_view> measured = {"bvh", "bvh_cones"};
    std::vector<double> candidates(measured.size(), 0.0), cull_seconds(measured.size(), 0.0);
    // One instance per culler for the whole run, so the bvh refits its tree step to step.
    std::vector<std::unique_ptr<ccd::cloth::Culler>> instances;
    for (const std::string_view name : measured) instances.push_back(ccd::cloth::find_culler(name)->make());
    for (int k = 1; k <= scene.steps; ++k) {
      const std::vector<ccd::Vec3> before = sim.positions();
      const auto start = std::chrono::steady_clock::now();
      sim.step();
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      iterations += sim.last_iterations();
      if (cull)
        for (std::size_t m = 0; m < measured.size(); ++m) {
          const auto t0 = std::chrono::steady_clock::now();
          const auto c = instances[m]->cull(sim.mesh(), before, sim.positions(), scene.thickness);
          cull_seconds[m] += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          candidates[m] += static_cast<double>(c.size());
        }
      if (k % every == 0 || k == scene.steps) record();
    }
    nlohmann::json j;
    j["format"] = "ccdlab-cloth-frames/1";
    j["scene"] = ccd::escape_invalid_utf8(scene_arg);
    j["nx"] = scene.nx;
    j["ny"] = scene.ny;
    j["step"] = scene.step;
    j["every"] = every;
    j["triangles"] = sim.mesh().triangles;
    nlohmann::json spheres = nlohmann::json::array();
    for (const auto& s : scene.spheres)
      spheres.push_back({{"center", {s.center.x(), s.center.y(), s.center.z()}}, {"radius", s.radius}});
    j["spheres"] = spheres;
    j["floor"] = scene.floor ? nlohmann::json(*scene.floor) : nlohmann::json(nullptr);
    j["frames"] = frames;
    output.commit(j.dump() + "\n");
    std::cout << "particles: " << scene.particle_count() << ", triangles: " << sim.mesh().triangles.size()
              << ", steps: " << scene.steps << " of " << scene.step << " s\n"
              << "time per step: " << seconds / scene.steps * 1e3 << " ms, CG iterations per step: "
              << static_cast<double>(iterations) / scene.steps << "\n"
              << "frames: " << frames.size() << " written to " << out_path << "\n";
    if (cull) {
      for (std::size_t m = 0; m < measured.size(); ++m)
        std::cout << measured[m] << ": " << candidates[m] / scene.steps << " candidates per step, "
                  << cull_seconds[m] / scene.steps * 1e3 << " ms per step\n";
      std::cout << "normal-cone culling ratio (bvh_cones / bvh candidates): "
                << (candidates[0] > 0 ? candidates[1] / candidates[0] : 1.0) << "\n";
    }
  } catch (...) {
    return command_failed("cloth", "simulating " + scene_arg);
  }
  return 0;
}

}  // namespace

extern const Command kClothCommand = {
    "cloth", "simulate a cloth scene (drape, twist, pile or a ccdlab-cloth/1 file); write its frames or its CCD queries",
    run_cloth};

}  // namespace ccdlab
