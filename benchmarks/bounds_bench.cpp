// Tightness and speed of the space-time bounds (bounds/registry.hpp).
// For each bound and step length h: a gas of 3150 spheres (radii 0.1-0.25,
// jittered grid, no overlap at t0) in a walled box [0, 10]^3, with
// gravity and accelerations |a| <= 50 that change 3 times per step, speeds up to 10 (80%) or 40.
// Candidate pairs = all pairs whose bound boxes overlap (brute force). Counters:
//   fp_rate   = pairs passing the bound's own test without contact in the step / passing
//               (contact by dense sampling of the exact trajectories, 1025 times per step)
//   passing, contacts, candidates; the time is per pair test (items = pair tests).
// Run: ./build/bounds_bench --benchmark_counters_tabular=true
#include <bounds/registry.hpp>

#include <benchmark/benchmark.h>

#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

struct Setup {
  ccd::Scene scene;
  ccd::Trajectories traj;
  std::vector<ccd::BodyState> start;
};

const Setup& gas(double h) {
  static std::map<double, Setup> cache;
  auto it = cache.find(h);
  if (it != cache.end()) return it->second;
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g;
  const auto rvec = [&](double len) -> ccd::Vec3 {  // explicit type: no dangling Eigen expression
    ccd::Vec3 x(g(rng), g(rng), g(rng));
    return x.normalized() * (len * u(rng));
  };
  Setup s;
  s.scene.horizon = h;
  s.scene.box = ccd::WallBox{ccd::Vec3::Zero(), ccd::Vec3::Constant(10)};
  s.scene.gravity = ccd::Vec3(0, -9.81, 0);
  // Jittered 15 x 15 x 14 grid (spacing 2/3): no overlaps at t0, contacts come from motion.
  for (int i = 0; i < 3150; ++i) {
    ccd::Body b;
    b.radius = 0.1 + 0.15 * u(rng);
    const ccd::Vec3 cell(i % 15, (i / 15) % 15, i / 225);
    b.position = (cell + ccd::Vec3::Constant(0.5)) * (10.0 / 15) + rvec(0.08);
    b.velocity = rvec(u(rng) < 0.8 ? 10.0 : 40.0);
    b.acceleration = rvec(40.0);
    for (int c = 1; c <= 3; ++c) b.acceleration_changes.push_back({h * c / 4, rvec(40.0)});
    s.scene.bodies.push_back(b);
  }
  s.traj = ccd::Trajectories(s.scene);
  for (std::size_t i = 0; i < s.scene.bodies.size(); ++i)
    s.start.push_back({s.traj.position(i, 0.0), s.traj.velocity(i, 0.0), s.traj.radius(i)});
  return cache.emplace(h, std::move(s)).first->second;
}

bool sampled_contact(const Setup& s, std::uint32_t a, std::uint32_t b, double h) {
  const double R = s.traj.radius(a) + s.traj.radius(b);
  for (int k = 0; k <= 1024; ++k) {
    const double t = h * k / 1024;
    if ((s.traj.position(a, t) - s.traj.position(b, t)).squaredNorm() <= R * R) return true;
  }
  return false;
}

void bm_bound(benchmark::State& state, std::string spec, double h) {
  const Setup& s = gas(h);
  const ccd::BoundSpec bs = ccd::parse_bound(spec);
  auto bound = bs.make();
  ccd::StepContext ctx;
  ctx.t0 = 0.0;
  ctx.t1 = h;
  ctx.start = s.start;
  ctx.exact = bs.info->knowledge == ccd::Knowledge::Exact ? &s.traj : nullptr;
  ctx.acceleration_bound = s.scene.max_acceleration();
  ctx.walls = s.scene.box;
  const ccd::RigidMotion motion(s.scene, s.traj);
  ctx.motion = &motion;
  std::vector<ccd::Aabb> boxes;
  bound->prepare(ctx, boxes);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> cand;
  for (std::uint32_t a = 0; a < boxes.size(); ++a)
    for (std::uint32_t b = a + 1; b < boxes.size(); ++b)
      if (boxes[a].overlaps(boxes[b])) cand.emplace_back(a, b);
  long passing = 0, contacts = 0;
  for (const auto& [a, b] : cand) {
    if (!bound->test(a, b).possible()) continue;
    ++passing;
    contacts += sampled_contact(s, a, b, h);
  }
  long accepted = 0;
  for (auto _ : state) {
    for (const auto& [a, b] : cand) accepted += bound->test(a, b).possible();
    benchmark::DoNotOptimize(accepted);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * cand.size()));
  state.counters["candidates"] = static_cast<double>(cand.size());
  state.counters["passing"] = static_cast<double>(passing);
  state.counters["contacts"] = static_cast<double>(contacts);
  state.counters["fp_rate"] = passing ? static_cast<double>(passing - contacts) / passing : 0.0;
  state.counters["ns_per_test"] =
      benchmark::Counter(static_cast<double>(state.iterations() * cand.size()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

int register_all() {
  const char* specs[] = {"swept_aabb", "capsule", "enclosing_sphere", "horn:1", "horn:4", "horn:16",
                         "horn_sat:1", "horn_sat:4"};
  const std::pair<const char*, double> steps[] = {{"1/240", 1.0 / 240}, {"1/60", 1.0 / 60}, {"1/15", 1.0 / 15}};
  for (const char* spec : specs)
    for (const auto& [name, h] : steps)
      benchmark::RegisterBenchmark((std::string(spec) + "/h=" + name).c_str(), bm_bound, std::string(spec), h);
  return 0;
}
const int registered = register_all();

}  // namespace

BENCHMARK_MAIN();
