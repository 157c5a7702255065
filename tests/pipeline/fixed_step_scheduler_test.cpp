// FixedStepScheduler (pipeline/fixed_step_scheduler.hpp): fixed steps over a horizon as a
// library call. Its counts and contacts are those of a plain loop of StepPipeline::run over
// the steps k dt, and those the runner records for the same method; discrete methods check
// the samples k dt <= T, continuous ones the steps that start before T; a contact sink gets
// the contacts a run without one keeps; a cancelled run stops at its first step.
#include <ccd/motion/state_cursor.hpp>
#include <pipeline/fixed_step_scheduler.hpp>
#include <pipeline/scheduler_registry.hpp>
#include <ccd/truth/ground_truth.hpp>
#include <generators/registry.hpp>
#include <experiments/method.hpp>
#include <experiments/runner.hpp>

#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <string>
#include <vector>

namespace {

struct Small {
  ccd::Scene scene = ccdlab::generate_scene(
      "gas", {{"bodies", 120}, {"seed", 5}, {"speed_max", 30}, {"horizon", 0.5}});
  ccd::Trajectories traj{scene};
  ccd::RigidMotion motion{scene, traj};
};

ccd::ScheduleInput input_of(const Small& s) {
  ccd::ScheduleInput in;
  in.motion = &s.motion;
  in.horizon = s.scene.horizon;
  in.acceleration_bound = s.scene.max_acceleration();
  in.walls = s.scene.box;
  in.timed = false;
  return in;
}

ccd::ScheduleResult run_fixed(const Small& s, const std::string& method, const std::string& schedule, double dt) {
  const ccdlab::MethodSpec m = ccdlab::parse_method(method);
  const auto scheduler = ccd::parse_scheduler(schedule).make({&m.bound, &m.broad_phase, dt});
  ccd::ScheduleResult out;
  REQUIRE(scheduler->run(input_of(s), out));
  return out;
}

// The reference: StepPipeline::run over every step, counted by hand.
struct LoopCounts {
  std::uint64_t steps = 0, candidates = 0, passed = 0, contacts = 0;
  std::vector<ccd::ScheduledContact> found;
};

LoopCounts plain_loop(const Small& s, const std::string& method, double dt) {
  const ccdlab::MethodSpec m = ccdlab::parse_method(method);
  ccd::StepPipeline pipeline(m.bound.make(), m.bound.info->knowledge, m.broad_phase.make());
  const bool continuous = m.continuous();
  ccd::StateCursor cursor(s.traj);
  std::vector<ccd::BodyState> states;
  ccd::StepResult step;
  ccd::StepContext ctx;
  ctx.acceleration_bound = s.scene.max_acceleration();
  ctx.walls = s.scene.box;
  ctx.exact = m.bound.info->knowledge == ccd::Knowledge::Exact ? &s.traj : nullptr;
  ctx.motion = &s.motion;
  LoopCounts c;
  const double T = s.scene.horizon;
  for (std::uint64_t k = 0; continuous ? double(k) * dt < T : double(k) * dt <= T; ++k) {
    ctx.t0 = double(k) * dt;
    ctx.t1 = continuous ? std::min(double(k + 1) * dt, T) : ctx.t0;
    cursor.evaluate(ctx.t0, states);
    ctx.start = states;
    pipeline.run(ctx, step, nullptr, cursor.pieces());
    ++c.steps;
    c.candidates += step.bodies.candidates.size();
    c.passed += step.bodies.passed.size();
    c.contacts += step.bodies.contacts.size();
    for (const ccd::PairContact& pc : step.bodies.contacts) c.found.push_back({pc.pair, pc.contact, ctx.t0, ctx.t1});
  }
  return c;
}

class Collect final : public ccd::ContactSink {
 public:
  std::vector<ccd::ScheduledContact> contacts;
  int calls = 0;
  void found(std::span<const ccd::ScheduledContact> c, std::span<const ccd::ScheduledStaticContact>) override {
    ++calls;
    contacts.insert(contacts.end(), c.begin(), c.end());
  }
};

}  // namespace

TEST_CASE("fixed steps through the library count what a loop of step pipelines counts",
          "[pipeline][scheduler][fixed]") {
  const Small s;
  for (const char* method : {"capsule/grid", "horn:4/sap", "aabb/grid", "enclosing_sphere/brute"}) {
    for (const double dt : {0.05, 0.3}) {  // 0.3 does not divide the horizon
      INFO(method << " dt " << dt);
      const ccd::ScheduleResult r = run_fixed(s, method, "fixed", dt);
      const LoopCounts loop = plain_loop(s, method, dt);
      const bool continuous = std::string(method).rfind("aabb/", 0) != 0;
      CHECK(r.stats.batches == loop.steps);
      CHECK(r.stats.batches == ccd::fixed_step_count(s.scene.horizon, dt, continuous));
      CHECK(r.stats.bodies.candidates == loop.candidates);
      CHECK(r.stats.bodies.checks == loop.candidates);
      CHECK(r.stats.bodies.passed == loop.passed);
      CHECK(r.stats.bodies.narrow_calls == loop.passed);
      CHECK(r.stats.refreshes == loop.steps * s.traj.size());
      REQUIRE(r.contacts.size() == loop.contacts);
      for (std::size_t i = 0; i < r.contacts.size(); ++i) {
        CHECK(r.contacts[i].pair == loop.found[i].pair);
        CHECK(r.contacts[i].contact.toi == loop.found[i].contact.toi);
        CHECK(r.contacts[i].from == loop.found[i].from);
        CHECK(r.contacts[i].to == loop.found[i].to);
        if (!continuous) CHECK(r.contacts[i].from == r.contacts[i].to);  // a sample
      }
      // The broad phase's own counters, summed over steps (sap counts its swaps).
      if (std::string(method).find("/sap") != std::string::npos) CHECK(r.stats.counters.count("swaps") == 1);
      else CHECK(r.stats.counters.empty());
    }
  }
}

