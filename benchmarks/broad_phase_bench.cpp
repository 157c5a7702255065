// ms per frame of every registered broad phase on the shared moving-spheres scene
// (benchmarks/support/peer_scene.hpp), following the peers' protocol: 2 warm-up frames, 20
// measured frames, median reported as the benchmark's time (manual time, one iteration):
// the median of the thread's CPU time per frame (robust to other jobs on a shared
// machine); the counter wall_ms is the median wall-clock time.
// Counters: pairs/frame, swaps/frame (sweep and prune), rebuilds among measured frames,
// min_ms and max_ms (fastest measured frame; slowest of frames 1-22, warm-up included),
// setup_ms (frame 0), all thread CPU time.
// Frames 0 and 22 are checked against the published pair counts and checksums; a mismatch
// fails the benchmark. At startup the scene is checked with `grid` up to the largest N run.
//
//   broad_phase_bench [--sizes=1000,10000,100000,1000000] [--slow] [benchmark flags]
//
// A second family, mixed_sizes/METHOD/100000, times a static scene whose sizes span three
// orders of magnitude (the case for `hgrid`), every frame a rebuild (`reuse=0` for `grid`
// and `hgrid`, whose Verlet list would otherwise serve the unchanged frames).
//
// Without --slow, combinations that are quadratic in practice are not registered:
// brute above 10,000 bodies, sweep above 100,000 (a one-axis sweep meets ~n^2 / L * 4
// x-overlaps: 3e9 at 1e6), sap above 100,000 (swaps grow as n^(5/3): past its budget
// at 1e6, so it rebuilds with that sweep every frame) and rtree at 1,000,000 (about
// 1.5 s per frame).
#include "support/peer_protocol.hpp"
#include "support/size_option.hpp"

#include <ccd/broad_phase/registry.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <memory>
#include <string>
#include <random>
#include <string>
#include <vector>

namespace {

bool too_slow(std::string_view name, std::size_t n) {
  return (name == "brute" && n > 10000) || ((name == "sap" || name == "sweep") && n > 100000) ||
         (name == "rtree" && n > 100000);
}

void run(benchmark::State& state, const ccd::BroadPhaseInfo* info, std::size_t n) {
  for (auto _ : state) {
    auto method = info->make();
    const ccdlab::bench::PeerRun r = ccdlab::bench::run_peer_protocol(*method, n);
    if (!r.error.empty()) {
      state.SkipWithError(r.error.c_str());
      return;
    }
    state.SetIterationTime(r.median_ms * 1e-3);
    state.counters["pairs/frame"] = r.pairs_per_frame;
    state.counters["swaps/frame"] = r.swaps_per_frame;
    state.counters["rebuilds"] = r.rebuilds;
    state.counters["min_ms"] = r.min_ms;
    state.counters["max_ms"] = r.max_ms;
    state.counters["setup_ms"] = r.setup_ms;
    state.counters["wall_ms"] = r.median_wall_ms;
  }
}

// The method rebuilding every frame: the mixed-sizes scene is static, so a Verlet list
// (`reuse`, grid and hgrid) would serve every frame after the first from its list.
std::unique_ptr<ccd::BroadPhase> rebuilding(const ccd::BroadPhaseInfo& info) {
  for (const ccd::ParameterSpec& p : info.parameters)
    if (p.name == "reuse") return ccd::parse_broad_phase(std::string(info.name) + ":reuse=0").make();
  return info.make();
}

// Sizes over three orders of magnitude: 99% of the spheres with radius log-uniform in
// [0.005, 0.05], 1% with radius 5, uniformly in [0, 100]^3 (seed 7), static. `grid` sizes
// its cells for the radius-5 spheres (about 100 small ones per cell); `hgrid` puts the small
// ones on fine levels. Same protocol (2 warm-up + 20 frames, median CPU ms).
void run_mixed(benchmark::State& state, const ccd::BroadPhaseInfo* info, std::size_t n) {
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> pos(0, 100), lg(std::log(0.005), std::log(0.05)), u(0, 1);
  std::vector<ccd::Aabb> boxes;
  for (std::size_t i = 0; i < n; ++i) {
    const ccd::Vec3 c(pos(gen), pos(gen), pos(gen));
    const double r = u(gen) < 0.01 ? 5.0 : std::exp(lg(gen));
    boxes.push_back(ccd::Aabb::around(c, r));
  }
  for (auto _ : state) {
    auto method = rebuilding(*info);
    std::vector<ccd::BodyPair> pairs;
    std::vector<double> ms;
    for (int f = 0; f < 22; ++f) {
      timespec a{}, b{};
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &a);
      method->find_pairs(boxes, pairs);
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &b);
      if (f >= 2) ms.push_back(static_cast<double>(b.tv_sec - a.tv_sec) * 1e3 + static_cast<double>(b.tv_nsec - a.tv_nsec) * 1e-6);
    }
    std::sort(ms.begin(), ms.end());
    state.SetIterationTime(0.5 * (ms[9] + ms[10]) * 1e-3);
    state.counters["pairs/frame"] = static_cast<double>(pairs.size());
    state.counters["box_tests"] = static_cast<double>(method->stats().box_tests);
  }
}

}  // namespace

int main(int argc, char** argv) {
  auto args = ccdlab::bench::take_sizes(argc, argv, {1000, 10000, 100000, 1000000}, "broad_phase_bench", 100000000,
                                        "1e8");
  if (!args) return 2;
  const std::vector<std::size_t>& sizes = args->sizes;
  std::vector<char*> rest;
  bool slow = false;
  for (char* a : args->rest) {
    if (std::strcmp(a, "--slow") == 0) slow = true;
    else rest.push_back(a);
  }
  std::size_t max_n = 0;
  for (std::size_t n : sizes) max_n = std::max(max_n, n);
  {
    auto grid = ccd::find_broad_phase("grid").make();
    const std::string err = ccdlab::bench::verify_peer_scene(*grid, max_n);
    if (!err.empty()) {
      std::fprintf(stderr, "peer scene check failed: %s\n", err.c_str());
      return 1;
    }
    std::fprintf(stderr, "peer scene: frames 0 and 22 match the published pairs and checksums up to N=%zu\n",
                 max_n);
  }
  for (std::size_t n : sizes)
    for (const ccd::BroadPhaseInfo& info : ccd::broad_phase_registry()) {
      if (!slow && too_slow(info.name, n)) continue;
      const std::string name = std::string(info.name) + "/" + std::to_string(n);
      benchmark::RegisterBenchmark(name.c_str(), run, &info, n)
          ->Iterations(1)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
    }
  for (const ccd::BroadPhaseInfo& info : ccd::broad_phase_registry()) {
    if (info.name == "brute") continue;
    const std::string name = "mixed_sizes/" + std::string(info.name) + "/100000";
    benchmark::RegisterBenchmark(name.c_str(), run_mixed, &info, std::size_t{100000})
        ->Iterations(1)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  }
  int rest_argc = static_cast<int>(rest.size());
  benchmark::Initialize(&rest_argc, rest.data());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
