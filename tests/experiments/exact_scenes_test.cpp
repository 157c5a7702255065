// Every method (both registries) on scenes built from dyadic numbers whose contacts sit
// where the truth used to go wrong: tangencies and starts exactly at wall reflections,
// acceleration changes, t = 0 and T; tiny radii at 1024 m/s; clusters 1e5 from the
// origin. The truth of each scene is checked against its hand-worked answer first; then
// conservative methods miss nothing and every record's self-check is clean (one
// definition of touching for truth, samples and narrow phase). Space-time methods run
// under both schedulers (fixed steps and @earliest).
#include "../../experiments/method.hpp"
#include "../../experiments/runner.hpp"
#include "method_cover.hpp"

#include <ccd/truth/ground_truth.hpp>
#include <generators/registry.hpp>

#include <tests/ccd/scene/body_builder.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

namespace experiments_exact_scenes_test {

using ccd::Body;
using ccd::Vec3;
using ccd::test::body;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Expected {
  std::uint32_t a, b;
  double enter, exit;  // NaN: only "after enter" is known
};

struct Case {
  std::string name;
  ccd::Scene scene;
  std::vector<Expected> events;
};

// Pairs are placed 16 apart along z so that only the intended bodies meet.
std::vector<Case> cases() {
  std::vector<Case> out;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  {  // Breaks: a floor bounce and acceleration changes, in one box.
    ccd::Scene s;
    s.horizon = 2.0;
    s.box = ccd::WallBox{Vec3(0, 0, 0), Vec3(8, 8, 80)};
    // (0, 1): tangent exactly at a bounce, t = 1 + 2^-16.
    s.bodies.push_back(body(0.5, Vec3(1, 0.5 + 0x1p-13 + 0x1p-28 + 0x1p-45, 2), Vec3::Zero(), Vec3(0, -0x1p-12, 0)));
    s.bodies.push_back(body(0.5, Vec3(2, 0.5, 2)));
    // (2, 3): contact begins exactly at a bounce, t = 1.
    s.bodies.push_back(body(0.5, Vec3(1, 0.625, 18), Vec3(1, 0, 0), Vec3(0, -0.25, 0)));
    s.bodies.push_back(body(0.5, Vec3(3, 0.5, 18)));
    // (4, 5): tangent exactly at an acceleration change, t = 1/2.
    Body a = body(0.5, Vec3(3, 5, 34), Vec3(2, 0, 0));
    a.acceleration_changes.push_back({0.5, Vec3(0, 0.0625, 0)});
    s.bodies.push_back(a);
    s.bodies.push_back(body(0.5, Vec3(4, 4, 34)));
    // (6, 7): contact begins exactly at an acceleration change, t = 1/2.
    Body c = body(0.5, Vec3(4 - 0x1p-7, 5, 50), Vec3(0x1p-6, 0, 0));
    c.acceleration_changes.push_back({0.5, Vec3(0, -1, 0)});
    s.bodies.push_back(c);
    s.bodies.push_back(body(0.5, Vec3(4, 4, 50)));
    // (8, 9): tangent at t = 0; (10, 11): tangent at t = T = 2.
    s.bodies.push_back(body(0.5, Vec3(2, 4, 66)));
    s.bodies.push_back(body(0.5, Vec3(2, 5, 66), Vec3(1, 0, 0)));
    s.bodies.push_back(body(0.5, Vec3(6, 4, 76)));
    s.bodies.push_back(body(0.5, Vec3(4, 5, 76), Vec3(1, 0, 0)));
    out.push_back({"breaks", s,
                   {{8, 9, 0.0, 0.0},
                    {4, 5, 0.5, 0.5},
                    {6, 7, 0.5, nan},
                    {2, 3, 1.0, nan},
                    {0, 1, 1.0 + 0x1p-16, 1.0 + 0x1p-16},
                    {10, 11, 2.0, 2.0}}});
  }
  for (const double X : {0.0, 100000.0}) {  // tiny and fast, near and far from the origin
    ccd::Scene s;
    s.horizon = 1.0;
    const double r = 0x1p-10, R = 2 * r, v = 1024.0;
    auto pass = [&](double z, double y) {
      s.bodies.push_back(body(r, Vec3(X, X, X + z)));
      s.bodies.push_back(body(r, Vec3(X - 0.5 * v, y, X + z), Vec3(v, 0, 0)));
    };
    const double touch = X + R;
    pass(0, touch);                                     // (0, 1) tangent at 1/2
    pass(16, std::nextafter(touch, kInf));              // (2, 3) one ulp beyond: nothing
    pass(32, std::nextafter(touch, -kInf));             // (4, 5) one ulp inside: a crossing
    pass(48, X + 1.5 * R);                              // (6, 7) clear miss
    const double h = std::nextafter(touch, -kInf) - X;
    const double half = std::sqrt((R - h) * (R + h)) / v;
    out.push_back({X == 0.0 ? "tiny fast" : "tiny fast at 1e5", s,
                   {{4, 5, 0.5 - half, 0.5 + half}, {0, 1, 0.5, 0.5}}});
  }
  return out;
}

}  // namespace

