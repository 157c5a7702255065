// The fixed cost of one ccd::parallel_for call (ccd/util/parallel_for.hpp): `threads`
// items that do nothing, so the time is all hand-out and wake-up. Compared with starting
// `threads - 1` std::jthreads for the call and joining them (the same contract, no pool),
// which sets how small a piece of work may be before threads stop paying off.
//
//   parallel_for_bench [benchmark flags]
#include <ccd/util/parallel_for.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace {

// parallel_for's contract on threads started for the call (worker 0 is the caller).
template <class Fn>
void jthread_for(std::size_t count, unsigned threads, Fn&& fn) {
  const auto workers = static_cast<unsigned>(std::min<std::size_t>(threads, count));
  std::atomic<std::size_t> next{0};
  auto work = [&](unsigned worker) {
    for (std::size_t k; (k = next.fetch_add(1, std::memory_order_relaxed)) < count;) fn(k, worker);
  };
  std::vector<std::jthread> started;
  started.reserve(workers - 1);
  for (unsigned w = 1; w < workers; ++w) started.emplace_back(work, w);
  work(0u);
}

void pool(benchmark::State& state) {
  const auto threads = static_cast<unsigned>(state.range(0));
  std::atomic<std::size_t> sink{0};
  for (auto _ : state)
    ccd::parallel_for(threads, threads, [&](std::size_t k, unsigned) { sink.fetch_add(k, std::memory_order_relaxed); });
  benchmark::DoNotOptimize(sink.load());
}

void jthreads(benchmark::State& state) {
  const auto threads = static_cast<unsigned>(state.range(0));
  std::atomic<std::size_t> sink{0};
  for (auto _ : state)
    jthread_for(threads, threads, [&](std::size_t k, unsigned) { sink.fetch_add(k, std::memory_order_relaxed); });
  benchmark::DoNotOptimize(sink.load());
}

}  // namespace

BENCHMARK(pool)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(jthreads)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_MAIN();
