// `ccdlab cloth queries SCENE --culler NAME --steps A:B [--hard-below D] -o DIR`: the
// vertex-face and edge-edge candidates of a cloth run's steps as benchmark-format query
// files with exact answers (docs/cloth.md#cloth-frames-and-queries-out).
#include "cloth_subcommands.hpp"
#include "command.hpp"

#include <cloth/cull/cullers.hpp>
#include <cloth/io/query_export.hpp>
#include <cloth/io/query_file.hpp>
#include <cloth/sim/cloth_simulator.hpp>
#include <cloth/truth/mesh_truth_file.hpp>
#include <ccd/io/utf8_text.hpp>
#include <ccd/io/output_directory.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/util/integer_text.hpp>
#include <ccd/util/parallel_for.hpp>

#include <chrono>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

namespace ccdlab {

namespace {

nlohmann::json kind_index(const std::vector<ccd::cloth::ExportedQuery>& qs, const std::string& file) {
  nlohmann::json step = nlohmann::json::array(), a = nlohmann::json::array(), b = nlohmann::json::array(),
                 vertices = nlohmann::json::array();
  std::size_t hits = 0;
  for (const auto& q : qs) {
    step.push_back(q.step);
    a.push_back(q.candidate.a);
    b.push_back(q.candidate.b);
    for (const std::uint32_t v : q.vertices) vertices.push_back(v);
    hits += q.hit ? 1 : 0;
  }
  return {{"file", file}, {"queries", qs.size()}, {"hits", hits}, {"step", step},
          {"a", a},       {"b", b},               {"vertices", vertices}};
}

std::string query_text(const std::vector<ccd::cloth::ExportedQuery>& qs) {
  std::vector<ccd::cloth::LinearQuery> queries;
  std::vector<bool> expected;
  for (const auto& q : qs) {
    queries.push_back(q.query);
    expected.push_back(q.hit);
  }
  return ccd::cloth::format_query_file(queries, expected);
}

}  // namespace

int run_cloth_queries(std::span<const std::string> args) {
  auto usage_error = [](const std::string& msg) {
    std::cerr << "ccdlab cloth queries: " << msg << " (see ccdlab cloth --help)\n";
    return kExitBadInput;
  };
  std::string scene_arg, out_path, culler_name = "bvh_cones", steps_text;
  int n = 32;
  unsigned threads = 1;
  bool force = false;
  std::optional<double> hard_below;
  std::uint64_t first = 0, end = 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool has_value = i + 1 < args.size();
    if (a == "-o" || a == "--output") {
      if (!has_value) return usage_error("-o needs a folder name");
      out_path = args[++i];
    } else if (a == "--culler") {
      if (!has_value) return usage_error("--culler needs a name: brute, bvh, bvh_cones, sensors or boxes:<broad phase>");
      culler_name = args[++i];
    } else if (a == "--steps") {
      if (!has_value) return usage_error("--steps needs A:B");
      steps_text = args[++i];
      const auto colon = steps_text.find(':');
      const auto lo = colon == std::string::npos ? std::nullopt
                                                 : ccd::parse_integer(steps_text.substr(0, colon), 0, 1000000);
      const auto hi = colon == std::string::npos ? std::nullopt
                                                 : ccd::parse_integer(steps_text.substr(colon + 1), 1, 1000000);
      if (!lo || !hi || *lo >= *hi)
        return usage_error("--steps '" + steps_text + "': needs A:B, integers with 0 <= A < B");
      first = *lo;
      end = *hi;
    } else if (a == "--hard-below") {
      const std::string v = has_value ? args[++i] : std::string();
      char* stop = nullptr;
      const double d = v.empty() ? -1.0 : std::strtod(v.c_str(), &stop);
      if (v.empty() || stop != v.c_str() + v.size() || !std::isfinite(d) || d < 0)
        return usage_error("--hard-below needs a distance (m), a finite number >= 0");
      hard_below = d;
    } else if (a == "--n") {
      const auto v = has_value ? ccd::parse_integer(args[++i], 4, 1000) : std::nullopt;
      if (!v) return usage_error("--n needs an integer in [4, 1000]");
      n = static_cast<int>(*v);
    } else if (a == "--threads") {
      const auto v = has_value ? ccd::parse_integer(args[++i], 1, 1024) : std::nullopt;
      if (!v) return usage_error("--threads needs an integer in [1, 1024]");
      threads = static_cast<unsigned>(*v);
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
  if (scene_arg.empty() || out_path.empty() || steps_text.empty())
    return usage_error("need a scene (drape, twist, pile or FILE.json), --steps A:B and -o DIR");
  const ccd::cloth::CullerEntry* culler = ccd::cloth::find_culler(culler_name);
  if (!culler)
    return usage_error("--culler: unknown culler '" + culler_name +
                       "' (brute, bvh, bvh_cones, sensors or boxes:<broad phase>)");
  try {
    const ccd::cloth::ClothScene scene = load_cloth_scene(scene_arg, n);
    if (end > static_cast<std::uint64_t>(scene.steps))
      return usage_error("--steps '" + steps_text + "': B must be <= the scene's " + std::to_string(scene.steps) +
                         " steps");
    // The whole run is simulated and kept (24 bytes a particle and state), whatever A:B.
    check_cloth_work(scene, scene_arg, scene.steps + 1.0, 24.0, force);
    ccd::OutputDirectory output(out_path, "index.json");
    const auto start = std::chrono::steady_clock::now();
    const std::vector<std::vector<ccd::Vec3>> frames = ccd::cloth::simulate_cloth(scene);
    const double simulated = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const ccd::cloth::ClothMesh mesh = ccd::cloth::make_grid_mesh(scene);
    ccd::cloth::QueryExportOptions options;
    options.cull_separation = std::max(scene.thickness, hard_below.value_or(0.0));
    options.hard_below = hard_below;
    options.threads = threads;
    const ccd::cloth::QueryExport ex = ccd::cloth::export_queries(mesh, frames, first, end, *culler, options);
    output.write("vf.csv", query_text(ex.vertex_face));
    output.write("ee.csv", query_text(ex.edge_edge));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nlohmann::json j;
    j["format"] = "ccdlab-cloth-queries/1";
    j["scene"] = ccd::escape_invalid_utf8(scene_arg);
    j["digest"] = ccd::cloth::motion_digest(mesh, frames, scene.thickness);
    j["culler"] = culler->name;
    j["culler_separation"] = options.cull_separation;
    j["hard_below"] = hard_below ? nlohmann::json(*hard_below) : nlohmann::json(nullptr);
    j["steps"] = {first, end};
    j["step"] = scene.step;
    j["candidates"] = ex.candidates;
    j["vf"] = kind_index(ex.vertex_face, "vf.csv");
    j["ee"] = kind_index(ex.edge_edge, "ee.csv");
    j["seconds"] = {{"simulation", simulated}, {"total", seconds}};
    output.write("index.json", j.dump() + "\n");
    output.commit();
    std::cout << "steps " << first << " to " << end - 1 << " of " << scene_arg << ", culler " << culler->name
              << ": " << ex.candidates << " candidates\n"
              << "vertex-face: " << j["vf"]["queries"] << " queries, " << j["vf"]["hits"] << " hits\n"
              << "edge-edge: " << j["ee"]["queries"] << " queries, " << j["ee"]["hits"] << " hits\n"
              << "written to " << out_path << " in " << seconds << " s (simulation " << simulated << " s)\n";
  } catch (...) {
    return command_failed("cloth queries", "simulating " + scene_arg);
  }
  return 0;
}

}  // namespace ccdlab
