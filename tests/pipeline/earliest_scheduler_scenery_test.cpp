// The earliest scheduler against static scenery (EarliestScheduler::set_scenery): every
// body-static event of the exact sphere-polygon truth (or the certified rigid one) that
// starts after t = 0 is found by a static narrow call whose interval contains its start,
// and every static contact lies in an event of its (body, polygon) pair (the runner's
// self-check rule), for every continuous bound, two broad phases, several windows and the
// scheduler's options. Scenes: dyadic adversarial cases at the origin and 2^20 away
// (tangent to a floor, grazing an edge and a vertex, at t = 0 and at the horizon, on a
// window boundary, after and exactly at a wall reflection, an acceleration change from
// rest, resting on a polygon at zero velocity, a fast ball through a thin plate), the
// hand-worked rigid cases, and random scenes of the floor_ramp, bowl, pinball and tumble
// generators.
#include <bounds/registry.hpp>
#include <ccd/broad_phase/registry.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <pipeline/earliest_scheduler.hpp>
#include <tests/pipeline/earliest_under_test.hpp>
#include <ccd/truth/rigid_static_truth.hpp>
#include <ccd/truth/static_truth.hpp>
#include <ccd/truth/truth_io.hpp>
#include <generators/registry.hpp>

#include <tests/ccd/scene/body_builder.hpp>
#include <tests/ccd/scene/rigid_scenery_scenes.hpp>
#include <tests/ccd/scene/scenery_support.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace pipeline_earliest_scheduler_scenery_test {

using ccd::Vec3;

