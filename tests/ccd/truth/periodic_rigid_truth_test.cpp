// The certified rigid truth of scenes that wrap around: against dyadic cases worked out by
// hand (across the seam, at the crossing instant, at t = 0 and the horizon, across a
// corner), against the central copy of the same scene tiled 3 x 3 x 3 without walls (event
// for event, within the certified brackets; all pairs of the tiling, no broad phase), and
// the generic solver with images against the exact periodic sphere truth (the cross-path
// test).
#include "../scene/periodic_rigid_scenes.hpp"

#include <ccd/motion/rigid_motion.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/truth/rigid_truth.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <tuple>

namespace ccd_truth_periodic_rigid_truth_test {

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

// The certified truth of the tiled scene (no wrapping) for the central copy, as events of
// the periodic scene (as ccd::test::central_events: pair (p, q), p < q, is the central
// copy of p against every copy of q), with their errors, sorted by (a, b, enter). Each such
// pair of the tiled scene is searched over the whole horizon (pair_bracket_events, no
// broad phase): all pairs, so the periodic truth's broad phase is checked too, and the
// tiled pairs that do not involve the central copy cost nothing.
std::vector<Bracketed> central_truth(const ccd::test::Tiling& t, std::size_t n) {
  const ccd::Trajectories traj(t.scene);
  const ccd::RigidMotion motion(t.scene, traj);
  const double T = t.scene.horizon;
  const std::size_t copies = t.scene.bodies.size() / n;
  std::vector<Bracketed> out;
  std::vector<ccd::ContactEvent> events;
  std::vector<ccd::EventError> errors;
  for (std::size_t p = 0; p < n; ++p)
    for (std::size_t q = p + 1; q < n; ++q)
      for (std::size_t c = 0; c < copies; ++c) {
        const auto x = static_cast<std::uint32_t>(t.central * n + p), y = static_cast<std::uint32_t>(c * n + q);
        events.clear();
        errors.clear();
        ccd::pair_bracket_events(motion, std::min(x, y), std::max(x, y), 0.0, T, std::ldexp(T, -30), 1000000, events,
                                 errors);
        for (std::size_t k = 0; k < events.size(); ++k)
          out.push_back({{static_cast<std::uint32_t>(p), static_cast<std::uint32_t>(q), events[k].enter, events[k].exit},
                         errors[k]});
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
      require_same(sorted_by_pair(r->truth), central_truth(t, c.scene.bodies.size()));
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
  INFO("seed " << seed << ": " << r->truth.events.size() << " events, " << wraps << " wraps");
  CHECK(wraps >= 10);
  CHECK(r->truth.events.size() >= 8);
  CHECK(r->truth.stats.grazing == 0);
  require_same(sorted_by_pair(r->truth), central_truth(ccd::test::tiled_rigid(s), s.bodies.size()));
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
#ifdef CCDLAB_SANITIZED
  const ccd::Scene s = ccd::test::random_periodic_scene(4, 40);
#else
  const ccd::Scene s = ccd::test::random_periodic_scene(4, 60);
#endif
  const auto g = solve(s, generic);
  const std::vector<Bracketed> x = sorted_by_pair(g->truth);
  std::vector<Bracketed> y = exact_of(s);
  std::sort(y.begin(), y.end(), [](const Bracketed& p, const Bracketed& q) {
    return std::tie(p.event.a, p.event.b, p.event.enter) < std::tie(q.event.a, q.event.b, q.event.enter);
  });
  CHECK(y.size() >= 5);
  require_same(x, y);
}

}  // namespace ccd_truth_periodic_rigid_truth_test
