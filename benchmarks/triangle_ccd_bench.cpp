// Speed of the triangle CCD kernels (cloth/ccd/triangle_ccd.hpp) and of the exact rational
// reference (cloth/exact/exact_ccd.hpp), per query, on two sets per kind:
//   hard:   ccdlab's hand-built hard queries (data/ccd/hard_vf.csv, hard_ee.csv)
//   random: near-contact queries: random unit-cube primitives whose t = 1 positions are
//           those at t = 0 plus a displacement uniform in [-0.6, 0.6]^3 (seed 16)
// Counters: hits (queries reported as contact), boxes (parameter boxes per query).
// Run: ./build/triangle_ccd_bench --benchmark_counters_tabular=true
#include <cloth/ccd/hard_queries.hpp>
#include <cloth/ccd/triangle_ccd.hpp>
#include <cloth/exact/exact_ccd.hpp>

#include <benchmark/benchmark.h>

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

void BM_Kernel_VF_Hard(benchmark::State& s) { static const auto q = hard(PrimitivePair::VertexFace); run_kernel(s, PrimitivePair::VertexFace, q); }
void BM_Kernel_EE_Hard(benchmark::State& s) { static const auto q = hard(PrimitivePair::EdgeEdge); run_kernel(s, PrimitivePair::EdgeEdge, q); }
void BM_Kernel_VF_Random(benchmark::State& s) { static const auto q = random_set(4096); run_kernel(s, PrimitivePair::VertexFace, q); }
void BM_Kernel_EE_Random(benchmark::State& s) { static const auto q = random_set(4096); run_kernel(s, PrimitivePair::EdgeEdge, q); }
void BM_Exact_VF_Hard(benchmark::State& s) { static const auto q = hard(PrimitivePair::VertexFace); run_exact(s, PrimitivePair::VertexFace, q); }
void BM_Exact_EE_Hard(benchmark::State& s) { static const auto q = hard(PrimitivePair::EdgeEdge); run_exact(s, PrimitivePair::EdgeEdge, q); }

BENCHMARK(BM_Kernel_VF_Hard);
BENCHMARK(BM_Kernel_EE_Hard);
BENCHMARK(BM_Kernel_VF_Random);
BENCHMARK(BM_Kernel_EE_Random);
BENCHMARK(BM_Exact_VF_Hard)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Exact_EE_Hard)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
