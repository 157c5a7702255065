// `ccdlab cloth queries SCENE --culler NAME --steps A:B [--hard-below D] -o DIR`: the
// vertex-face and edge-edge candidates of a cloth run's steps as benchmark-format query
// files with exact answers (docs/cloth.md#cloth-frames-and-queries-out).
#include "cloth_subcommands.hpp"
#include "command.hpp"
#include "command_line.hpp"

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

constexpr const char* kClothQueriesDescription =
    "Simulates the cloth and writes, for the step intervals A, A+1, ..., B-1 (interval s runs\n"
    "from state s to state s + 1, each vertex moving linearly; 0 <= A < B <= the scene's\n"
    "steps), every vertex-face and edge-edge candidate the culler returns (one instance over\n"
    "the steps, separation = the scene's thickness) into the folder DIR (atomically: a\n"
    "temporary folder renamed):\n"
    "  vf.csv, ee.csv  the public CCD benchmark's layout (8 rows per query; x, y, z as exact\n"
    "                  numerator, denominator of the doubles; column 7 the exact answer at\n"
    "                  separation 0 from the rational reference), read by `ccdlab ccd`\n"
    "  index.json      ccdlab-cloth-queries/1: the motion's digest, the options, and per query\n"
    "                  its step, primitive ids and mesh vertices\n";

int run_cloth_queries(std::span<const std::string> args) {
  std::string scene_arg, out_path, culler_name = "bvh_cones", steps_text;
  int n = 32;
  unsigned threads = 1;
  bool force = false;
  std::optional<double> hard_below;
  std::uint64_t first = 0, end = 0;
  CommandLine cli("cloth queries", kClothQueriesDescription, "cloth");
  cli.footer("The whole run is simulated whatever A:B: above 1e9 particle-steps or 4e9 bytes of states\n"
             "it is refused before the simulation with the estimate unless --force.\n"
             "\n"
             "Exit status: 0 success, 1 runtime failure, 2 bad input or usage (nothing written).");
  cli.positional("SCENE", scene_arg, "drape, twist, pile or a ccdlab-cloth/1 file");
  cli.text("-o,--output", out_path, "DIR",
           "the folder; an existing DIR is replaced only when it is empty or holds\n"
           "an index.json",
           "-o needs a folder name");
  cli.value(
      "--steps", "A:B", "the step intervals A to B-1, integers with 0 <= A < B <= the scene's steps",
      [&](const std::string& v) {
        steps_text = v;
        const auto colon = v.find(':');
        const auto lo = colon == std::string::npos ? std::nullopt : ccd::parse_integer(v.substr(0, colon), 0, 1000000);
        const auto hi = colon == std::string::npos ? std::nullopt : ccd::parse_integer(v.substr(colon + 1), 1, 1000000);
        if (!lo || !hi || *lo >= *hi) cli.fail("--steps '" + v + "': needs A:B, integers with 0 <= A < B");
        first = *lo;
        end = *hi;
      },
      "--steps needs A:B");
  cli.text("--culler", culler_name, "NAME",
           "the culler: brute, bvh, bvh_cones (default), sensors or boxes:<broad phase>",
           "--culler needs a name: brute, bvh, bvh_cones, sensors or boxes:<broad phase>");
  cli.number("--hard-below", 0.0, false, "D",
             "keep only the queries whose primitives come within distance D (m,\n"
             "touching included) during their step, decided exactly; the culler then runs\n"
             "with separation max(thickness, D)",
             [&hard_below](double d) { hard_below = d; });
  declare_cloth_scene_options(cli, n, nullptr);
  cli.integer("--threads", 1, 1024, "T", "threads of the exact reference (default 1)",
              [&threads](std::uint64_t v) { threads = static_cast<unsigned>(v); });
  cli.flag("--force", force, "run past the work limits");
  const ccd::cloth::CullerEntry* culler = nullptr;
  try {
    if (!cli.parse(args)) return 0;
    if (scene_arg.empty() || out_path.empty() || steps_text.empty())
      cli.fail("need a scene (drape, twist, pile or FILE.json), --steps A:B and -o DIR");
    culler = ccd::cloth::find_culler(culler_name);
    if (!culler)
      cli.fail("--culler: unknown culler '" + culler_name + "' (brute, bvh, bvh_cones, sensors or boxes:<broad phase>)");
  } catch (...) {
    return command_failed("cloth queries");
  }
  try {
    const ccd::cloth::ClothScene scene = load_cloth_scene(scene_arg, n);
    if (end > static_cast<std::uint64_t>(scene.steps))
      cli.fail("--steps '" + steps_text + "': B must be <= the scene's " + std::to_string(scene.steps) + " steps");
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
