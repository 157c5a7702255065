// The earliest scheduler on its own (the runner's zero-miss tests run it on every scene
// family through `BOUND/BROADPHASE@earliest`): every contact event of the exact truth is
// found by a narrow call whose interval contains its start, for every option; far pairs
// cost no check; an approaching pair is looked at only when it can touch; the refinement
// terminates on a grazing pair; in scenes that wrap around (the dyadic seam cases and wrapped
// gases) nothing is missed, nothing is reported at a wrong image shift or twice; checks run in
// rounds as they are made find what checks queued at their times find.
#include <bounds/registry.hpp>
#include <ccd/broad_phase/registry.hpp>
#include <pipeline/earliest_scheduler.hpp>
#include <tests/pipeline/earliest_under_test.hpp>
#include <ccd/truth/ground_truth.hpp>
#include <generators/registry.hpp>

#include <tests/ccd/scene/body_builder.hpp>
#include <tests/ccd/scene/periodic_scenes.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

namespace pipeline_earliest_scheduler_test {

using ccd::Vec3;

namespace {

ccd::test::EarliestUnderTest make(const std::string& bound, const std::string& broad, double dt, double stale = 0.25,
                            bool align = true, bool refresh_bodies = false, double reach = 0.0, bool recheck = false,
                            double chunk = 2.0) {
  const ccd::BoundSpec b = ccd::parse_bound(bound);
  ccd::ScheduleOptions o;
  o.window = dt;
  o.stale = stale;
  o.align = align;
  o.refresh_bodies = refresh_bodies;
  o.reach = reach;
  o.recheck = recheck;
  o.chunk = chunk;
  return ccd::test::EarliestUnderTest(std::make_unique<ccd::EarliestScheduler>(
      b.make(), b.make(), b.info->knowledge, ccd::parse_broad_phase(broad).make(), o));
}

// Events (enter > 0) with no contact of their pair whose narrow interval contains enter.
long undetected(const std::vector<ccd::ContactEvent>& events, const std::vector<ccd::ScheduledContact>& contacts,
                double slack) {
  long missed = 0;
  for (const ccd::ContactEvent& e : events) {
    if (e.enter == 0.0) continue;
    bool found = false;
    for (const ccd::ScheduledContact& c : contacts)
      found = found || (c.pair.a == e.a && c.pair.b == e.b && c.from - slack <= e.enter && e.enter <= c.to + slack);
    missed += !found;
  }
  return missed;
}

}  // namespace

TEST_CASE("the earliest scheduler misses no event, whatever its options", "[pipeline][scheduler][zero_miss]") {
  struct Scene {
    const char* generator;
    nlohmann::json params;
  };
  const Scene s = GENERATE(Scene{"gas", {{"bodies", 150}, {"seed", 3}, {"speed_max", 30}, {"horizon", 0.5}}},
                           Scene{"rain", {{"bodies", 120}, {"seed", 12}, {"horizon", 1.0}, {"aspect", 1}}},
                           Scene{"bullets", {{"bodies", 80}, {"seed", 14}, {"bullets", 8}, {"horizon", 0.5}}});
  const ccd::Scene scene = ccdlab::generate_scene(s.generator, s.params);
  const ccd::Trajectories traj(scene);
  const auto events = ccd::compute_truth(traj);
  INFO(s.generator << ": " << events.size() << " events");
  REQUIRE(events.size() > 5);
  const double A = scene.max_acceleration();
  for (const char* bound : {"horn:4", "capsule", "horn_sat:3", "swept_aabb", "enclosing_sphere"}) {
    for (const double stale : {0.01, 0.25, 1.0}) {
      // pair refinement; body refreshes aligned; on own clocks; then the same three with
      // speed-adapted windows (reach: every body its own window length)
      for (const int mode : {0, 1, 2, 3, 4, 5}) {
        const bool align = mode % 3 != 2, refresh_bodies = mode % 3 != 0;
        const double reach = mode >= 3 ? 1.0 : 0.0;
        for (const double dt : {0.05, 0.3}) {  // 0.3 does not divide the horizon
          INFO(s.generator << " " << bound << " stale " << stale << " mode " << mode << " dt " << dt);
          ccd::test::EarliestUnderTest sched = make(bound, "grid", dt, stale, align, refresh_bodies, reach);
          std::vector<ccd::ScheduledContact> contacts;
          REQUIRE(sched.run(traj, scene.horizon, A, scene.box, contacts));
          CHECK(undetected(events, contacts, 1e-9 * scene.horizon) == 0);
          const ccd::ScheduleStats& st = sched.stats();
          CHECK(st.bodies.passed <= st.bodies.checks);
          CHECK(st.refreshes >= traj.size());
          for (const ccd::ScheduledContact& c : contacts) {
            CHECK(c.from <= c.contact.toi);
            CHECK(c.contact.toi <= c.to);
          }
          if (stale == 1.0 && align && reach == 0.0) {
            // No refinement: every body refreshes at every window, as fixed steps would.
            const double windows = std::ceil(scene.horizon / dt);
            CHECK(st.refreshes == traj.size() * static_cast<std::uint64_t>(windows));
          }
        }
      }
    }
  }
}

TEST_CASE("the earliest scheduler checks a pair only when it can touch", "[pipeline][scheduler]") {
  // (0, 1) head-on along x at relative speed 4, surfaces 3 apart at t = 0: they touch at
  // t = 3/4 exactly (dyadic). Bodies 2 to 5 rest, 1000 away from everything.
  ccd::Scene s;
  s.horizon = 1.0;
  s.bodies.push_back(ccd::test::body(0.5, Vec3(0, 0, 0), Vec3(2, 0, 0)));
  s.bodies.push_back(ccd::test::body(0.5, Vec3(4, 0, 0), Vec3(-2, 0, 0)));
  s.bodies.push_back(ccd::test::body(0.5, Vec3(1000, 0, 0)));
  s.bodies.push_back(ccd::test::body(0.5, Vec3(2000, 0, 0)));
  s.bodies.push_back(ccd::test::body(0.5, Vec3(-1000, 0, 0)));
  s.bodies.push_back(ccd::test::body(0.5, Vec3(0, 1000, 0)));
  const ccd::Trajectories traj(s);
  for (const char* bound : {"horn:4", "capsule"}) {
   for (const bool refresh_bodies : {false, true}) {
    INFO(bound << " refresh_bodies " << refresh_bodies);
    ccd::test::EarliestUnderTest sched = make(bound, "brute", 1.0, 0.25, true, refresh_bodies);
    std::vector<ccd::ScheduledContact> contacts;
    REQUIRE(sched.run(traj, s.horizon, 0.0, std::nullopt, contacts));
    REQUIRE(contacts.size() == 1);
    CHECK(contacts[0].pair == ccd::BodyPair{0, 1});
    CHECK(contacts[0].contact.toi == 0.75);
    // One narrow call, at the refined check, no earlier than half the way in.
    CHECK(sched.stats().bodies.narrow_calls == 1);
    CHECK(contacts[0].from >= 0.5);
    CHECK(contacts[0].from <= 0.75);
    // The far bodies were never paired: only (0, 1) was tested (at the start and after
    // each refinement).
    CHECK(sched.stats().bodies.checks <= 4);
    if (refresh_bodies) CHECK(sched.stats().bodies.candidates == sched.stats().bodies.checks);
    else CHECK(sched.stats().bodies.candidates == 1);  // refinements re-test the pair alone
   }
  }
}

TEST_CASE("speed-adapted windows: fast bodies refresh often, slow ones once per dt", "[pipeline][scheduler]") {
  // Radius 1/2 everywhere, so reach 2 is a length of 1. Body 0 flies at 64 along x: its
  // windows are dt / 64 (64 x 1/64 = 1, not more than the reach); body 1 rests in its way
  // (surfaces 31 apart at t = 0: contact at t = 31/64 exactly); body 2 moves at 3/4 far
  // away (a whole window of dt = 1); body 3 at 3 (windows of 1/4). The fast body's short
  // boxes never meet body 2's, and the broad phase updates only the bodies that expire.
  ccd::Scene s;
  s.horizon = 1.0;
  s.bodies.push_back(ccd::test::body(0.5, Vec3(0, 0, 0), Vec3(64, 0, 0)));
  s.bodies.push_back(ccd::test::body(0.5, Vec3(32, 0, 0)));
  s.bodies.push_back(ccd::test::body(0.5, Vec3(16, 8, 0), Vec3(0.75, 0, 0)));
  s.bodies.push_back(ccd::test::body(0.5, Vec3(0, -40, 0), Vec3(0, 3, 0)));
  const ccd::Trajectories traj(s);
  for (const char* bound : {"horn:4", "capsule", "swept_aabb", "enclosing_sphere"}) {
    for (const char* broad : {"grid", "sap", "brute"}) {
      for (const bool align : {true, false}) {
        INFO(bound << " " << broad << " align " << align);
        ccd::test::EarliestUnderTest sched = make(bound, broad, 1.0, 1.0, align, false, 2.0);
        std::vector<ccd::ScheduledContact> contacts;
        REQUIRE(sched.run(traj, s.horizon, 0.0, std::nullopt, contacts));
        // Contact begins exactly at a window boundary of body 0: found from the window
        // that ends there (a later one may report the pair overlapping).
        REQUIRE(!contacts.empty());
        for (const ccd::ScheduledContact& c : contacts) CHECK(c.pair == ccd::BodyPair{0, 1});
        CHECK(contacts[0].contact.toi == 31.0 / 64.0);
        CHECK(contacts[0].to == 31.0 / 64.0);
        // 4 bounds at t = 0 over dt, bodies 0 and 3 rebuilt at once over their shorter
        // windows, then 63 expiries of body 0 and 3 of body 3 (body 1 and 2 never expire).
        CHECK(sched.stats().refreshes == 4 + 2 + 63 + 3);
        // Body 0 checked against body 1 only in the windows where their boxes meet; body 2
        // and 3 never meet anything.
        CHECK(sched.stats().bodies.candidates <= 4);
      }
    }
  }
}

TEST_CASE("the refinement terminates on a grazing pair", "[pipeline][scheduler]") {
  // Tangent at t = 1/2 (dyadic: y offset exactly r_a + r_b): a bound's earliest creeps up
  // on 1/2 without reaching it; each refinement must advance a window by stale x dt.
  ccd::Scene s;
  s.horizon = 1.0;
  s.bodies.push_back(ccd::test::body(0.5, Vec3(-1, 0, 0), Vec3(2, 0, 0)));
  s.bodies.push_back(ccd::test::body(0.5, Vec3(1, 1, 0), Vec3(-2, 0, 0)));
  const ccd::Trajectories traj(s);
  for (const char* bound : {"horn:4", "horn_sat:4", "capsule", "swept_aabb", "enclosing_sphere"}) {
   for (const bool refresh_bodies : {false, true}) {
    INFO(bound << " refresh_bodies " << refresh_bodies);
    ccd::test::EarliestUnderTest sched = make(bound, "brute", 1.0, 0.01, true, refresh_bodies);
    std::vector<ccd::ScheduledContact> contacts;
    REQUIRE(sched.run(traj, s.horizon, 0.0, std::nullopt, contacts));
    REQUIRE(contacts.size() == 1);
    CHECK(contacts[0].contact.toi == Approx(0.5).margin(1e-7));
    CHECK(sched.stats().refreshes <= 2 + 2 * 100);  // at most 1 / stale refinements per body
   }
  }
}

TEST_CASE("the earliest scheduler refuses what it cannot run", "[pipeline][scheduler]") {
  const ccd::BoundSpec sphere = ccd::parse_bound("sphere");
  ccd::ScheduleOptions o;
  o.window = 0.1;
  CHECK_THROWS_AS(ccd::EarliestScheduler(sphere.make(), sphere.make(), sphere.info->knowledge,
                                         ccd::parse_broad_phase("grid").make(), o),
                  std::invalid_argument);
  const ccd::BoundSpec capsule = ccd::parse_bound("capsule");
  o.reach = -1.0;
  CHECK_THROWS_AS(ccd::EarliestScheduler(capsule.make(), capsule.make(), capsule.info->knowledge,
                                         ccd::parse_broad_phase("grid").make(), o),
                  std::invalid_argument);
  o.reach = 0.0;
  o.chunk = -1.0;  // a chunk is a multiple of a length: >= 0
  CHECK_THROWS_AS(ccd::EarliestScheduler(capsule.make(), capsule.make(), capsule.info->knowledge,
                                         ccd::parse_broad_phase("grid").make(), o),
                  std::invalid_argument);
  o.chunk = 2.0;
  o.window = 0.0;
  CHECK_THROWS_AS(ccd::EarliestScheduler(capsule.make(), capsule.make(), capsule.info->knowledge,
                                         ccd::parse_broad_phase("grid").make(), o),
                  std::invalid_argument);
}

namespace {

// A scene whose exact truth has one contact event, entering at `enter` (dyadic).
struct OneContact {
  const char* name;
  ccd::Scene scene;
  double enter;
};

std::vector<OneContact> one_contact_scenes() {
  std::vector<OneContact> out;
  {  // head-on at relative speed 4, surfaces 3 apart: contact at 3/4
    ccd::Scene s;
    s.horizon = 1.0;
    s.bodies.push_back(ccd::test::body(0.5, Vec3(0, 0, 0), Vec3(2, 0, 0)));
    s.bodies.push_back(ccd::test::body(0.5, Vec3(4, 0, 0), Vec3(-2, 0, 0)));
    out.push_back({"head-on", s, 0.75});
  }
  {  // the same 2^40 away from the origin (every coordinate still exact)
    ccd::Scene s;
    s.horizon = 1.0;
    const Vec3 far(0x1p40, -0x1p40, 0x1p40);
    s.bodies.push_back(ccd::test::body(0.5, far + Vec3(0, 0, 0), Vec3(2, 0, 0)));
    s.bodies.push_back(ccd::test::body(0.5, far + Vec3(4, 0, 0), Vec3(-2, 0, 0)));
    out.push_back({"far from the origin", s, 0.75});
  }
  {  // tangent at 1/2: y offset exactly r_a + r_b, the pair touches without overlapping
    ccd::Scene s;
    s.horizon = 1.0;
    s.bodies.push_back(ccd::test::body(0.5, Vec3(-1, 0, 0), Vec3(2, 0, 0)));
    s.bodies.push_back(ccd::test::body(0.5, Vec3(1, 1, 0), Vec3(-2, 0, 0)));
    out.push_back({"tangent", s, 0.5});
  }
  {  // contact exactly at the horizon: centres 5 apart closing at 4, R = 1
    ccd::Scene s;
    s.horizon = 1.0;
    s.bodies.push_back(ccd::test::body(0.5, Vec3(0, 0, 0), Vec3(2, 0, 0)));
    s.bodies.push_back(ccd::test::body(0.5, Vec3(5, 0, 0), Vec3(-2, 0, 0)));
    out.push_back({"at the horizon", s, 1.0});
  }
  {  // contact exactly at a wall reflection: body 0 reaches the wall x = 4 (centre 3.5) at
     // 7/4 and turns back while body 1, on the wall's line (equal x), arrives along y.
    ccd::Scene s;
    s.horizon = 2.0;
    s.box = ccd::WallBox{Vec3(-8, -8, -8), Vec3(4, 8, 8)};
    s.bodies.push_back(ccd::test::body(0.5, Vec3(0, 0, 0), Vec3(2, 0, 0)));
    s.bodies.push_back(ccd::test::body(0.5, Vec3(3.5, -4.5, 0), Vec3(0, 2, 0)));
    out.push_back({"at a wall reflection", s, 1.75});
  }
  {  // an acceleration change: body 0 rests until 1/2, then accelerates at 8 towards body 1
     // (at rest, surfaces 1 apart): 4 (t - 1/2)^2 = 1 at t = 1
    ccd::Scene s;
    s.horizon = 2.0;
    ccd::Body b = ccd::test::body(0.5, Vec3(0, 0, 0));
    b.acceleration_changes.push_back({0.5, Vec3(8, 0, 0)});
    s.bodies.push_back(b);
    s.bodies.push_back(ccd::test::body(0.5, Vec3(2, 0, 0)));
    out.push_back({"after an acceleration change", s, 1.0});
  }
  {  // t = 0: the pair touches at the start, then separates; a third body arrives at 1/4
    ccd::Scene s;
    s.horizon = 1.0;
    s.bodies.push_back(ccd::test::body(0.5, Vec3(0, 0, 0), Vec3(0, 0, 0)));
    s.bodies.push_back(ccd::test::body(0.5, Vec3(1, 0, 0), Vec3(1, 0, 0)));
    s.bodies.push_back(ccd::test::body(0.5, Vec3(0, -3, 0), Vec3(0, 8, 0)));
    out.push_back({"touching at t = 0", s, 0.25});
  }
  return out;
}

}  // namespace

TEST_CASE("speed re-checks miss nothing on adversarial dyadic scenes", "[pipeline][scheduler][zero_miss]") {
  for (const OneContact& c : one_contact_scenes()) {
    const ccd::Trajectories traj(c.scene);
    const auto events = ccd::compute_truth(traj);
    std::size_t later = 0;  // events entering after t = 0: exactly the one at c.enter
    for (const ccd::ContactEvent& e : events)
      if (e.enter > 0.0) {
        ++later;
        CHECK(e.enter == c.enter);
      }
    REQUIRE(later == 1);
    const double A = c.scene.max_acceleration();
    for (const char* bound : {"horn:4", "capsule", "horn_sat:3", "swept_aabb", "enclosing_sphere"}) {
      for (const char* broad : {"brute", "grid"}) {
        for (const double chunk : {0.0, 2.0, 1.0 / 16.0}) {
          for (const double dt : {2.0, 0.25, 0.3}) {
            INFO(c.name << ": " << bound << "/" << broad << " chunk " << chunk << " dt " << dt);
            ccd::test::EarliestUnderTest sched = make(bound, broad, dt, 0.25, true, false, 0.0, true, chunk);
            std::vector<ccd::ScheduledContact> contacts;
            REQUIRE(sched.run(traj, c.scene.horizon, A, c.scene.box, contacts));
            CHECK(undetected(events, contacts, 1e-9 * c.scene.horizon) == 0);
            // The contact is found at its exact time by a call that starts no later.
            bool exact = false;
            for (const ccd::ScheduledContact& sc : contacts) {
              CHECK(sc.from <= sc.contact.toi);
              CHECK(sc.contact.toi <= sc.to);
              exact = exact || (sc.from <= c.enter && sc.contact.toi == Approx(c.enter).margin(1e-12));
            }
            CHECK(exact);
            const ccd::ScheduleStats& st = sched.stats();
            CHECK(st.rechecks <= st.bodies.checks);
            // No bound is built beyond one per body and window (no refinement).
            CHECK(st.refreshes <= traj.size() * static_cast<std::uint64_t>(std::ceil(c.scene.horizon / dt)));
          }
        }
      }
    }
  }
}

TEST_CASE("speed re-checks: a close pair moving in parallel costs a bounded number of checks", "[pipeline][scheduler]") {
  // Same velocity (20, 0, 0), centres 1 + 2^-10 apart (R = 1): they never touch. Speed
  // bounds see a closing speed of 40, so each chunk (chunk x R / 40) ends with a re-check;
  // the pair costs at most horizon / chunk-time narrow calls and twice as many checks.
  ccd::Scene s;
  s.horizon = 1.0;
  s.bodies.push_back(ccd::test::body(0.5, Vec3(0, 0, 0), Vec3(20, 0, 0)));
  s.bodies.push_back(ccd::test::body(0.5, Vec3(0, 1.0 + 0x1p-10, 0), Vec3(20, 0, 0)));
  const ccd::Trajectories traj(s);
  REQUIRE(ccd::compute_truth(traj).empty());
  // The capsules and the swept boxes stay 2^-10 apart (their tests are Disjoint); the
  // enclosing spheres of the window meet, so the pair passes and the re-checks do the work.
  for (const double chunk : {2.0, 8.0}) {
    INFO("chunk " << chunk);
    ccd::test::EarliestUnderTest sched = make("enclosing_sphere", "brute", 1.0, 0.25, true, false, 0.0, true, chunk);
    std::vector<ccd::ScheduledContact> contacts;
    REQUIRE(sched.run(traj, s.horizon, 0.0, std::nullopt, contacts));
    CHECK(contacts.empty());
    const double chunks = s.horizon / (chunk * 1.0 / 40.0);
    CHECK(sched.stats().bodies.narrow_calls >= 1);
    CHECK(double(sched.stats().bodies.narrow_calls) <= chunks + 1.0);
    CHECK(double(sched.stats().bodies.checks) <= 2.0 * chunks + 3.0);
    CHECK(sched.stats().refreshes == 2);  // one bound per body: nothing rebuilt
  }
}

TEST_CASE("speed re-checks: far pairs skip ahead, the narrow phase covers only the approach", "[pipeline][scheduler]") {
  // Head-on at relative speed 4 from surfaces 3 apart, dt = the horizon: one bound per body,
  // the capsule's pair test passes at t = 0; the re-check skips to 3/4 (the exact contact:
  // speeds are exact here), and one narrow call over a chunk from there finds it.
  ccd::Scene s;
  s.horizon = 1.0;
  s.bodies.push_back(ccd::test::body(0.5, Vec3(0, 0, 0), Vec3(2, 0, 0)));
  s.bodies.push_back(ccd::test::body(0.5, Vec3(4, 0, 0), Vec3(-2, 0, 0)));
  const ccd::Trajectories traj(s);
  ccd::test::EarliestUnderTest sched = make("capsule", "brute", 1.0, 0.25, true, false, 0.0, true, 2.0);
  std::vector<ccd::ScheduledContact> contacts;
  REQUIRE(sched.run(traj, s.horizon, 0.0, std::nullopt, contacts));
  REQUIRE(contacts.size() == 1);
  CHECK(contacts[0].contact.toi == 0.75);
  CHECK(contacts[0].from <= 0.75);
  CHECK(contacts[0].from >= 0.75 - 1e-12);  // the re-check's earliest, up to its rounding margin
  CHECK(sched.stats().bodies.narrow_calls == 1);
  CHECK(sched.stats().refreshes == 2);
  CHECK(sched.stats().bodies.checks <= 3);  // the bound's test and at most two re-checks
}

namespace {

// Every event of the truth (t = 0 included) has a contact of its pair whose narrow interval
// contains its start; every contact lies in an event of its pair (its time between enter
// and exit: a contact at a wrong image shift would not); no contact is reported twice (same
// pair, same interval: one image pair through two pairs of slots).
void check_wrapped(const std::vector<ccd::ContactEvent>& events, const std::vector<ccd::ScheduledContact>& contacts,
                   double slack) {
  long missed = 0, stray = 0, twice = 0;
  for (const ccd::ContactEvent& e : events) {
    bool found = false;
    for (const ccd::ScheduledContact& c : contacts)
      found = found || (c.pair.a == e.a && c.pair.b == e.b && c.from - slack <= e.enter && e.enter <= c.to + slack);
    missed += !found;
  }
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const ccd::ScheduledContact& c = contacts[i];
    bool inside = false;
    for (const ccd::ContactEvent& e : events)
      inside = inside || (c.pair.a == e.a && c.pair.b == e.b && e.enter - slack <= c.contact.toi &&
                          c.contact.toi <= e.exit + slack);
    stray += !inside;
    for (std::size_t j = 0; j < i; ++j)
      twice += contacts[j].pair == c.pair && contacts[j].from == c.from && contacts[j].to == c.to;
  }
  CHECK(missed == 0);
  CHECK(stray == 0);
  CHECK(twice == 0);
}

}  // namespace