TEST_CASE("exact scenes: the truth is the hand-worked answer", "[runner][exact]") {
  for (const Case& c : cases()) {
    INFO(c.name);
    const ccd::Trajectories traj(c.scene);
    const auto events = ccd::compute_truth(traj);
    REQUIRE(events.size() == c.events.size());
    for (std::size_t i = 0; i < events.size(); ++i) {
      INFO("event " << i);
      CHECK(events[i].a == c.events[i].a);
      CHECK(events[i].b == c.events[i].b);
      if (std::isnan(c.events[i].exit)) {
        CHECK(events[i].enter == c.events[i].enter);  // begins exactly at the break
        CHECK(events[i].exit > events[i].enter);
      } else {
        // A crossing: the hand-worked times (rounded) to a millionth of its width.
        const double margin = 1e-6 * (c.events[i].exit - c.events[i].enter) + 1e-15;
        CHECK(events[i].enter == Approx(c.events[i].enter).epsilon(0).margin(margin));
        CHECK(events[i].exit == Approx(c.events[i].exit).epsilon(0).margin(margin));
      }
      if (c.events[i].enter == c.events[i].exit) {
        CHECK(events[i].enter == c.events[i].enter);  // tangencies exactly, as points
        CHECK(events[i].exit == c.events[i].exit);
      }
    }
  }
}

TEST_CASE("exact scenes: conservative methods miss nothing, every self-check is clean", "[runner][exact]") {
  for (const Case& c : cases()) {
    const ccd::Trajectories traj(c.scene);
    const ccdlab::TruthIndex truth(ccd::compute_truth(traj));
    ccdlab::RunInput in;
    in.scene = &c.scene;
    const ccd::RigidMotion scene_motion(c.scene, traj);
    in.motion = &scene_motion;
    in.truth = &truth;
    in.acceleration_bound = c.scene.max_acceleration();
    std::vector<std::string> names = ccdlab::all_method_names();
    for (const std::string& m : ccdlab::scheduled_method_names()) {
      names.push_back(m);
      names.push_back(m + ":stale=0.01");  // refined often: the pairs' own bounds
      names.push_back(m + ":stale=0.01,align=0,refresh_bodies=1");  // bodies refreshed, each on its own clock
      names.push_back(m + ":reach=64");  // speed-adapted windows: fast bodies on short ones
      names.push_back(m + ":reach=64,stale=0.01,align=0,refresh_bodies=1");
    }
#ifdef CCDLAB_SANITIZED
    // Under the sanitizers (CI's memory-error pass, about 10x slower) one dt per method;
    // the Release build runs all three.
    const std::vector<double> dts = {0.0625};
#else
    const std::vector<double> dts = {0.0625, 0.1, 0.03};
#endif
    for (const std::string& name : ccdlab::test::sanitizer_cover(names)) {
      const ccdlab::MethodSpec m = ccdlab::parse_method(name);
      for (const double dt : dts) {
        INFO(c.name << " " << name << " dt " << dt);
        const ccdlab::RunRecord r = ccdlab::run_method(in, m, dt);
        CHECK(r.self_check_unexpected == 0);
        CHECK(r.self_check_undetected == 0);
        if (r.conservative && r.continuous) CHECK(r.bodies.missed == 0);
        // dt = 1/16 puts a sample on every tangency at 0, 1/2 and T: a discrete method
        // sees each of them (they touch exactly at the sample).
        if (!r.continuous && dt == 0.0625 && c.name == "breaks") CHECK(r.bodies.detected + r.bodies.initial_contacts >= 4);
      }
    }
  }
}

}  // namespace experiments_exact_scenes_test
