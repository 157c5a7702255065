// Speed of the cloth self-collision cullers (cloth/cull/cullers.hpp) on the built-in
// scenes: each iteration culls the next step interval of the simulated run (continuous
// mode, separation = the scene's thickness), with one culler instance kept over the run
// (so `bvh` and `bvh_cones` refit their hierarchy, and rebuild it when it degrades). One
// iteration per step interval: every interval of the run once, in order. Each scene is
// simulated once per process, before its first benchmark.
// Counters: candidates (per interval), rebuilt (share of intervals that rebuilt the tree).
// Run: ./build/cloth_cull_bench --n=72 --benchmark_counters_tabular=true
//      (--n: particles per side, default 72: 10,082 triangles; the simulation takes minutes)
#include <cloth/cull/cullers.hpp>
#include <cloth/sim/cloth_simulator.hpp>

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace {

int g_n = 72;

struct Run {
  ccd::cloth::ClothScene scene;
  ccd::cloth::ClothMesh mesh;
  std::vector<std::vector<ccd::Vec3>> frames;
};

const Run& run_of(const std::string& name) {
  static std::map<std::string, Run> runs;
  auto it = runs.find(name);
  if (it == runs.end()) {
    Run r;
    r.scene = ccd::cloth::builtin_cloth_scene(name, g_n);
    r.mesh = ccd::cloth::make_grid_mesh(r.scene);
    r.frames = ccd::cloth::simulate_cloth(r.scene);
    it = runs.emplace(name, std::move(r)).first;
  }
  return it->second;
}

void cull(benchmark::State& state, const std::string& scene, const std::string& culler) {
  const Run& r = run_of(scene);
  const auto instance = ccd::cloth::find_culler(culler)->make();
  std::size_t k = 0, candidates = 0, rebuilt = 0, calls = 0;
  for (auto _ : state) {
    const auto c = instance->cull(r.mesh, r.frames[k], r.frames[k + 1], r.scene.thickness);
    benchmark::DoNotOptimize(c.data());
    candidates += c.size();
    for (const auto& counter : instance->counters())
      if (counter.name == "rebuilt") rebuilt += counter.value;
    ++calls;
    k = k + 2 == r.frames.size() ? 0 : k + 1;
  }
  state.counters["triangles"] = static_cast<double>(r.mesh.triangles.size());
  state.counters["candidates"] = static_cast<double>(candidates) / static_cast<double>(calls);
  state.counters["rebuilt"] = static_cast<double>(rebuilt) / static_cast<double>(calls);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], "--n=", 4) == 0) {
      g_n = std::atoi(argv[i] + 4);
      if (g_n < 4 || g_n > 1000) return 2;
    } else {
      args.push_back(argv[i]);
    }
  }
  for (const std::string scene : {"drape", "twist", "pile"})
    for (const std::string culler : {"bvh", "bvh_cones", "sensors", "boxes:grid", "boxes:sap"})
      benchmark::RegisterBenchmark(("cull/" + scene + "/" + culler).c_str(),
                                   [scene, culler](benchmark::State& s) { cull(s, scene, culler); })
          ->Iterations(ccd::cloth::builtin_cloth_scene(scene, g_n).steps)
          ->Unit(benchmark::kMillisecond);
  int count = static_cast<int>(args.size());
  benchmark::Initialize(&count, args.data());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