TEST_CASE("the earliest scheduler misses no event in a scene that wraps around, whatever its options",
          "[pipeline][scheduler][zero_miss][periodic]") {
  struct Case {
    std::string name;
    ccd::Scene scene;
    double dt;
  };
  std::vector<Case> cases;
  // dt = 0.25 puts window ends on the contact instants 0.5, 1, 2, 3; 0.3 does not.
  for (const ccd::test::PeriodicCase& c : ccd::test::periodic_cases()) {
    cases.push_back({c.name, c.scene, 0.25});
#ifndef CCDLAB_SANITIZED
    cases.push_back({c.name, c.scene, 0.3});
#endif
  }
  // A random dyadic scene (gravity along a wrapped axis, acceleration changes) and a gas
  // that crosses the seam often.
#ifdef CCDLAB_SANITIZED
  const int gas_bodies = 50;
  const std::vector<std::string> broads = {"grid"};
#else
  const int gas_bodies = 100;
  const std::vector<std::string> broads = {"grid", "sap"};
#endif
  cases.push_back({"random periodic", ccd::test::random_periodic_scene(5, 40), 0.125});
  cases.push_back({"gas wrap=1",
                   ccdlab::generate_scene("gas", {{"bodies", gas_bodies},
                                                  {"seed", 21},
                                                  {"speed_max", 30},
                                                  {"horizon", 0.5},
                                                  {"wrap", 1}}),
                   0.05});
  struct Mode {
    const char* name;
    double stale;
    bool align, refresh_bodies;
    double reach;
    bool recheck;
    double chunk;
  };
  const Mode modes[] = {
      {"default", 0.25, true, false, 0.0, false, 2.0},     {"stale=0.01", 0.01, true, false, 0.0, false, 2.0},
      {"stale=1", 1.0, true, false, 0.0, false, 2.0},      {"refresh_bodies", 0.01, true, true, 0.0, false, 2.0},
      {"align=0", 0.25, false, true, 0.0, false, 2.0},     {"reach=1", 0.25, true, false, 1.0, false, 2.0},
      {"reach=1 refresh_bodies", 0.01, false, true, 1.0, false, 2.0},
      {"recheck", 0.25, true, false, 0.0, true, 2.0},      {"recheck chunk=0", 0.25, true, false, 0.0, true, 0.0},
      {"recheck reach=1", 0.25, true, false, 1.0, true, 0.5},
  };
  long contacts_total = 0;
  for (const Case& c : cases) {
    REQUIRE(c.scene.wraps());
    const ccd::Trajectories traj(c.scene);
    const auto events = ccd::compute_truth(traj);
    REQUIRE(!events.empty());
    const double A = c.scene.max_acceleration();
    for (const char* bound : {"horn:4", "capsule", "horn_sat:3", "swept_aabb", "enclosing_sphere"}) {
      for (const Mode& m : modes) {
        for (const std::string& broad : broads) {
          INFO(c.name << " dt " << c.dt << " " << bound << "/" << broad << " " << m.name);
          ccd::test::EarliestUnderTest sched =
              make(bound, broad, c.dt, m.stale, m.align, m.refresh_bodies, m.reach, m.recheck, m.chunk);
          std::vector<ccd::ScheduledContact> contacts;
          REQUIRE(sched.run(traj, c.scene.horizon, A, c.scene.box, contacts));
          check_wrapped(events, contacts, 1e-9 * c.scene.horizon);
          contacts_total += static_cast<long>(contacts.size());
        }
      }
    }
  }
  CHECK(contacts_total > 0);
}

