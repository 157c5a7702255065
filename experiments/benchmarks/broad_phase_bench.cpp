// ms per frame of every registered broad phase on the shared moving-spheres scene
// (ccd/broad_phase/peer_scene.hpp), following the peers' protocol: 2 warm-up frames, 20
// measured frames, median reported as the benchmark's time (manual time, one iteration):
// the median of the thread's CPU time per frame (robust to other jobs on a shared
// machine); the counter wall_ms is the median wall-clock time.
// Counters: pairs/frame, swaps/frame (sweep and prune), rebuilds among measured frames.
// Frames 0 and 22 are checked against the published pair counts and checksums; a mismatch
// fails the benchmark. At startup the scene is checked with `grid` up to the largest N run.
//
//   broad_phase_bench [--sizes=1000,10000,100000,1000000] [--slow] [benchmark flags]
//
// Without --slow, combinations that are quadratic in practice are not registered:
// brute above 10,000 bodies, sap above 100,000 (a one-axis sweep meets ~n^2 / L * 4
// x-overlaps: 3e9 at 1e6) and rtree at 1,000,000 (about 1.5 s per frame).
#include "support/peer_protocol.hpp"

#include <ccd/broad_phase/registry.hpp>

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

bool too_slow(std::string_view name, std::size_t n) {
  return (name == "brute" && n > 10000) || (name == "sap" && n > 100000) || (name == "rtree" && n > 100000);
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
    state.counters["wall_ms"] = r.median_wall_ms;
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::size_t> sizes = {1000, 10000, 100000, 1000000};
  bool slow = false;
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], "--sizes=", 8) == 0) {
      sizes.clear();
      for (const char* p = argv[i] + 8; *p;) {
        char* end = nullptr;
        sizes.push_back(std::strtoull(p, &end, 10));
        p = (*end == ',') ? end + 1 : end;
        if (end == p && *p) break;
      }
    } else if (std::strcmp(argv[i], "--slow") == 0) {
      slow = true;
    } else {
      rest.push_back(argv[i]);
    }
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
  int rest_argc = static_cast<int>(rest.size());
  benchmark::Initialize(&rest_argc, rest.data());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
