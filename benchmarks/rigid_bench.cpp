// Timing of the rigid-body kernels (docs/rigid_bodies.md):
//  - gjk_box_pair: convex_distance of two boxes (half extents 0.5 x 0.3 x 0.2) in 4,096
//    pre-generated random poses (fixed seed; centres 0.5 to 2 apart, about a quarter
//    overlapping), one pass per iteration; ns_per_query is the time per call;
//  - ca_spinning_stick: conservative advancement over [0, 1] for 256 pairs of a stick
//    (half length 1, radius 0.05) spinning at 4 to 32 rad/s about a random axis with zero
//    translation and a ball of radius 0.1 resting at 0.25 to 1.5 from its centre;
//    us_per_pair is the time per pair;
//  - rigid_truth_crates: the certified truth of 2,000 crates spinning and bouncing in a box
//    over 2 s (the `crates` scene below), one thread; reports events and grazing.
//   ./build/rigid_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/narrow/conservative_advancement.hpp>
#include <ccd/queries/convex_distance.hpp>
#include <ccd/truth/truth.hpp>

#include <Eigen/Geometry>
#include <benchmark/benchmark.h>
#include <cmath>
#include <random>
#include <vector>

namespace {

using ccd::Vec3;

Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> N(0.0, 1.0);
  return Eigen::Quaterniond(N(rng), N(rng), N(rng), N(rng)).normalized().toRotationMatrix();
}

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> N(0.0, 1.0);
  Vec3 v(N(rng), N(rng), N(rng));
  return v / v.norm();
}

void gjk_box_pair(benchmark::State& state) {
  const ccd::Shape box = ccd::make_box_shape(Vec3(0.5, 0.3, 0.2));
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> U(0.5, 2.0);
  std::vector<std::pair<ccd::ProxyPose, ccd::ProxyPose>> poses;
  for (int i = 0; i < 4096; ++i)
    poses.push_back({{Vec3::Zero(), random_rotation(rng)}, {U(rng) * random_unit(rng), random_rotation(rng)}});
  std::size_t overlapping = 0;
  for (auto _ : state)
    for (const auto& [pa, pb] : poses) {
      const ccd::ConvexDistance d = ccd::convex_distance(box.proxy(), pa, box.proxy(), pb);
      overlapping += d.status == ccd::ConvexDistance::Status::Overlapping;
      benchmark::DoNotOptimize(d);
    }
  state.counters["ns_per_query"] =
      benchmark::Counter(static_cast<double>(state.iterations() * poses.size()) * 1e-9,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["overlapping_fraction"] =
      static_cast<double>(overlapping) / static_cast<double>(state.iterations() * poses.size());
}
BENCHMARK(gjk_box_pair)->Unit(benchmark::kMicrosecond);

void ca_spinning_stick(benchmark::State& state) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  ccd::Scene s;
  s.horizon = 1.0;
  s.shapes.push_back(ccd::make_capsule_shape(1.0, 0.05, "stick"));
  for (int i = 0; i < 256; ++i) {
    const Vec3 c(8.0 * i, 0, 0);
    ccd::Body stick;
    stick.position = c;
    ccd::RigidBody r;
    r.shape = 0;
    r.angular_velocity = (4.0 + 28.0 * U(rng)) * random_unit(rng);
    s.add_rigid_body(stick, r);
    ccd::Body ball;
    ball.radius = 0.1;
    ball.position = c + (0.25 + 1.25 * U(rng)) * random_unit(rng);
    s.add_rigid_body(ball, ccd::RigidBody{});
  }
  const ccd::Trajectories traj(s);
  const ccd::RigidMotion motion(s, traj);
  ccd::NarrowInput in;
  in.motion = &motion;
  in.t0 = 0.0;
  in.t1 = 1.0;
  std::size_t hits = 0;
  for (auto _ : state)
    for (std::uint32_t i = 0; i < 256; ++i) {
      const ccd::ContactResult r = ccd::conservative_advancement(in, 2 * i, 2 * i + 1);
      hits += r.found();
      benchmark::DoNotOptimize(r);
    }
  state.counters["us_per_pair"] = benchmark::Counter(static_cast<double>(state.iterations() * 256) * 1e-6,
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["hit_fraction"] = static_cast<double>(hits) / static_cast<double>(state.iterations() * 256);
}
BENCHMARK(ca_spinning_stick)->Unit(benchmark::kMicrosecond);

// 2,000 crates (half extents 0.5 x 0.3 x 0.2) in a 40 m box under gravity, speeds up to
// 4 m/s, spinning up to 6 rad/s about random axes.
ccd::Scene crates(std::size_t n) {
  std::mt19937_64 rng(2000);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  ccd::Scene s;
  s.horizon = 2.0;
  s.gravity = Vec3(0, -9.81, 0);
  s.box = ccd::WallBox{Vec3::Zero(), Vec3(40, 40, 40)};
  s.shapes.push_back(ccd::make_box_shape(Vec3(0.5, 0.3, 0.2), "crate"));
  for (std::size_t i = 0; i < n; ++i) {
    ccd::Body b;
    b.position = Vec3(1 + 38 * U(rng), 1 + 38 * U(rng), 1 + 38 * U(rng));
    b.velocity = 4.0 * U(rng) * random_unit(rng);
    ccd::RigidBody r;
    r.shape = 0;
    r.orientation = Eigen::Quaterniond(random_rotation(rng));
    r.angular_velocity = 6.0 * U(rng) * random_unit(rng);
    s.add_rigid_body(b, r);
  }
  return s;
}

void rigid_truth_crates(benchmark::State& state) {
  const ccd::Scene s = crates(2000);
  const ccd::Trajectories traj(s);
  const ccd::RigidMotion motion(s, traj);
  ccd::TruthOptions o;
  o.threads = 1;
  ccd::Truth r;
  for (auto _ : state) {
    r = ccd::compute_truth(motion, {}, o);
    benchmark::DoNotOptimize(r);
  }
  state.counters["events"] = static_cast<double>(r.events.size());
  state.counters["grazing"] = static_cast<double>(r.stats.grazing);
  state.counters["evaluations"] = static_cast<double>(r.stats.evaluations);
}
BENCHMARK(rigid_truth_crates)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