TEST_CASE("the earliest scheduler on a wrapped gas: every broad phase, images counted", "[pipeline][scheduler][periodic]") {
  // Every broad phase under the scheduler on a dense wrapped gas: no event missed, and the
  // images are real: some contact is across the seam (centres more than half a box apart).
#ifdef CCDLAB_SANITIZED
  const int bodies = 60;
#else
  const int bodies = 150;
#endif
  const ccd::Scene scene = ccdlab::generate_scene(
      "gas", {{"bodies", bodies}, {"seed", 4}, {"speed_max", 40}, {"horizon", 0.5}, {"wrap", 1}});
  const ccd::Trajectories traj(scene);
  const auto events = ccd::compute_truth(traj);
  REQUIRE(events.size() > 5);
  const double half = 0.5 * (scene.box->max - scene.box->min).minCoeff();
  for (const ccd::BroadPhaseInfo& broad : ccd::broad_phase_registry()) {
    for (const double reach : {0.0, 1.0}) {
      INFO(broad.name << " reach " << reach);
      ccd::test::EarliestUnderTest sched = make("capsule", std::string(broad.name), 0.05, 0.25, true, false, reach);
      std::vector<ccd::ScheduledContact> contacts;
      REQUIRE(sched.run(traj, scene.horizon, 0.0, scene.box, contacts));
      check_wrapped(events, contacts, 1e-9 * scene.horizon);
      long across = 0;
      for (const ccd::ScheduledContact& c : contacts) {
        const Vec3 d = traj.position(c.pair.b, c.contact.toi) - traj.position(c.pair.a, c.contact.toi);
        across += d.cwiseAbs().maxCoeff() > half;
      }
      CHECK(across > 0);
      CHECK(sched.stats().refreshes > static_cast<std::uint64_t>(bodies) * 10);  // images included
    }
  }
}

