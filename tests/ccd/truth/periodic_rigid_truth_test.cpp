// The certified rigid truth of scenes that wrap around: against dyadic cases worked out by
// hand (across the seam, at the crossing instant, at t = 0 and the horizon, across a
// corner), against the central copy of the same scene tiled 3 x 3 x 3 without walls (event
// for event, within the certified brackets), and the generic solver with images against
// the exact periodic sphere truth (the cross-path test).
#include "../scene/periodic_rigid_scenes.hpp"

#include <ccd/motion/rigid_motion.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/truth/rigid_truth.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <tuple>

namespace {

struct Bracketed {
  ccd::ContactEvent event;
  ccd::EventError error;
};

struct Solved {
  ccd::Trajectories traj;
  std::unique_ptr<ccd::RigidMotion> motion;
  ccd::RigidTruthResult truth;
};

std::unique_ptr<Solved> solve(const ccd::Scene& s, ccd::RigidTruthOptions o = {}) {
  auto r = std::make_unique<Solved>();
  r->traj = ccd::Trajectories(s);
  r->motion = std::make_unique<ccd::RigidMotion>(s, r->traj);
  r->truth = ccd::compute_rigid_truth(*r->motion, o);
  return r;
}

std::vector<Bracketed> sorted_by_pair(const ccd::RigidTruthResult& t) {
  std::vector<Bracketed> out;
  for (std::size_t i = 0; i < t.events.size(); ++i) out.push_back({t.events[i], t.errors[i]});
  std::sort(out.begin(), out.end(), [](const Bracketed& x, const Bracketed& y) {
    return std::tie(x.event.a, x.event.b, x.event.enter) < std::tie(y.event.a, y.event.b, y.event.enter);
  });
  return out;
}

// The tiled truth's events of the central copy, as events of the periodic scene (as
// ccd::test::central_events), with their errors, sorted by (a, b, enter).
std::vector<Bracketed> central(const ccd::RigidTruthResult& tiled, std::size_t n, std::uint32_t copy) {
  std::vector<Bracketed> out;
  const auto m = static_cast<std::uint32_t>(n);
  for (std::size_t i = 0; i < tiled.events.size(); ++i) {
    const ccd::ContactEvent& e = tiled.events[i];
    const std::uint32_t ox = e.a % m, oy = e.b % m;
    if (ox == oy || (ox < oy ? e.a / m : e.b / m) != copy) continue;
    out.push_back({{std::min(ox, oy), std::max(ox, oy), e.enter, e.exit}, tiled.errors[i]});
  }
  std::sort(out.begin(), out.end(), [](const Bracketed& x, const Bracketed& y) {
    return std::tie(x.event.a, x.event.b, x.event.enter) < std::tie(y.event.a, y.event.b, y.event.enter);
  });
  return out;
}

// Two certified truths of the same motion agree when every event's brackets meet: both
// hold the exact time. The slack covers the rounding of positions evaluated from
// different pieces (pieces end at the seam in one scene, not in the other): ulps of the
// coordinates, far below a picosecond at these speeds.
constexpr double kSlack = 1e-12;

void require_same(const std::vector<Bracketed>& x, const std::vector<Bracketed>& y) {
  REQUIRE(x.size() == y.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const ccd::ContactEvent& p = x[i].event;
    const ccd::ContactEvent& q = y[i].event;
    INFO("event " << i << ": (" << p.a << ", " << p.b << ") [" << p.enter << " +- " << x[i].error.enter_error << ", "
                  << p.exit << " +- " << x[i].error.exit_error << "] vs (" << q.a << ", " << q.b << ") [" << q.enter
                  << " +- " << y[i].error.enter_error << ", " << q.exit << " +- " << y[i].error.exit_error << "]");
    CHECK(p.a == q.a);
    CHECK(p.b == q.b);
    CHECK(std::fabs(p.enter - q.enter) <= x[i].error.enter_error + y[i].error.enter_error + kSlack);
    CHECK(std::fabs(p.exit - q.exit) <= x[i].error.exit_error + y[i].error.exit_error + kSlack);
    CHECK(x[i].error.grazing == y[i].error.grazing);
  }
}

}  // namespace

