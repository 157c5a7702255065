#include <pipeline/scheduler_registry.hpp>

#include <pipeline/earliest_scheduler.hpp>
#include <pipeline/fixed_step_scheduler.hpp>
#include <generators/registry.hpp>

#include <catch2/catch.hpp>

#include <memory>
#include <stdexcept>
#include <string>

namespace pipeline_scheduler_registry_test {

namespace {

// The message of the std::invalid_argument `f` throws ("" when it throws none).
template <class F>
std::string refusal(F f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

bool mentions(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

struct Gas {
  ccd::Scene scene = ccdlab::generate_scene("gas", {{"bodies", 100}, {"seed", 7}, {"speed_max", 30}, {"horizon", 0.5}});
  ccd::Trajectories traj{scene};
  ccd::RigidMotion motion{scene, traj};
  ccd::ScheduleInput input() const {
    ccd::ScheduleInput in;
    in.motion = &motion;
    in.horizon = scene.horizon;
    in.acceleration_bound = scene.max_acceleration();
    in.walls = scene.box;
    in.timed = false;
    return in;
  }
};

ccd::ScheduleStats stats_of(ccd::Scheduler& s, const ccd::ScheduleInput& in) {
  ccd::ScheduleResult out;
  REQUIRE(s.run(in, out));
  return out.stats;
}

}  // namespace

TEST_CASE("parse_scheduler resolves names and options", "[pipeline][scheduler][registry]") {
  const ccd::SchedulerSpec fixed = ccd::parse_scheduler("fixed");
  CHECK_FALSE(fixed.earliest());
  CHECK(fixed.options.integer("narrow_from_earliest") == 0);
  CHECK(fixed.options.integer("kinematic") == 0);  // the kinematic principle is opt-in
  CHECK(ccd::parse_scheduler("fixed:kinematic=1").options.integer("kinematic") == 1);
  CHECK_THROWS_AS(ccd::parse_scheduler("fixed:kinematic=2"), std::invalid_argument);
  CHECK(ccd::default_scheduler().info == fixed.info);
  const ccd::SchedulerSpec e = ccd::parse_scheduler("earliest");
  CHECK(e.earliest());
  CHECK(e.options.number("stale") == 0.25);
  CHECK(e.options.integer("align") == 1);
  CHECK(ccd::parse_scheduler("earliest:0.5").options.number("stale") == 0.5);  // first option
  CHECK(ccd::parse_scheduler("earliest:stale=1,align=0").options.integer("align") == 0);
  CHECK(ccd::parse_scheduler("fixed:narrow_from_earliest=1").options.integer("narrow_from_earliest") == 1);
  CHECK(e.options.integer("recheck") == 0);  // speed re-checks are opt-in
  CHECK(e.options.number("chunk") == 2.0);
  const ccd::SchedulerSpec r = ccd::parse_scheduler("earliest:recheck=1,chunk=0");
  CHECK(r.options.integer("recheck") == 1);
  CHECK(r.options.number("chunk") == 0.0);
  SECTION("bad names and values name the part and list the valid ones") {
    try {
      ccd::parse_scheduler("hubbard");
      FAIL("accepted");
    } catch (const std::invalid_argument& err) {
      CHECK(std::string(err.what()).find("valid schedulers: fixed, earliest") != std::string::npos);
    }
    CHECK_THROWS_AS(ccd::parse_scheduler("earliest:stale=0"), std::invalid_argument);  // (0, 1]
    CHECK_THROWS_AS(ccd::parse_scheduler("earliest:stale=1.5"), std::invalid_argument);
    CHECK_THROWS_AS(ccd::parse_scheduler("earliest:align=2"), std::invalid_argument);
    CHECK_THROWS_AS(ccd::parse_scheduler("earliest:recheck=2"), std::invalid_argument);
    CHECK_THROWS_AS(ccd::parse_scheduler("earliest:chunk=-1"), std::invalid_argument);
    CHECK_THROWS_AS(ccd::parse_scheduler("fixed:stale=0.5"), std::invalid_argument);
  }
}

TEST_CASE("the registry's factory builds each scheduler with its options", "[pipeline][scheduler][registry]") {
  const Gas g;
  const ccd::BoundSpec capsule = ccd::parse_bound("capsule");
  const ccd::BroadPhaseSpec grid = ccd::parse_broad_phase("grid");
  for (const ccd::SchedulerInfo& info : ccd::scheduler_registry()) {
    INFO(info.name);
    const auto s = ccd::parse_scheduler(info.name).make({&capsule, &grid, 0.1});
    REQUIRE(s);
    if (info.name == "fixed") CHECK(dynamic_cast<ccd::FixedStepScheduler*>(s.get()) != nullptr);
    if (info.name == "earliest") CHECK(dynamic_cast<ccd::EarliestScheduler*>(s.get()) != nullptr);
  }
  SECTION("earliest: every option as the spec gives it, as a scheduler built with them directly") {
    for (const char* spec : {"earliest", "earliest:stale=1", "earliest:stale=0.05,align=0",
                             "earliest:reach=2,refresh_bodies=1", "earliest:recheck=1,chunk=0.5"}) {
      INFO(spec);
      const ccd::SchedulerSpec e = ccd::parse_scheduler(spec);
      ccd::ScheduleOptions o;
      o.window = 0.1;
      o.stale = e.options.number("stale");
      o.align = e.options.integer("align") != 0;
      o.reach = e.options.number("reach");
      o.refresh_bodies = e.options.integer("refresh_bodies") != 0;
      o.recheck = e.options.integer("recheck") != 0;
      o.chunk = e.options.number("chunk");
      ccd::EarliestScheduler direct(capsule.make(), capsule.make(), capsule.info->knowledge, grid.make(), o);
      const auto made = e.make({&capsule, &grid, 0.1});
      const ccd::ScheduleStats a = stats_of(*made, g.input()), b = stats_of(direct, g.input());
      CHECK(a.bodies.checks == b.bodies.checks);
      CHECK(a.rechecks == b.rechecks);
      CHECK(a.refreshes == b.refreshes);
      CHECK(a.bodies.narrow_calls == b.bodies.narrow_calls);
      CHECK(a.batches == b.batches);
    }
    // The options change what runs: no refinement builds fewer bounds, re-checks re-check.
    const auto plain = ccd::parse_scheduler("earliest").make({&capsule, &grid, 0.1});
    const auto never = ccd::parse_scheduler("earliest:stale=1").make({&capsule, &grid, 0.1});
    const auto recheck = ccd::parse_scheduler("earliest:recheck=1").make({&capsule, &grid, 0.1});
    const ccd::ScheduleStats p = stats_of(*plain, g.input());
    CHECK(stats_of(*never, g.input()).refreshes < p.refreshes);
    CHECK(p.rechecks == 0);
    CHECK(stats_of(*recheck, g.input()).rechecks > 0);
  }
  SECTION("fixed: dt is the step, the options reach the step pipeline") {
    const auto coarse = ccd::parse_scheduler("fixed").make({&capsule, &grid, 0.1});
    CHECK(stats_of(*coarse, g.input()).batches == 5);
    const auto fine = ccd::parse_scheduler("fixed:narrow_from_earliest=1").make({&capsule, &grid, 0.05});
    CHECK(stats_of(*fine, g.input()).batches == 10);
    ccd::Scene floor = ccdlab::generate_scene("floor_ramp", {{"bodies", 60}, {"seed", 2}});
    const ccd::Trajectories traj(floor);
    const ccd::RigidMotion motion(floor, traj);
    ccd::ScheduleInput in;
    in.motion = &motion;
    in.horizon = floor.horizon;
    in.acceleration_bound = floor.max_acceleration();
    in.walls = floor.box;
    in.timed = false;
    const double dt = floor.horizon / 8;
    const auto plain = ccd::parse_scheduler("fixed").make({&capsule, &grid, dt});
    const auto kinematic = ccd::parse_scheduler("fixed:kinematic=1").make({&capsule, &grid, dt});
    plain->set_scenery(floor.scenery);
    kinematic->set_scenery(floor.scenery);
    const ccd::ScheduleStats a = stats_of(*plain, in), b = stats_of(*kinematic, in);
    REQUIRE(a.scenery.passed > 0);
    CHECK(a.scenery.tests_saved == 0);
    CHECK(b.scenery.tests_saved > 0);  // the kinematic principle skipped some passed pairs
    CHECK(b.scenery.narrow_calls + b.scenery.tests_saved == b.scenery.passed);
  }
}

TEST_CASE("the registry refuses bad scheduler options and parts, naming them", "[pipeline][scheduler][registry]") {
  CHECK(mentions(refusal([] { ccd::parse_scheduler("earliest:stale=0"); }), "stale"));
  CHECK(mentions(refusal([] { ccd::parse_scheduler("earliest:chunk=-1"); }), "chunk"));
  CHECK(mentions(refusal([] { ccd::parse_scheduler("earliest:reach=-1"); }), "reach"));
  CHECK(mentions(refusal([] { ccd::parse_scheduler("earliest:recheck=2"); }), "recheck"));
  CHECK(mentions(refusal([] { ccd::parse_scheduler("fixed:kinematic=0.5"); }), "kinematic"));
  CHECK(mentions(refusal([] { ccd::parse_scheduler("fixed:stale=0.5"); }), "stale"));  // not fixed's
  CHECK(mentions(refusal([] { ccd::parse_scheduler("earliest:window=1"); }), "window"));
  const ccd::BoundSpec capsule = ccd::parse_bound("capsule");
  const ccd::BoundSpec aabb = ccd::parse_bound("aabb");
  const ccd::BroadPhaseSpec grid = ccd::parse_broad_phase("grid");
  const std::string instant = refusal([&] { ccd::parse_scheduler("earliest").make({&aabb, &grid, 0.1}); });
  CHECK(mentions(instant, "scheduler 'earliest'"));
  CHECK(mentions(instant, "space-time bound"));
  CHECK(mentions(refusal([&] { ccd::parse_scheduler("earliest").make({&capsule, &grid, 0.0}); }), "dt"));
  CHECK(mentions(refusal([&] { ccd::parse_scheduler("fixed").make({&capsule, &grid, -1.0}); }), "dt"));
  CHECK(mentions(refusal([&] { ccd::parse_scheduler("fixed").make({&capsule, nullptr, 0.1}); }), "broad phase"));
  CHECK(refusal([&] { ccd::parse_scheduler("fixed").make({&aabb, &grid, 0.1}); }).empty());  // samples
}

}  // namespace pipeline_scheduler_registry_test