TEST_CASE("checks run in rounds as they are made find what checks queued at their times find",
          "[pipeline][scheduler]") {
  // Without refinement (stale = 1) `refresh_bodies` changes nothing but the way checks run:
  // queued as events in time order (refresh_bodies = 1) or at once, in rounds, after the
  // refresh that made them (refresh_bodies = 0). Both must test the same pairs, make the same
  // narrow calls over the same intervals and find the same contacts; with rounds, a pair's
  // contacts come in time order. Plain scenes (walls, bullets, acceleration changes) and a
  // wrapped gas (checks on image slots).
#ifdef CCDLAB_SANITIZED
  const int gas_bodies = 60, wrapped_bodies = 40;
#else
  const int gas_bodies = 150, wrapped_bodies = 100;
#endif
  const ccd::Scene scenes[] = {
      ccdlab::generate_scene("gas", {{"bodies", gas_bodies}, {"seed", 3}, {"speed_max", 30}, {"horizon", 0.5}}),
      ccdlab::generate_scene("bullets", {{"bodies", 80}, {"seed", 14}, {"bullets", 8}, {"horizon", 0.5}}),
      ccdlab::generate_scene("swarm", {{"bodies", 60}, {"seed", 2}, {"horizon", 0.5}}),
      ccdlab::generate_scene(
          "gas", {{"bodies", wrapped_bodies}, {"seed", 21}, {"speed_max", 30}, {"horizon", 0.5}, {"wrap", 1}}),
  };
  const auto key = [](const ccd::ScheduledContact& c) {
    return std::make_tuple(c.pair.a, c.pair.b, c.from, c.to, c.contact.toi);
  };
  long contacts_total = 0;
  for (const ccd::Scene& scene : scenes) {
    const ccd::Trajectories traj(scene);
    const double A = scene.max_acceleration();
    for (const char* bound : {"capsule", "horn:4", "swept_aabb"}) {
      for (const double reach : {0.0, 1.0}) {
        for (const double dt : {0.05, 0.3}) {
          INFO(scene.bodies.size() << " bodies, wraps " << scene.wraps() << ", " << bound << " reach " << reach
                                   << " dt " << dt);
          ccd::test::EarliestUnderTest rounds = make(bound, "grid", dt, 1.0, true, false, reach);
          ccd::test::EarliestUnderTest queued = make(bound, "grid", dt, 1.0, true, true, reach);
          std::vector<ccd::ScheduledContact> a, b;
          ccd::StepTimes times;
          REQUIRE(rounds.run(traj, scene.horizon, A, scene.box, a, &times));
          REQUIRE(queued.run(traj, scene.horizon, A, scene.box, b));
          CHECK(rounds.stats().bodies.checks == queued.stats().bodies.checks);
          CHECK(rounds.stats().bodies.passed == queued.stats().bodies.passed);
          CHECK(rounds.stats().bodies.narrow_calls == queued.stats().bodies.narrow_calls);
          CHECK(rounds.stats().refreshes == queued.stats().refreshes);
          REQUIRE(a.size() == b.size());
          // A pair's contacts in time order, as the rounds run them.
          for (std::size_t i = 0; i < a.size(); ++i)
            for (std::size_t j = i + 1; j < a.size(); ++j)
              if (a[i].pair.a == a[j].pair.a && a[i].pair.b == a[j].pair.b) CHECK(a[i].contact.toi <= a[j].contact.toi);
          std::sort(a.begin(), a.end(), [&](const auto& x, const auto& y) { return key(x) < key(y); });
          std::sort(b.begin(), b.end(), [&](const auto& x, const auto& y) { return key(x) < key(y); });
          for (std::size_t i = 0; i < a.size(); ++i) CHECK(key(a[i]) == key(b[i]));
          if (!a.empty()) CHECK(times.narrow > 0.0);  // stage times are taken per round
          contacts_total += static_cast<long>(a.size());
        }
      }
    }
  }
  CHECK(contacts_total > 0);
}

}  // namespace pipeline_earliest_scheduler_test
