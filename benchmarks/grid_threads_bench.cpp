// `grid` with 1, 2, ... threads (GridOptions::threads; --threads, default 1,2) on the shared moving-spheres scene
// (benchmarks/support/peer_scene.hpp), peers' protocol: frame 0 builds, frames 1-2 warm up,
// frames 3-22 measured. Not through the registry (whose `grid` is serial). Every frame is a
// rebuild (reuse = 0: no Verlet list), since the rebuild is what the threads split.
// Reported time: median WALL-clock ms per frame (threads only pay off in wall time);
// counters: cpu_ms = median process CPU ms per frame (all threads; on an idle machine
// cpu_ms / wall ms ~ the cores in use), pairs/frame. Speedup = wall(1) / wall(T). On a
// shared machine the other cores may be busy: compare with the load average.
//
//   grid_threads_bench [--sizes=100000,1000000] [--threads=1,2] [benchmark flags]
#include <ccd/broad_phase/grid.hpp>
#include <benchmarks/support/peer_scene.hpp>
#include <benchmarks/support/size_option.hpp>

#include <benchmark/benchmark.h>

#include <cstdio>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

namespace {

double process_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return 0.5 * (v[(v.size() - 1) / 2] + v[v.size() / 2]);
}

void run(benchmark::State& state, std::size_t n, unsigned threads) {
  for (auto _ : state) {
    ccdlab::bench::PeerScene scene(n, 1);
    ccd::UniformGrid grid(ccd::GridOptions{.threads = threads, .reuse = 0});
    std::vector<ccd::Aabb> boxes;
    std::vector<ccd::BodyPair> pairs;
    scene.boxes(boxes);
    grid.find_pairs(boxes, pairs);
    std::vector<double> wall, cpu;
    double pair_sum = 0;
    for (int f = 1; f <= 22; ++f) {
      scene.step();
      scene.boxes(boxes);
      const auto w0 = std::chrono::steady_clock::now();
      const double c0 = process_cpu_ms();
      grid.find_pairs(boxes, pairs);
      const double c1 = process_cpu_ms();
      const auto w1 = std::chrono::steady_clock::now();
      if (f > 2) {
        wall.push_back(std::chrono::duration<double, std::milli>(w1 - w0).count());
        cpu.push_back(c1 - c0);
        pair_sum += static_cast<double>(pairs.size());
      }
    }
    state.SetIterationTime(median(wall) * 1e-3);
    state.counters["cpu_ms"] = median(cpu);
    state.counters["min_wall_ms"] = *std::min_element(wall.begin(), wall.end());
    state.counters["pairs/frame"] = pair_sum / 20;
  }
}

}  // namespace

int main(int argc, char** argv) {
  auto args = ccdlab::bench::take_sizes(argc, argv, {100000, 1000000}, "grid_threads_bench", 100000000, "1e8");
  if (!args) return 2;
  auto threads = ccdlab::bench::take_threads(std::move(args->rest), {1, 2}, "grid_threads_bench");
  if (!threads) return 2;
  const std::vector<std::size_t>& sizes = args->sizes;
  std::vector<char*>& rest = threads->rest;
  for (std::size_t n : sizes)
    for (std::size_t t : threads->values)
      benchmark::RegisterBenchmark(("grid_threads/" + std::to_string(n) + "/" + std::to_string(t)).c_str(), run, n,
                                   static_cast<unsigned>(t))
          ->Iterations(1)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
  int rest_argc = static_cast<int>(rest.size());
  benchmark::Initialize(&rest_argc, rest.data());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
