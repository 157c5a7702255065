// The static index's query cost: 1,000 moving boxes against N scenery triangles
// (N = 100 .. 10,000, spread in a cube of side 40, each about 40 / N^(1/3) across, so
// the scenery keeps the same density of surface as N grows), one find_pairs per
// iteration. Three structures: StaticIndex (the static AABB tree ccdlab uses), a uniform
// grid built here for the comparison (cell = the mean polygon box's largest side; each
// polygon listed in every cell its box touches, a query visits its box's cells and
// removes duplicates), and brute force (every box pair). Build time is reported apart
// (BM_*_build). Counters: pairs found, ns per moving box.
//   ./build/static_index_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <ccd/broad_phase/static_index.hpp>

#include <benchmark/benchmark.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <unordered_map>
#include <utility>
#include <vector>

namespace {

using ccd::Aabb;
using ccd::Vec3;

std::vector<ccd::StaticPolygon> scenery(std::size_t n) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(-20.0, 20.0), s(-1.0, 1.0);
  const double size = 40.0 / std::cbrt(double(n));
  std::vector<ccd::StaticPolygon> out;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 c(u(rng), u(rng), u(rng));
    ccd::StaticPolygon p;
    for (int k = 0; k < 3; ++k) p.vertices.push_back(c + Vec3(s(rng), s(rng), s(rng)) * size);
    out.push_back(std::move(p));
  }
  return out;
}

std::vector<Aabb> moving(std::size_t m) {
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> u(-20.0, 20.0), r(0.05, 0.5);
  std::vector<Aabb> out;
  for (std::size_t i = 0; i < m; ++i) out.push_back(Aabb::around(Vec3(u(rng), u(rng), u(rng)), r(rng)));
  return out;
}

std::vector<Aabb> boxes_of(const std::vector<ccd::StaticPolygon>& polygons) {
  std::vector<Aabb> b;
  for (const auto& p : polygons) b.push_back(ccd::polygon_box(p));
  return b;
}

// The uniform grid the tree is compared with.
class UniformGrid {
 public:
  explicit UniformGrid(const std::vector<Aabb>& boxes) : boxes_(boxes) {
    double mean = 0.0;
    lo_ = boxes[0].lo;
    for (const Aabb& b : boxes) {
      mean += (b.hi - b.lo).maxCoeff();
      lo_ = lo_.cwiseMin(b.lo);
    }
    cell_ = std::max(mean / double(boxes.size()), 1e-9);
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
      const auto [a, z] = range(boxes[i]);
      for (long x = a[0]; x <= z[0]; ++x)
        for (long y = a[1]; y <= z[1]; ++y)
          for (long w = a[2]; w <= z[2]; ++w) cells_[key(x, y, w)].push_back(i);
    }
  }
  void find_pairs(const std::vector<Aabb>& boxes, std::vector<ccd::StaticPair>& out) const {
    out.clear();
    std::vector<std::uint32_t> hits;
    for (std::uint32_t b = 0; b < boxes.size(); ++b) {
      hits.clear();
      const auto [a, z] = range(boxes[b]);
      for (long x = a[0]; x <= z[0]; ++x)
        for (long y = a[1]; y <= z[1]; ++y)
          for (long w = a[2]; w <= z[2]; ++w) {
            const auto it = cells_.find(key(x, y, w));
            if (it == cells_.end()) continue;
            for (const std::uint32_t p : it->second)
              if (boxes_[p].overlaps(boxes[b])) hits.push_back(p);
          }
      std::sort(hits.begin(), hits.end());
      hits.erase(std::unique(hits.begin(), hits.end()), hits.end());
      for (const std::uint32_t p : hits) out.push_back({b, p});
    }
  }

 private:
  std::pair<std::array<long, 3>, std::array<long, 3>> range(const Aabb& b) const {
    std::array<long, 3> a{}, z{};
    for (int k = 0; k < 3; ++k) {
      a[k] = static_cast<long>(std::floor((b.lo[k] - lo_[k]) / cell_));
      z[k] = static_cast<long>(std::floor((b.hi[k] - lo_[k]) / cell_));
    }
    return {a, z};
  }
  static std::uint64_t key(long x, long y, long z) {
    return (std::uint64_t(x + (1 << 20)) << 42) ^ (std::uint64_t(y + (1 << 20)) << 21) ^ std::uint64_t(z + (1 << 20));
  }
  std::vector<Aabb> boxes_;
  Vec3 lo_;
  double cell_ = 1.0;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

void report(benchmark::State& state, std::size_t pairs, std::size_t m) {
  state.counters["pairs"] = double(pairs);
  state.counters["ns_per_box"] =
      benchmark::Counter(double(m) * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_tree(benchmark::State& state) {
  const auto polygons = scenery(std::size_t(state.range(0)));
  const auto index = ccd::StaticIndex::from_polygons(polygons);
  const auto q = moving(1000);
  std::vector<ccd::StaticPair> out;
  for (auto _ : state) {
    index.find_pairs(q, out);
    benchmark::DoNotOptimize(out.data());
  }
  report(state, out.size(), q.size());
}

void BM_grid(benchmark::State& state) {
  const auto polygons = scenery(std::size_t(state.range(0)));
  const UniformGrid grid(boxes_of(polygons));
  const auto q = moving(1000);
  std::vector<ccd::StaticPair> out;
  for (auto _ : state) {
    grid.find_pairs(q, out);
    benchmark::DoNotOptimize(out.data());
  }
  report(state, out.size(), q.size());
}

void BM_brute(benchmark::State& state) {
  const auto boxes = boxes_of(scenery(std::size_t(state.range(0))));
  const auto q = moving(1000);
  std::vector<ccd::StaticPair> out;
  for (auto _ : state) {
    out.clear();
    for (std::uint32_t b = 0; b < q.size(); ++b)
      for (std::uint32_t p = 0; p < boxes.size(); ++p)
        if (q[b].overlaps(boxes[p])) out.push_back({b, p});
    benchmark::DoNotOptimize(out.data());
  }
  report(state, out.size(), q.size());
}

void BM_tree_build(benchmark::State& state) {
  const auto polygons = scenery(std::size_t(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(ccd::StaticIndex::from_polygons(polygons).size());
}

void BM_grid_build(benchmark::State& state) {
  const auto boxes = boxes_of(scenery(std::size_t(state.range(0))));
  for (auto _ : state) {
    const UniformGrid g(boxes);
    benchmark::DoNotOptimize(&g);
  }
}

}  // namespace

BENCHMARK(BM_tree)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_grid)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_brute)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_tree_build)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_grid_build)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