TEST_CASE("fixed steps through the library give the counts of the runner's records",
          "[pipeline][scheduler][fixed][runner]") {
  const Small s;
  const ccdlab::TruthIndex truth(ccd::compute_truth(s.traj));
  REQUIRE(truth.events().size() > 5);
  ccdlab::RunInput in;
  in.scene = &s.scene;
  const ccd::RigidMotion scene_motion(s.scene, s.traj);
  in.motion = &scene_motion;
  in.truth = &truth;
  in.acceleration_bound = s.scene.max_acceleration();
  for (const char* method : {"capsule/grid", "horn:4/sap", "aabb/grid", "swept_aabb/grid@fixed:narrow_from_earliest=1"}) {
    for (const double dt : {0.05, 0.3}) {
      INFO(method << " dt " << dt);
      const ccdlab::MethodSpec m = ccdlab::parse_method(method);
      const ccdlab::RunRecord rec = ccdlab::run_method(in, m, dt);
      const std::string name(method);
      const std::size_t at = name.find('@');
      const ccd::ScheduleResult r =
          run_fixed(s, name.substr(0, at), at == std::string::npos ? "fixed" : name.substr(at + 1), dt);
      CHECK(rec.steps == r.stats.batches);
      CHECK(rec.bodies.candidates == r.stats.bodies.candidates);
      CHECK(rec.bodies.passed == r.stats.bodies.passed);
      CHECK(rec.bodies.confirmed == r.contacts.size());
      CHECK(rec.false_positives == r.stats.bodies.passed - r.contacts.size());
      CHECK(rec.rebuilds == r.stats.rebuilds);
      REQUIRE(rec.counters.size() == r.stats.counters.size());
      for (const auto& [name_, value] : rec.counters) CHECK(r.stats.counters.at(name_) == value);
      CHECK(rec.bodies.detected + rec.bodies.missed + rec.bodies.initial_contacts == truth.events().size());
      if (rec.conservative) CHECK(rec.bodies.missed == 0);
    }
  }
}

TEST_CASE("a contact sink gets each step's contacts, the result keeps none", "[pipeline][scheduler][fixed]") {
  const Small s;
  const ccd::BoundSpec bound = ccd::parse_bound("capsule");
  const ccd::BroadPhaseSpec broad = ccd::parse_broad_phase("grid");
  const ccd::ScheduleResult plain = run_fixed(s, "capsule/grid", "fixed", 0.05);
  REQUIRE(!plain.contacts.empty());
  Collect sink;
  ccd::ScheduleInput in = input_of(s);
  in.sink = &sink;
  ccd::ScheduleResult out;
  REQUIRE(ccd::parse_scheduler("fixed").make({&bound, &broad, 0.05})->run(in, out));
  CHECK(out.contacts.empty());
  REQUIRE(sink.contacts.size() == plain.contacts.size());
  for (std::size_t i = 0; i < plain.contacts.size(); ++i) {
    CHECK(sink.contacts[i].pair == plain.contacts[i].pair);
    CHECK(sink.contacts[i].from == plain.contacts[i].from);
  }
  CHECK(sink.calls > 1);  // per step, not once at the end
  CHECK(std::uint64_t(sink.calls) <= out.stats.batches);
  Collect earliest_sink;
  in.sink = &earliest_sink;
  REQUIRE(ccd::parse_scheduler("earliest").make({&bound, &broad, 0.05})->run(in, out));
  CHECK(out.contacts.empty());
  CHECK(earliest_sink.calls == 1);  // all at the end
  CHECK_FALSE(earliest_sink.contacts.empty());
}

TEST_CASE("a cancelled fixed-step run stops before its first step", "[pipeline][scheduler][fixed]") {
  const Small s;
  const ccd::BoundSpec bound = ccd::parse_bound("capsule");
  const ccd::BroadPhaseSpec broad = ccd::parse_broad_phase("grid");
  const std::atomic<bool> cancel{true};
  ccd::ScheduleInput in = input_of(s);
  in.cancel = &cancel;
  ccd::ScheduleResult out;
  CHECK_FALSE(ccd::parse_scheduler("fixed").make({&bound, &broad, 0.05})->run(in, out));
  CHECK_FALSE(out.finished);
  CHECK(out.stats.batches == 0);
}

TEST_CASE("fixed_step_count: samples for discrete methods, steps starting before T for continuous ones",
          "[pipeline][scheduler][fixed]") {
  CHECK(ccd::fixed_step_count(1.0, 0.1, false) == 11);  // t = 0, 0.1, ..., 1.0
  CHECK(ccd::fixed_step_count(1.0, 0.1, true) == 10);   // 10 * 0.1 == 1.0: no empty last step
  CHECK(ccd::fixed_step_count(0.7, 0.1, true) == 7);    // 6 * 0.1 < 0.7 < 7 * 0.1
  CHECK(ccd::fixed_step_count(0.5, 0.3, true) == 2);    // [0, 0.3], [0.3, 0.5]
  CHECK(ccd::fixed_step_count(0.5, 0.3, false) == 2);   // 0, 0.3
  CHECK(ccd::fixed_step_count(1.0, 0.0, true) == 0);
}