namespace {

struct Mode {
  const char* name;
  double stale;
  bool refresh_bodies;
  double reach;
  bool recheck;
};

// Pair refinement (default), none, a fine one, body refreshes (queued checks), speed-adapted
// windows with both refinements, and speed re-checks.
constexpr Mode kModes[] = {
    {"default", 0.25, false, 0.0, false},         {"stale=1", 1.0, false, 0.0, false},
    {"stale=0.01", 0.01, false, 0.0, false},      {"refresh_bodies=1", 0.25, true, 0.0, false},
    {"reach=2", 0.25, false, 2.0, false},         {"reach=2,refresh_bodies=1", 0.25, true, 2.0, false},
    {"recheck=1", 0.25, false, 0.0, true},        {"recheck=1,reach=2", 0.25, false, 2.0, true},
};

ccd::test::EarliestUnderTest make(const std::string& bound, const std::string& broad, double dt, const Mode& m,
                            const ccd::RigidMotion* rigid = nullptr) {
  const ccd::BoundSpec b = ccd::parse_bound(bound);
  ccd::ScheduleOptions o;
  o.window = dt;
  o.stale = m.stale;
  o.refresh_bodies = m.refresh_bodies;
  o.reach = m.reach;
  o.recheck = m.recheck;
  return ccd::test::EarliestUnderTest(std::make_unique<ccd::EarliestScheduler>(
      b.make(), b.make(), b.info->knowledge, ccd::parse_broad_phase(broad).make(), o), rigid);
}

struct Outcome {
  long missed = 0;      // events (enter > 0) no static contact of their pair covers
  long unexpected = 0;  // static contacts whose interval meets no event of their pair
  long found = 0;       // events (enter > 0) covered
  long initial = 0;     // events in progress at t = 0 (reported or not)
};

// The runner's rules (experiments/runner.cpp, match_static_contact): an event is detected
// by a contact of its pair found over [from, to] with from <= enter <= to; a contact is
// expected when an event of its pair meets [from, to]; `slack` is the truth's accuracy.
Outcome compare(const std::vector<ccd::StaticEvent>& events, const std::vector<ccd::ScheduledStaticContact>& contacts,
                double slack) {
  Outcome o;
  for (const ccd::StaticEvent& e : events) {
    if (e.enter == 0.0) {
      ++o.initial;
      continue;
    }
    const bool found = std::any_of(contacts.begin(), contacts.end(), [&](const ccd::ScheduledStaticContact& c) {
      return c.pair.body == e.body && c.pair.polygon == e.polygon && c.from - slack <= e.enter &&
             e.enter <= c.to + slack;
    });
    found ? ++o.found : ++o.missed;
  }
  for (const ccd::ScheduledStaticContact& c : contacts) {
    CHECK(c.from <= c.contact.toi);
    CHECK(c.contact.toi <= c.to);
    const bool expected = std::any_of(events.begin(), events.end(), [&](const ccd::StaticEvent& e) {
      return e.body == c.pair.body && e.polygon == c.pair.polygon && e.exit >= c.from - slack &&
             e.enter <= c.to + slack;
    });
    o.unexpected += !expected;
  }
  return o;
}

// One body and its own polygon per case, 16 apart along x (no body meets another case's
// polygon), all at `o`; dyadic data, horizon 1, walls [o, o + 160]^3. Contact instants
// (exact): see each line.
ccd::Scene adversarial_scene(const Vec3& o) {
  ccd::Scene s;
  s.horizon = 1.0;
  s.box = ccd::WallBox{o, o + Vec3::Constant(160)};
  auto add = [&](int k, ccd::Body b, std::vector<Vec3> polygon) {
    const Vec3 at = o + Vec3(16.0 * k + 16.0, 16.0, 16.0);
    b.position += at;
    for (Vec3& v : polygon) v += at;
    s.bodies.push_back(b);
    s.scenery.push_back(ccd::polygon_from_vertices(std::move(polygon)));
  };
  const std::vector<Vec3> sq{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const double tiny = std::ldexp(1.0, -20);
  add(0, ccd::test::body(0.625, {1.375, 1.5, 1}, {0, 0, -2}), sq);          // grazes the vertex (1, 1, 0) at 1/2
  add(1, ccd::test::body(0.5, {1.5, -2, 0}, {0, 4, 0}), sq);                // in the plane: grazes the edge x = 1, [1/2, 3/4]
  add(2, ccd::test::body(0.25, {0.5, 0.5, 2.25}, {0, 0, -2}), sq);          // reaches the face at the horizon t = 1
  add(3, ccd::test::body(0.25, {0.5, 0.5, 0.75}, {0, 0, -2}, {0, 0, 4}), sq);  // tangent to the floor at 1/2 (apex)
  add(4, ccd::test::body(0.25, {-1, 0.5, 0.25}, {2, 0, 0}), sq);            // slides at height r, enters over x = 0 at 1/2
  {
    ccd::Body b = ccd::test::body(0.25, {0.5, 0.5, 1}, Vec3::Zero(), {0, 0, -4});  // from rest; z = r at 7/8
    b.acceleration_changes.push_back({0.25, Vec3::Zero()});
    add(5, b, sq);
  }
  add(6, ccd::test::body(0.25, {0.5, 0.5, 0.25}, {0, 0, 1}), sq);           // touches at t = 0 only, leaving
  add(7, ccd::test::body(0.25, {0.5, 0.5, 0.25}), sq);                      // at rest on the face: [0, 1]
  add(8, ccd::test::body(0.25, {0.5, 0.5, 0.25 + tiny}), sq);               // at rest 2^-20 above it: no contact
  add(9, ccd::test::body(0.125, {0.5, 0.5, 20}, {0, 0, -40}), sq);          // through the thin plate at ~1/2
  // Wall x = o.x: from (1, 2, 2) at (-4, 8, 0) the ball reflects at t = 3/16 (x = 1/4) and
  // reaches the plate x = 3/2 at t = 7/16; the second one touches the plate y = 15/4 exactly
  // at the reflection.
  s.bodies.push_back(ccd::test::body(0.25, o + Vec3(1, 2, 2), {-4, 8, 0}));
  s.scenery.push_back(ccd::polygon_from_vertices({o + Vec3(1.5, 5, 1), o + Vec3(1.5, 7, 1), o + Vec3(1.5, 7, 3),
                                                  o + Vec3(1.5, 5, 3)}));
  s.bodies.push_back(ccd::test::body(0.25, o + Vec3(1, 2, 6), {-4, 8, 0}));
  s.scenery.push_back(ccd::polygon_from_vertices({o + Vec3(0, 3.75, 5), o + Vec3(0, 3.75, 7), o + Vec3(1, 3.75, 7),
                                                  o + Vec3(1, 3.75, 5)}));
  return s;
}

// The continuous bounds of the registry (every one can be scheduled).
std::vector<std::string> continuous_bounds() {
  std::vector<std::string> out;
  for (const ccd::BoundInfo& b : ccd::bound_registry())
    if (b.knowledge != ccd::Knowledge::Instant) out.emplace_back(b.name);
  return out;
}

}  // namespace

TEST_CASE("the earliest scheduler misses no body-static event on the dyadic cases",
          "[pipeline][scheduler][scenery][zero_miss]") {
  for (const double offset : {0.0, 1048576.0}) {
    const ccd::Scene scene = adversarial_scene(Vec3::Constant(offset));
    const ccd::Trajectories traj(scene);
    const std::vector<ccd::StaticEvent> events = ccd::compute_static_truth(traj, scene.scenery, 1);
    // The cases' events: 0-5, 9, 10, 11 after t = 0; 6 and 7 from t = 0; none for 8.
    REQUIRE(events.size() == 11);
    const double A = scene.max_acceleration();
    long found = 0;
#ifdef CCDLAB_SANITIZED
    const std::vector<const char*> broads{"grid"};  // every run meets every assertion: fewer runs
#else
    const std::vector<const char*> broads{"grid", "sap"};
#endif
    for (const std::string& bound : continuous_bounds())
      for (const char* broad : broads)
        // 1/4 and 1/8 put window ends on the contact instants 3/16, 1/4, 7/16, 1/2, 7/8, 1;
        // 0.3 does not divide the horizon.
        for (const double dt : {0.25, 0.125, 0.3})
          for (const Mode& m : kModes) {
            INFO("offset " << offset << " " << bound << "/" << broad << "@earliest:" << m.name << " dt " << dt);
            ccd::test::EarliestUnderTest sched = make(bound, broad, dt, m);
            sched.set_scenery(scene.scenery);
            std::vector<ccd::ScheduledContact> contacts;
            REQUIRE(sched.run(traj, scene.horizon, A, scene.box, contacts));
            CHECK(contacts.empty());  // no two bodies meet
            const Outcome o = compare(events, sched.static_contacts(), 1e-9 * scene.horizon);
            CHECK(o.missed == 0);
            CHECK(o.unexpected == 0);
            CHECK(o.found == 9);
            const ccd::ScheduleStats& st = sched.stats();
            CHECK(st.scenery.passed <= st.scenery.checks);
            CHECK(st.scenery.candidates <= st.scenery.checks);
            CHECK(st.scenery.narrow_calls >= sched.static_contacts().size());
            found += o.found;
          }
    CHECK(found > 0);
  }
}

TEST_CASE("the earliest scheduler without scenery makes no static check", "[pipeline][scheduler][scenery]") {
  const ccd::Scene scene = adversarial_scene(Vec3::Zero());
  const ccd::Trajectories traj(scene);
  ccd::test::EarliestUnderTest sched = make("capsule", "grid", 0.25, kModes[0]);
  std::vector<ccd::ScheduledContact> contacts;
  REQUIRE(sched.run(traj, scene.horizon, 0.0, scene.box, contacts));
  CHECK(sched.static_contacts().empty());
  CHECK(sched.stats().scenery.candidates == 0);
  CHECK(sched.stats().scenery.checks == 0);
  CHECK(sched.stats().scenery.narrow_calls == 0);
}

TEST_CASE("the earliest scheduler finds a ball's floor contact from the check, not the window start",
          "[pipeline][scheduler][scenery]") {
  // A ball of radius 1/4 falls at 2 onto a floor 3/4 below its lowest point: contact at
  // t = 3/8 exactly; one window of 1 (stale 1: no refinement). The capsule's static test
  // gives the speed bound's earliest time (3/4) / 2 = 3/8 itself, so the narrow call
  // starts there and finds the contact at its start.
  ccd::Scene s;
  s.horizon = 1.0;
  s.bodies.push_back(ccd::test::body(0.25, {0.5, 0.5, 1}, {0, 0, -2}));
  s.scenery.push_back(ccd::test::square_z(-4, -4, 0, 8));
  const ccd::Trajectories traj(s);
  ccd::test::EarliestUnderTest sched = make("capsule", "brute", 1.0, kModes[1]);
  sched.set_scenery(s.scenery);
  std::vector<ccd::ScheduledContact> contacts;
  REQUIRE(sched.run(traj, s.horizon, 0.0, std::nullopt, contacts));
  REQUIRE(sched.static_contacts().size() == 1);
  const ccd::ScheduledStaticContact& c = sched.static_contacts()[0];
  CHECK(c.pair == ccd::StaticPair{0, 0});
  CHECK(c.contact.toi == 0.375);
  CHECK(c.from > 0.0);
  CHECK(c.from <= 0.375);
  CHECK(c.to == 1.0);
  CHECK(sched.stats().scenery.checks == 1);
  CHECK(sched.stats().scenery.narrow_calls == 1);
}

TEST_CASE("the earliest scheduler misses no rigid body-static event on the hand-worked cases",
          "[pipeline][scheduler][scenery][rigid][zero_miss]") {
  const ccd::Scene scene = ccd::test::rigid_static_cases();
  const ccd::Trajectories traj(scene);
  const ccd::RigidMotion motion(scene, traj);
  const ccd::RigidStaticTruthResult truth = ccd::compute_rigid_static_truth(motion, scene.scenery);
  REQUIRE(truth.events.size() >= 5);
  const double slack = std::max(1e-9 * scene.horizon, ccd::largest_error(truth.errors));
  long found = 0;
  for (const char* bound : {"capsule", "horn:4", "swept_aabb", "enclosing_sphere", "obb_sat:4"})
    for (const double dt : {0.25, 0.5, 1.0 / 3.0})  // 1/4 and 1/2 put window ends on 1/2, 1, 3/2, 2
      for (const Mode& m : {kModes[0], kModes[3], kModes[4], kModes[6]}) {
        INFO(bound << "/grid@earliest:" << m.name << " dt " << dt);
        ccd::test::EarliestUnderTest sched = make(bound, "grid", dt, m, &motion);
        sched.set_scenery(scene.scenery);
        std::vector<ccd::ScheduledContact> contacts;
        REQUIRE(sched.run(traj, scene.horizon, scene.max_acceleration(), scene.box, contacts));
        const Outcome o = compare(truth.events, sched.static_contacts(), slack);
        CHECK(o.missed == 0);
        CHECK(o.unexpected == 0);
        CHECK(o.found > 0);
        found += o.found;
      }
  CHECK(found > 0);
}

TEST_CASE("the earliest scheduler misses no body-static event in generated scenes",
          "[pipeline][scheduler][scenery][zero_miss]") {
  struct Case {
    const char* generator;
    nlohmann::json params;
  };
#ifdef CCDLAB_SANITIZED
  constexpr int k = 1;  // bodies halved
#else
  constexpr int k = 2;
#endif
  const Case c = GENERATE_COPY(
      Case{"floor_ramp", {{"bodies", 12 * k}, {"seed", 4}, {"ramps", 2}, {"horizon", 1.0}}},
      Case{"bowl", {{"bodies", 12 * k}, {"seed", 5}, {"horizon", 1.0}}},
      Case{"pinball", {{"bodies", 10 * k}, {"obstacles", 40}, {"seed", 6}, {"horizon", 0.5}}},
      Case{"tumble", {{"bodies", 4 * k}, {"seed", 7}, {"horizon", 1.0}, {"spin_max", 16.0}}});
  const ccd::Scene scene = ccdlab::generate_scene(c.generator, c.params);
  const ccd::Trajectories traj(scene);
  const bool rigid = scene.has_non_spheres();
  std::optional<ccd::RigidMotion> motion;
  if (rigid) motion.emplace(scene, traj);
  std::vector<ccd::StaticEvent> events;
  double slack = 1e-9 * scene.horizon;
  if (rigid) {
    const ccd::RigidStaticTruthResult truth = ccd::compute_rigid_static_truth(*motion, scene.scenery);
    events = truth.events;
    slack = std::max(slack, ccd::largest_error(truth.errors));
  } else {
    events = ccd::compute_static_truth(traj, scene.scenery, 1);
  }
  INFO(c.generator << ": " << events.size() << " static events");
  REQUIRE(events.size() > 3);
  std::vector<std::string> bounds{"capsule", "horn:4", "swept_aabb", "enclosing_sphere"};
  if (rigid) bounds.emplace_back("obb_sat:4");
  long found = 0;
  for (const std::string& bound : bounds)
    for (const char* broad : {"grid", "sap"})
      for (const double dt : {0.0625, 0.3})
        for (const Mode& m : {kModes[0], kModes[1], kModes[3], kModes[5], kModes[7]}) {
          if (std::string(broad) == "sap" && std::string(m.name) != "default") continue;
          INFO(c.generator << " " << bound << "/" << broad << "@earliest:" << m.name << " dt " << dt);
          ccd::test::EarliestUnderTest sched = make(bound, broad, dt, m, rigid ? &*motion : nullptr);
          sched.set_scenery(scene.scenery);
          std::vector<ccd::ScheduledContact> contacts;
          REQUIRE(sched.run(traj, scene.horizon, scene.max_acceleration(), scene.box, contacts));
          const Outcome o = compare(events, sched.static_contacts(), slack);
          CHECK(o.missed == 0);
          CHECK(o.unexpected == 0);
          found += o.found;
        }
  CHECK(found > 0);
}

TEST_CASE("the earliest scheduler refuses scenery in a scene that wraps around", "[pipeline][scheduler][scenery]") {
  ccd::Scene s;
  s.horizon = 1.0;
  s.box = ccd::WallBox{Vec3::Zero(), Vec3::Constant(8)};
  s.box->boundary = {ccd::Boundary::Wrap, ccd::Boundary::Wrap, ccd::Boundary::Wrap};
  s.bodies.push_back(ccd::test::body(0.25, {1, 1, 1}, {1, 0, 0}));
  const ccd::Trajectories traj(s);
  const std::vector<ccd::StaticPolygon> floor{ccd::test::square_z(0, 0, 0.5, 4)};
  ccd::test::EarliestUnderTest sched = make("capsule", "grid", 0.25, kModes[0]);
  sched.set_scenery(floor);
  std::vector<ccd::ScheduledContact> contacts;
  CHECK_THROWS_AS(sched.run(traj, s.horizon, 0.0, s.box, contacts), std::invalid_argument);
}

}  // namespace pipeline_earliest_scheduler_scenery_test
