// Speed of the triangle CCD kernels (cloth/ccd/triangle_ccd.hpp) and of the exact rational
// reference (cloth/exact/exact_ccd.hpp), per query, on two sets per kind:
//   hard:   ccdlab's hand-built hard queries (data/ccd/hard_vf.csv, hard_ee.csv)
//   random: near-contact queries: random unit-cube primitives whose t = 1 positions are
//           those at t = 0 plus a displacement uniform in [-0.6, 0.6]^3 (seed 16)
// Counters: hits (queries reported as contact), boxes (parameter boxes per query).
// The *_Quantiles benchmarks time every query of the set one by one, the whole set per
// iteration, and report the median, p99.9 and largest time per query in microseconds
// (median_us, p999_us, max_us). Argument 0: the steady clock around each call (cheap, but
// on a shared machine the tail holds the time the thread was descheduled). Argument 1: the
// thread's CPU clock (time spent elsewhere is not counted, but each reading is a system
// call of about 0.3 us, which every figure includes). Argument 2 of the random sets: 1 runs
// the kernel with keep_tolerance_stops (tolerance stops reported as contacts, undecided),
// 0 as it is by default (tolerance stops decided): before and after, in one run.
// Run: ./build/triangle_ccd_bench --benchmark_counters_tabular=true
#include <cloth/ccd/hard_queries.hpp>
#include <cloth/ccd/triangle_ccd.hpp>
#include <cloth/exact/exact_ccd.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <ctime>
#include <random>
#include <vector>

namespace {

using ccd::cloth::LinearQuery;
using ccd::cloth::PrimitivePair;

std::vector<LinearQuery> hard(PrimitivePair kind) {
  std::vector<LinearQuery> q;
  for (const auto& c : ccd::cloth::hard_queries(kind)) q.push_back(c.query);
  return q;
}

std::vector<LinearQuery> random_set(int n) {
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> u(0.0, 1.0), d(-0.6, 0.6);
  std::vector<LinearQuery> out;
  for (int i = 0; i < n; ++i) {
    LinearQuery q;
    for (int k = 0; k < 4; ++k) {
      q.x[static_cast<std::size_t>(k)] = ccd::Vec3(u(rng), u(rng), u(rng));
      q.x[static_cast<std::size_t>(k + 4)] = q.x[static_cast<std::size_t>(k)] + ccd::Vec3(d(rng), d(rng), d(rng));
    }
    out.push_back(q);
  }
  return out;
}

void run_kernel(benchmark::State& state, PrimitivePair kind, const std::vector<LinearQuery>& set) {
  std::size_t i = 0, hits = 0, boxes = 0, n = 0;
  for (auto _ : state) {
    const auto r = ccd::cloth::triangle_ccd(kind, set[i]);
    benchmark::DoNotOptimize(r);
    hits += r.status != ccd::QueryStatus::Miss;
    boxes += r.boxes;
    ++n;
    i = i + 1 == set.size() ? 0 : i + 1;
  }
  state.counters["hits"] = benchmark::Counter(static_cast<double>(hits) / static_cast<double>(n));
  state.counters["boxes"] = benchmark::Counter(static_cast<double>(boxes) / static_cast<double>(n));
}

void run_exact(benchmark::State& state, PrimitivePair kind, const std::vector<LinearQuery>& set) {
  std::vector<ccd::cloth::RationalQuery> rq;
  for (const auto& q : set) rq.push_back(ccd::cloth::to_rational(q));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(ccd::cloth::exact_contact(kind, rq[i], 0));
    i = i + 1 == rq.size() ? 0 : i + 1;
  }
}

void run_quantiles(benchmark::State& state, PrimitivePair kind, const std::vector<LinearQuery>& set) {
  ccd::cloth::TriangleCcdOptions options;
  options.keep_tolerance_stops = state.range(1) != 0;
  std::vector<double> us;
  for (auto _ : state)
    for (const LinearQuery& q : set) {
      const clockid_t clock = state.range(0) == 0 ? CLOCK_MONOTONIC : CLOCK_THREAD_CPUTIME_ID;
      timespec t0{}, t1{};
      clock_gettime(clock, &t0);
      const auto r = ccd::cloth::triangle_ccd(kind, q, options);
      clock_gettime(clock, &t1);
      benchmark::DoNotOptimize(r);
      us.push_back(static_cast<double>(t1.tv_sec - t0.tv_sec) * 1e6 + static_cast<double>(t1.tv_nsec - t0.tv_nsec) * 1e-3);
    }
  std::sort(us.begin(), us.end());
  auto quantile = [&](double p) { return us[std::min(us.size() - 1, static_cast<std::size_t>(p * static_cast<double>(us.size())))]; };
  state.counters["median_us"] = quantile(0.5);
  state.counters["p999_us"] = quantile(0.999);
  state.counters["max_us"] = us.back();
}

void BM_Kernel_VF_Hard(benchmark::State& s) { static const auto q = hard(PrimitivePair::VertexFace); run_kernel(s, PrimitivePair::VertexFace, q); }
void BM_Kernel_EE_Hard(benchmark::State& s) { static const auto q = hard(PrimitivePair::EdgeEdge); run_kernel(s, PrimitivePair::EdgeEdge, q); }
void BM_Kernel_VF_Random(benchmark::State& s) { static const auto q = random_set(4096); run_kernel(s, PrimitivePair::VertexFace, q); }
void BM_Kernel_EE_Random(benchmark::State& s) { static const auto q = random_set(4096); run_kernel(s, PrimitivePair::EdgeEdge, q); }
void BM_Kernel_VF_Random_Quantiles(benchmark::State& s) { static const auto q = random_set(4096); run_quantiles(s, PrimitivePair::VertexFace, q); }
void BM_Kernel_EE_Random_Quantiles(benchmark::State& s) { static const auto q = random_set(4096); run_quantiles(s, PrimitivePair::EdgeEdge, q); }
void BM_Kernel_VF_Hard_Quantiles(benchmark::State& s) { static const auto q = hard(PrimitivePair::VertexFace); run_quantiles(s, PrimitivePair::VertexFace, q); }
void BM_Kernel_EE_Hard_Quantiles(benchmark::State& s) { static const auto q = hard(PrimitivePair::EdgeEdge); run_quantiles(s, PrimitivePair::EdgeEdge, q); }
void BM_Exact_VF_Hard(benchmark::State& s) { static const auto q = hard(PrimitivePair::VertexFace); run_exact(s, PrimitivePair::VertexFace, q); }
void BM_Exact_EE_Hard(benchmark::State& s) { static const auto q = hard(PrimitivePair::EdgeEdge); run_exact(s, PrimitivePair::EdgeEdge, q); }

BENCHMARK(BM_Kernel_VF_Hard);
BENCHMARK(BM_Kernel_EE_Hard);
BENCHMARK(BM_Kernel_VF_Random);
BENCHMARK(BM_Kernel_EE_Random);
// Arguments: clock (0 steady, 1 thread CPU), keep_tolerance_stops (1) or not (0).
BENCHMARK(BM_Kernel_VF_Random_Quantiles)->ArgsProduct({{0, 1}, {1, 0}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Kernel_EE_Random_Quantiles)->ArgsProduct({{0, 1}, {1, 0}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Kernel_VF_Hard_Quantiles)->ArgsProduct({{0, 1}, {0}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Kernel_EE_Hard_Quantiles)->ArgsProduct({{0, 1}, {0}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Exact_VF_Hard)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Exact_EE_Hard)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
