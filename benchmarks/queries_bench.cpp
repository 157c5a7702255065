// Timing of the analytic queries. ray_sphere: 100,000 pre-generated random rays (fixed
// seed; about half hit, the rest miss, a few start inside), one pass over all of them per
// benchmark iteration. The counter ns_per_query is the time per call.
//   ./build/queries_bench --benchmark_repetitions=5
#include <ccd/queries/ray_sphere.hpp>

#include <benchmark/benchmark.h>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

struct RayCase {
  ccd::Vec3 origin, direction, centre;
  double radius, t_max;
};

std::vector<RayCase> make_cases(std::size_t n) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::normal_distribution<double> N(0.0, 1.0);
  auto unit = [&] {
    ccd::Vec3 v(N(rng), N(rng), N(rng));
    return ccd::Vec3(v / v.norm());
  };
  std::vector<RayCase> cases;
  cases.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    RayCase c;
    c.centre = 10.0 * ccd::Vec3(U(rng), U(rng), U(rng));
    c.radius = std::exp2(2.0 * U(rng));
    c.origin = c.centre + (0.9 * c.radius + 10.0 * (U(rng) + 1.0)) * unit();
    // Aimed at a point within 2 R of the centre: about half of the lines meet the sphere.
    const ccd::Vec3 aim = c.centre + 2.0 * c.radius * (0.5 * (U(rng) + 1.0)) * unit();
    c.direction = (aim - c.origin) * std::exp2(3.0 * U(rng));
    c.t_max = U(rng) < 0.0 ? std::numeric_limits<double>::infinity() : 2.0;
    cases.push_back(c);
  }
  return cases;
}

void BM_ray_sphere(benchmark::State& state) {
  const std::vector<RayCase> cases = make_cases(100000);
  for (auto _ : state) {
    for (const RayCase& c : cases) {
      auto r = ccd::ray_sphere(c.origin, c.direction, c.centre, c.radius, c.t_max);
      benchmark::DoNotOptimize(r);
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * cases.size()));
  state.counters["ns_per_query"] =
      benchmark::Counter(static_cast<double>(cases.size()),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  std::size_t hits = 0;
  for (const RayCase& c : cases) {
    hits += ccd::ray_sphere(c.origin, c.direction, c.centre, c.radius, c.t_max).status ==
            ccd::RaySphereStatus::Hit;
  }
  state.counters["hit_fraction"] = static_cast<double>(hits) / static_cast<double>(cases.size());
}
BENCHMARK(BM_ray_sphere)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