TEST_CASE("periodic rigid truth: dyadic cases across the seam", "[truth][periodic][rigid]") {
  for (const ccd::test::RigidPeriodicCase& c : ccd::test::rigid_periodic_cases()) {
    SECTION(c.name) {
      REQUIRE_NOTHROW(ccd::validate_scene(c.scene, "case.json"));
      const auto r = solve(c.scene);
      REQUIRE(r->truth.events.size() == 1);
      const ccd::ContactEvent& e = r->truth.events[0];
      const ccd::EventError& err = r->truth.errors[0];
      INFO("[" << e.enter << " +- " << err.enter_error << ", " << e.exit << " +- " << err.exit_error << "]");
      CHECK(e.a == c.expected.a);
      CHECK(e.b == c.expected.b);
      CHECK(err.grazing == c.grazing);
      // The brackets hold the exact times (dyadic: exact in binary) and are narrow.
      CHECK(std::fabs(e.enter - c.expected.enter) <= err.enter_error);
      CHECK(std::fabs(e.exit - c.expected.exit) <= err.exit_error);
      CHECK(err.enter_error < 1e-6);
      CHECK(err.exit_error < 1e-6);
      // In contact at t = 0 or at the horizon with a certified overlap: that end is exact.
      if (c.expected.enter == 0.0) CHECK((e.enter == 0.0 && err.enter_error == 0.0));
      if (c.expected.exit == c.scene.horizon && !c.grazing) CHECK((e.exit == c.scene.horizon && err.exit_error == 0.0));
      // The central copy of the tiled scene (no wrapping) finds the same event.
      const ccd::test::Tiling t = ccd::test::tiled_rigid(c.scene);
      require_same(sorted_by_pair(r->truth), central(solve(t.scene)->truth, c.scene.bodies.size(), t.central));
    }
  }
}

TEST_CASE("periodic rigid truth equals the central copy of the 3 x 3 x 3 tiling, event for event",
          "[truth][periodic][rigid]") {
  // Spinning sticks, crates, plates and balls, one tumbling freely, angular-velocity
  // changes; the horizon keeps every central body among the neighbouring tiles.
  const std::uint64_t seed = GENERATE(1, 2);
  const ccd::Scene s = ccd::test::random_rigid_periodic_scene(seed, 24);
  REQUIRE_NOTHROW(ccd::validate_scene(s, "random.json"));
  const auto r = solve(s);
  // A test that never wraps or never touches tests nothing.
  std::size_t wraps = 0;
  for (std::size_t i = 0; i < r->traj.size(); ++i) wraps += r->traj.pieces(i).size() - 1;
  const ccd::test::Tiling t = ccd::test::tiled_rigid(s);
  const auto tiled = solve(t.scene);
  INFO("seed " << seed << ": " << r->truth.events.size() << " events, " << wraps << " wraps");
  CHECK(wraps >= 10);
  CHECK(r->truth.events.size() >= 8);
  CHECK(r->truth.stats.grazing == 0);
  require_same(sorted_by_pair(r->truth), central(tiled->truth, s.bodies.size(), t.central));
}

TEST_CASE("periodic rigid truth: the generic solver with images agrees with the exact sphere truth",
          "[truth][periodic][rigid]") {
  ccd::RigidTruthOptions generic;
  generic.generic_spheres = true;
  auto exact_of = [](const ccd::Scene& s) {
    const auto r = solve(s);
    std::vector<Bracketed> out;
    for (const ccd::ContactEvent& e : r->truth.events) out.push_back({e, {}});
    return out;
  };
  for (const ccd::test::PeriodicCase& c : ccd::test::periodic_cases()) {
    // A tangent touch (enter == exit) lies inside the search's distance band for a while,
    // where separation and touching alternate: several grazing slivers, each certified
    // only as "maybe". The cross-path compares transversal contacts.
    if (std::any_of(c.expected.begin(), c.expected.end(), [](const ccd::ContactEvent& e) { return e.enter == e.exit; }))
      continue;
    INFO(c.name);
    const auto g = solve(c.scene, generic);
    const std::vector<Bracketed> x = sorted_by_pair(g->truth), y = exact_of(c.scene);
    REQUIRE(x.size() == y.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      // Tangent cases touch without overlap: the generic solver flags them grazing, with
      // the exact time inside the bracket.
      CHECK(x[i].event.a == y[i].event.a);
      CHECK(x[i].event.b == y[i].event.b);
      CHECK(std::fabs(x[i].event.enter - y[i].event.enter) <= x[i].error.enter_error + kSlack);
      CHECK(std::fabs(x[i].event.exit - y[i].event.exit) <= x[i].error.exit_error + kSlack);
    }
  }
  const ccd::Scene s = ccd::test::random_periodic_scene(4, 60);
  const auto g = solve(s, generic);
  const std::vector<Bracketed> x = sorted_by_pair(g->truth);
  std::vector<Bracketed> y = exact_of(s);
  std::sort(y.begin(), y.end(), [](const Bracketed& p, const Bracketed& q) {
    return std::tie(p.event.a, p.event.b, p.event.enter) < std::tie(q.event.a, q.event.b, q.event.enter);
  });
  CHECK(y.size() >= 5);
  require_same(x, y);
}
