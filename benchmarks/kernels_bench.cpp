// Cost of ccdlab's kernels.
//
// sphere_contact_linear: the exact first-contact query of two spheres under linear motion
// (ccd/queries/sphere_sphere_contact.hpp, quadratic case), ns per pair over 100,000 random
// pairs (seed 11): centres in [0, 10]^3, velocities in [-10, 10]^3, radii in [0.5, 1.5],
// one time unit. Counter: contacts (pairs with a contact in [0, 1]).
//
// sphere_contact_linear_batch: the same pairs through the batched exact query
// (ccd/queries/sphere_sphere_batch.hpp: structure of arrays, SIMD filter, the scalar exact
// query on the undecided pairs; identical answers), ns per pair.
//
// narrow/sphere_sphere/{scalar,batch}/100000: the exact narrow phase alone on the pairs that
// pass the capsule bound in one step of the 100,000-body peer scene (below): pair by pair
// through ccd::sphere_sphere_narrow, and through ccd::sphere_sphere_narrow_batch (the
// pipeline's). Counter: confirmed (contacts), s/pair.
//
// pipeline/continuous/BOUND and pipeline/discrete/aabb: one step (dt = 1/60) of the shared 100,000-body
// peer scene (benchmarks/support/peer_scene.hpp: its positions, velocities and radii, linear
// motion, no walls during the step), through the step pipeline the runner calls
// (pipeline/step_pipeline.hpp). A continuous pipeline is a space-time bound (capsule,
// swept_aabb: exact knowledge; horn:1 with A = 0, the true bound) + `grid` + the bound's
// pair test + the exact first contact on the survivors; the discrete one is the `aabb`
// bound at the step's start + `grid` + the bound's test + the narrow phase's sample test
// (ccd::in_contact, the ground truth's definition of touching). Counters: candidates
// (broad-phase pairs), passed (after the bound's test), confirmed (contacts). The
// continuous pipelines run the batched narrow phase; .../scalar runs the same pipeline
// with the sphere x sphere entry called pair by pair (a table whose entry wraps it).
#include <bounds/registry.hpp>
#include <ccd/broad_phase/grid.hpp>
#include <benchmarks/support/peer_scene.hpp>
#include <ccd/motion/state_cursor.hpp>
#include <ccd/motion/trajectory.hpp>
#include <pipeline/step_pipeline.hpp>
#include <ccd/queries/ray_sphere.hpp>
#include <ccd/narrow/sphere_sphere_narrow.hpp>
#include <ccd/narrow/sphere_sphere_narrow_batch.hpp>
#include <ccd/queries/sphere_sphere_batch.hpp>
#include <ccd/queries/sphere_sphere_contact.hpp>
#include <ccd/scene/scene.hpp>

#include <benchmark/benchmark.h>

#include <memory>
#include <utility>
#include <random>
#include <vector>

namespace {

// 100,000 random pairs (seed 11), the same for both contact benchmarks.
const std::pair<std::vector<ccd::MovingSphere>, std::vector<ccd::MovingSphere>>& random_pairs(std::size_t n) {
  static const auto pairs = [n] {
    std::mt19937_64 gen(11);
    std::uniform_real_distribution<double> pos(0, 10), vel(-10, 10), rad(0.5, 1.5);
    std::vector<ccd::MovingSphere> a(n), b(n);
    for (std::size_t i = 0; i < n; ++i) {
      for (ccd::MovingSphere* s : {&a[i], &b[i]}) {
        s->position = ccd::Vec3(pos(gen), pos(gen), pos(gen));
        s->velocity = ccd::Vec3(vel(gen), vel(gen), vel(gen));
        s->radius = rad(gen);
      }
    }
    return std::make_pair(std::move(a), std::move(b));
  }();
  return pairs;
}

// Times `query(a, b)` (returns {contact?, toi}) over the 100,000 random pairs.
template <class Query>
void time_contact_query(benchmark::State& state, Query query) {
  constexpr std::size_t n = 100000;
  const auto& [a, b] = random_pairs(n);
  std::size_t contacts = 0;
  for (auto _ : state) {
    contacts = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const auto [hit, toi] = query(a[i], b[i]);
      contacts += hit;
      benchmark::DoNotOptimize(toi);
    }
  }
  state.counters["contacts"] = static_cast<double>(contacts);
  // Seconds per pair, printed with an SI prefix (e.g. "34.4n" = 34.4 ns).
  state.counters["s/pair"] = benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate |
                                                                            benchmark::Counter::kInvert);
}

