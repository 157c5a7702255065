// `ccdlab cloth frames SCENE -o DIR`: the vertex positions at every integrator step, the
// triangles, the edges and the springs, so any tool can replay the motion
// (docs/cloth.md#cloth-frames-and-queries-out).
#include "cloth_subcommands.hpp"
#include "command.hpp"

#include "../work_estimate.hpp"

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

int run_cloth_frames(std::span<const std::string> args) {
  auto usage_error = [](const std::string& msg) {
    std::cerr << "ccdlab cloth frames: " << msg << " (see ccdlab cloth --help)\n";
    return kExitBadInput;
  };
  std::string scene_arg, out_path;
  int n = 32;
  bool force = false;
  std::optional<int> steps;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool has_value = i + 1 < args.size();
    if (a == "-o" || a == "--output") {
      if (!has_value) return usage_error("-o needs a folder name");
      out_path = args[++i];
    } else if (a == "--n") {
      const auto v = has_value ? ccd::parse_integer(args[++i], 4, 1000) : std::nullopt;
      if (!v) return usage_error("--n needs an integer in [4, 1000]");
      n = static_cast<int>(*v);
    } else if (a == "--steps") {
      const auto v = has_value ? ccd::parse_integer(args[++i], 1, 1000000) : std::nullopt;
      if (!v) return usage_error("--steps needs an integer in [1, 1000000]");
      steps = static_cast<int>(*v);
    } else if (a == "--force") {
      force = true;
    } else if (a.size() > 1 && a[0] == '-') {
      return usage_error("unknown option '" + a + "'");
    } else if (scene_arg.empty()) {
      scene_arg = a;
    } else {
      return usage_error("one scene only");
    }
  }
  if (scene_arg.empty() || out_path.empty())
    return usage_error("need a scene (drape, twist, pile or FILE.json) and -o DIR");
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
