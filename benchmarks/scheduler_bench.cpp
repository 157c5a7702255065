// The earliest-contact scheduler (pipeline/earliest_scheduler.hpp) against fixed steps
// of the same bounds (pipeline/step_pipeline.hpp), over a whole horizon of 1 s, on two
// scenes of the scheduling study (docs/studies.md), built here with a fixed seed. Both are
// built by the scheduler registry's factory from their spec (pipeline/scheduler_registry.hpp)
// and run over the horizon through the Scheduler interface:
//  - sparse_gas: 2,000 spheres of radius 1 at volume fraction 0.002 in a walled cube,
//    velocities uniform in the ball of radius 20;
//  - bullets: 950 spheres of radius 1 at volume fraction 0.05 moving at up to 1, and 50
//    bullets of radius 1/20 at 200.
// Each benchmark is one run over the horizon; its time is the thread's CPU time per run
// (manual time: robust to other jobs on a shared machine), the counter wall_ms the wall
// time. Counters: pair_checks (bound pair tests; for fixed steps the broad phase's
// candidates, each tested), narrow_calls (for fixed steps the pairs that passed),
// refreshes (bounds built; bodies x steps for fixed steps), contacts.
//
//   scheduler_bench [benchmark flags]   e.g. --benchmark_repetitions=9 --benchmark_report_aggregates_only=true
#include <bounds/registry.hpp>
#include <ccd/broad_phase/registry.hpp>
#include <pipeline/scheduler.hpp>
#include <pipeline/scheduler_registry.hpp>
#include <ccd/util/thread_cpu_time.hpp>

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace {

// n spheres of radius 1 at volume fraction `fraction` (of the n - bullets field bodies) in a
// walled cube around the origin, velocities uniform in the ball of radius `speed`; the
// first `bullets` of radius 1/20 at `bullet_speed`.
ccd::Scene make_scene(int n, double fraction, double speed, int bullets, double bullet_speed) {
  ccd::Scene s;
  s.horizon = 1.0;
  const double volume = (n - bullets) * 4.0 / 3.0 * std::numbers::pi / fraction;
  const double half = 0.5 * std::cbrt(volume);
  s.box = ccd::WallBox{ccd::Vec3::Constant(-half), ccd::Vec3::Constant(half)};
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto in_ball = [&] {
    ccd::Vec3 v;
    do v = ccd::Vec3(u(rng), u(rng), u(rng));
    while (v.squaredNorm() > 1.0);
    return v;
  };
  for (int i = 0; i < n; ++i) {
    ccd::Body b;
    b.radius = i < bullets ? 0.05 : 1.0;
    b.position = (half - b.radius) * ccd::Vec3(u(rng), u(rng), u(rng));
    b.velocity = i < bullets ? bullet_speed * in_ball().normalized() : speed * in_ball();
    s.bodies.push_back(b);
  }
  return s;
}

struct Fixture {
  ccd::Scene scene;
  ccd::Trajectories centres;
  ccd::RigidMotion motion;
  explicit Fixture(ccd::Scene s) : scene(std::move(s)), centres(scene), motion(scene, centres) {}
};

const Fixture& sparse_gas() {
  static const Fixture f(make_scene(2000, 0.002, 20.0, 0, 0.0));
  return f;
}
const Fixture& bullets() {
  static const Fixture f(make_scene(1000, 0.05, 1.0, 50, 200.0));
  return f;
}

struct Costs {
  double pair_checks = 0, narrow_calls = 0, refreshes = 0, contacts = 0;
};

void report(benchmark::State& state, double cpu, double wall, const Costs& c) {
  state.SetIterationTime(cpu);
  state.counters["wall_ms"] = wall * 1e3;
  state.counters["pair_checks"] = c.pair_checks;
  state.counters["narrow_calls"] = c.narrow_calls;
  state.counters["refreshes"] = c.refreshes;
  state.counters["contacts"] = c.contacts;
}

// The parts of a method, each named as its registry reads it.
struct Method {
  const char* bound;     ///< "capsule" (bounds/registry.hpp)
  const char* broad;     ///< "grid" (ccd/broad_phase/registry.hpp)
  const char* schedule;  ///< "fixed", "earliest:stale=1", ... (pipeline/scheduler_registry.hpp)
};

// One run of the scheduler of `method` over the horizon, windows or steps of dt.
void run(benchmark::State& state, const Fixture& (*scene)(), Method method, double dt) {
  const Fixture& f = scene();
  const ccd::BoundSpec bound = ccd::parse_bound(method.bound);
  const ccd::BroadPhaseSpec broad = ccd::parse_broad_phase(method.broad);
  const ccd::SchedulerSpec spec = ccd::parse_scheduler(method.schedule);
  ccd::ScheduleInput in;
  in.motion = &f.motion;
  in.horizon = f.scene.horizon;
  in.acceleration_bound = f.scene.max_acceleration();
  in.walls = f.scene.box;
  in.timed = false;
  ccd::ScheduleResult result;
  for (auto _ : state) {
    const std::unique_ptr<ccd::Scheduler> scheduler = spec.make({&bound, &broad, dt});
    const auto wall0 = std::chrono::steady_clock::now();
    const double cpu0 = ccd::thread_cpu_seconds();
    scheduler->run(in, result);
    const double cpu = ccd::thread_cpu_seconds() - cpu0;
    const ccd::ScheduleStats& st = result.stats;
    report(state, cpu, std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count(),
           {double(st.bodies.checks), double(st.bodies.narrow_calls), double(st.refreshes), double(result.contacts.size())});
  }
}

void register_all() {
  const auto add = [](const char* name, const Fixture& (*scene)(), Method method, double dt) {
    benchmark::RegisterBenchmark(name, run, scene, method, dt)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  };
  // Sparse gas: the fixed methods' best dt is the horizon (one bound per body).
  add("sparse_gas/fixed/swept_aabb/grid/dt=1", sparse_gas, {"swept_aabb", "grid", "fixed"}, 1.0);
  add("sparse_gas/fixed/capsule/grid/dt=1", sparse_gas, {"capsule", "grid", "fixed"}, 1.0);
  add("sparse_gas/earliest/capsule/grid/dt=1", sparse_gas, {"capsule", "grid", "earliest"}, 1.0);
  add("sparse_gas/earliest:recheck=1/capsule/grid/dt=1", sparse_gas,
      {"capsule", "grid", "earliest:recheck=1"}, 1.0);
  add("sparse_gas/earliest:recheck=1,chunk=0/capsule/grid/dt=1", sparse_gas,
      {"capsule", "grid", "earliest:recheck=1,chunk=0"}, 1.0);
  add("sparse_gas/earliest:stale=1/capsule/grid/dt=1", sparse_gas, {"capsule", "grid", "earliest:stale=1"},
      1.0);
  add("sparse_gas/earliest:stale=1/swept_aabb/grid/dt=1", sparse_gas,
      {"swept_aabb", "grid", "earliest:stale=1"}, 1.0);
  // Bullets: fixed steps need a dt small enough for the bullets.
  add("bullets/fixed/capsule/grid/dt=0.03", bullets, {"capsule", "grid", "fixed"}, 0.03);
  add("bullets/fixed/capsule/grid/dt=0.01", bullets, {"capsule", "grid", "fixed"}, 0.01);
  add("bullets/earliest:reach=16/capsule/grid/dt=1", bullets, {"capsule", "grid", "earliest:reach=16"}, 1.0);
  add("bullets/earliest:reach=16,recheck=1/capsule/grid/dt=1", bullets,
      {"capsule", "grid", "earliest:reach=16,recheck=1"}, 1.0);
  add("bullets/earliest:reach=16,recheck=1,chunk=0/capsule/grid/dt=1", bullets,
      {"capsule", "grid", "earliest:reach=16,recheck=1,chunk=0"}, 1.0);
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