void sphere_contact_linear(benchmark::State& state) {
  time_contact_query(state, [](const ccd::MovingSphere& a, const ccd::MovingSphere& b) {
    const ccd::SphereSphereContact c = ccd::sphere_sphere_first_contact(a, b, 1.0);
    return std::pair{c.status != ccd::ContactStatus::Miss, c.toi};
  });
}

// The same pairs through ccd/queries/ray_sphere.hpp (relative motion: a ray from the
// relative centre against a sphere of radius r_a + r_b at the origin), the leaner query.
void sphere_contact_linear_ray(benchmark::State& state) {
  time_contact_query(state, [](const ccd::MovingSphere& a, const ccd::MovingSphere& b) {
    const ccd::RaySphereResult c =
        ccd::ray_sphere(b.position - a.position, b.velocity - a.velocity, ccd::Vec3::Zero(), a.radius + b.radius, 1.0);
    return std::pair{c.status == ccd::RaySphereStatus::Hit || c.status == ccd::RaySphereStatus::Overlapping, c.toi};
  });
}

void sphere_contact_linear_batch(benchmark::State& state) {
  constexpr std::size_t n = 100000;
  const auto& [a, b] = random_pairs(n);
  ccd::LinearSpherePairs pairs;
  for (std::size_t i = 0; i < n; ++i) pairs.push_back(a[i], b[i]);
  std::vector<ccd::SphereSphereContact> out(n);
  std::size_t contacts = 0;
  for (auto _ : state) {
    ccd::sphere_sphere_first_contact_batch(pairs, 1.0, out);
    benchmark::DoNotOptimize(out.data());
  }
  for (const ccd::SphereSphereContact& c : out) contacts += c.status != ccd::ContactStatus::Miss;
  state.counters["contacts"] = static_cast<double>(contacts);
  state.counters["s/pair"] = benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate |
                                                                            benchmark::Counter::kInvert);
}

struct PipelineScene {
  ccd::Scene scene;
  ccd::Trajectories traj;
  std::vector<ccd::BodyState> start;  // at t = 0, from the state cursor, as the runner does
  std::vector<std::size_t> piece;     // each body's piece at t = 0
};

const PipelineScene& pipeline_scene() {
  static const PipelineScene s = [] {
    PipelineScene p;
    const ccdlab::bench::PeerScene peer(100000, 1);
    p.scene.horizon = ccdlab::bench::PeerScene::kDt;
    for (std::size_t i = 0; i < peer.size(); ++i) {
      ccd::Body body;
      body.radius = peer.radii()[i];
      body.position = ccd::Vec3(peer.centres(0)[i], peer.centres(1)[i], peer.centres(2)[i]);
      body.velocity = ccd::Vec3(peer.velocities(0)[i], peer.velocities(1)[i], peer.velocities(2)[i]);
      p.scene.bodies.push_back(body);
    }
    p.traj = ccd::Trajectories(p.scene);
    ccd::StateCursor cursor(p.traj);
    cursor.evaluate(0.0, p.start);
    p.piece.assign(cursor.pieces().begin(), cursor.pieces().end());
    return p;
  }();
  return s;
}

// The default narrow table with the sphere x sphere entry wrapped, so that the pipeline
// calls it pair by pair instead of through the batched form.
const ccd::NarrowTable& scalar_narrow_table() {
  static const ccd::NarrowTable table = [] {
    ccd::NarrowTable t = ccd::narrow_table();
    t.add(ccd::ShapeKind::Sphere, ccd::ShapeKind::Sphere,
          [](const ccd::NarrowInput& in, std::uint32_t a, std::uint32_t b) { return ccd::sphere_sphere_narrow(in, a, b); });
    return t;
  }();
  return table;
}

void pipeline(benchmark::State& state, const char* bound_name, bool scalar_narrow = false) {
  const PipelineScene& s = pipeline_scene();
  const ccd::BoundSpec spec = ccd::parse_bound(bound_name);
  const bool continuous = spec.info->knowledge != ccd::Knowledge::Instant;
  // reuse = 0: the benchmark repeats one step, which a Verlet list would serve from its list.
  ccd::StepPipeline step_pipeline(spec.make(), spec.info->knowledge,
                                  std::make_unique<ccd::UniformGrid>(ccd::GridOptions{.reuse = 0}),
                                  scalar_narrow ? scalar_narrow_table() : ccd::narrow_table());
  ccd::StepContext ctx;
  ctx.t0 = 0.0;
  ctx.t1 = continuous ? ccdlab::bench::PeerScene::kDt : 0.0;
  ctx.start = s.start;
  ctx.exact = spec.info->knowledge == ccd::Knowledge::Exact ? &s.traj : nullptr;
  ctx.acceleration_bound = 0.0;  // linear motion: the true bound
  const ccd::RigidMotion motion(s.scene, s.traj);
  ctx.motion = &motion;
  ccd::StepResult step;
  for (auto _ : state) step_pipeline.run(ctx, step, nullptr, s.piece);
  state.counters["candidates"] = static_cast<double>(step.bodies.candidates.size());
  state.counters["passed"] = static_cast<double>(step.bodies.passed.size());
  state.counters["confirmed"] = static_cast<double>(step.bodies.contacts.size());
}

// The narrow phase alone on the pairs that pass the capsule bound in one step.
void narrow(benchmark::State& state, bool batched) {
  const PipelineScene& s = pipeline_scene();
  const ccd::RigidMotion motion(s.scene, s.traj);
  static const std::vector<ccd::BodyPair> passed = [&s, &motion] {
    const ccd::BoundSpec spec = ccd::parse_bound("capsule");
    ccd::StepPipeline step_pipeline(spec.make(), spec.info->knowledge, std::make_unique<ccd::UniformGrid>());
    ccd::StepContext ctx;
    ctx.t1 = ccdlab::bench::PeerScene::kDt;
    ctx.start = s.start;
    ctx.exact = &s.traj;
    ctx.motion = &motion;
    ccd::StepResult step;
    step_pipeline.run(ctx, step, nullptr, s.piece);
    return step.bodies.passed;
  }();
  const ccd::NarrowInput in{&motion, s.start, s.piece, 0.0, ccdlab::bench::PeerScene::kDt, false};
  std::vector<ccd::ContactResult> out(passed.size());
  for (auto _ : state) {
    if (batched) {
      ccd::sphere_sphere_narrow_batch(in, passed, out);
    } else {
      for (std::size_t i = 0; i < passed.size(); ++i) out[i] = ccd::sphere_sphere_narrow(in, passed[i].a, passed[i].b);
    }
    benchmark::DoNotOptimize(out.data());
  }
  std::size_t confirmed = 0;
  for (const ccd::ContactResult& c : out) confirmed += c.found();
  state.counters["confirmed"] = static_cast<double>(confirmed);
  state.counters["s/pair"] = benchmark::Counter(static_cast<double>(passed.size()),
                                                benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK(sphere_contact_linear)->Unit(benchmark::kMillisecond);
BENCHMARK(sphere_contact_linear_ray)->Unit(benchmark::kMillisecond);
BENCHMARK(sphere_contact_linear_batch)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(narrow, scalar, false)->Name("narrow/sphere_sphere/scalar/100000")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(narrow, batch, true)->Name("narrow/sphere_sphere/batch/100000")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(pipeline, capsule, "capsule")->Name("pipeline/continuous/capsule/100000")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(pipeline, capsule_scalar, "capsule", true)
    ->Name("pipeline/continuous/capsule/100000/scalar")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(pipeline, swept_aabb, "swept_aabb")
    ->Name("pipeline/continuous/swept_aabb/100000")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(pipeline, horn1, "horn:1")->Name("pipeline/continuous/horn:1/100000")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(pipeline, discrete, "aabb")->Name("pipeline/discrete/aabb/100000")->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
