// The certified rigid ground truth: brackets that hold the exact times on spinning cases
// with closed-form contacts, the flags for grazing contacts, and the cross-path test
// against the exact sphere solver.
#include <ccd/truth/rigid_truth.hpp>

#include "../scene/rigid_scenes.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

namespace ccd_truth_rigid_truth_test {

using ccd::Vec3;

namespace {

struct World {
  ccd::Scene scene;
  ccd::Trajectories traj;
  std::unique_ptr<ccd::RigidMotion> rigid;
  ccd::RigidTruthResult truth(ccd::RigidTruthOptions o = {}) {
    traj = ccd::Trajectories(scene);
    rigid = std::make_unique<ccd::RigidMotion>(scene, traj);
    return ccd::compute_rigid_truth(*rigid, o);
  }
};

// The spinning stick and resting ball of rigid_scenes.hpp: in contact while |cos(theta)| <= 1/4.
World spinning_stick(double omega, double horizon, std::vector<ccd::AngularVelocityChange> changes = {}) {
  World w;
  w.scene = ccd::test::spinning_stick_scene(omega, horizon, std::move(changes));
  return w;
}

void check_event(const ccd::ContactEvent& e, const ccd::EventError& err, double enter, double exit) {
  CHECK_FALSE(err.grazing);
  CHECK(std::fabs(e.enter - enter) <= err.enter_error);
  CHECK(std::fabs(e.exit - exit) <= err.exit_error);
  CHECK(err.enter_error < 1e-6);
  CHECK(err.exit_error < 1e-6);
}

}  // namespace

TEST_CASE("rigid truth: a stick spinning through a resting ball, zero translation", "[truth][rigid]") {
  // Four half turns over [0, 4] at omega = pi: contact on [k + c, k + 1 - c], c = acos(1/4)/pi.
  World w = spinning_stick(M_PI, 4.0);
  const ccd::RigidTruthResult r = w.truth();
  const double c = std::acos(0.25) / M_PI;
  REQUIRE(r.events.size() == 4);
  REQUIRE(r.errors.size() == 4);
  for (int k = 0; k < 4; ++k) {
    CHECK(r.events[k].a == 0);
    CHECK(r.events[k].b == 1);
    check_event(r.events[k], r.errors[k], k + c, k + 1 - c);
  }
  CHECK(r.stats.grazing == 0);
}

TEST_CASE("rigid truth: at an angular-velocity change, at t = 0 and at the horizon", "[truth][rigid]") {
  SECTION("rest until 1/2, then spin at pi: contact on [1/2 + c, 3/2 - c]") {
    World w = spinning_stick(0.0, 1.75, {{0.5, Vec3(0, 0, M_PI)}});
    const ccd::RigidTruthResult r = w.truth();
    const double c = std::acos(0.25) / M_PI;
    REQUIRE(r.events.size() == 1);
    check_event(r.events[0], r.errors[0], 0.5 + c, 1.5 - c);
  }
  SECTION("in contact from t = 0 to the horizon: enter 0 and exit T, both exact") {
    World w = spinning_stick(0.0, 1.0);
    w.scene.bodies[1].position = Vec3(0.5, 0.125, 0);  // 1/8 from the axis: overlapping by 1/16
    const ccd::RigidTruthResult r = w.truth();
    REQUIRE(r.events.size() == 1);
    CHECK(r.events[0].enter == 0.0);
    CHECK(r.events[0].exit == 1.0);
    CHECK(r.errors[0].enter_error == 0.0);
    CHECK(r.errors[0].exit_error == 0.0);
  }
  SECTION("a ball sliding along the stick at exactly touching distance (dyadic) is grazing") {
    World w = spinning_stick(0.0, 1.0);
    w.scene.bodies[1].position = Vec3(-0.5, 0.1875, 0);  // 3/16 = 1/16 + 1/8 from the axis
    w.scene.bodies[1].velocity = Vec3(1, 0, 0);
    const ccd::RigidTruthResult r = w.truth();
    REQUIRE(r.events.size() == 1);
    CHECK(r.errors[0].grazing);
    CHECK(r.stats.grazing == 1);
  }
  SECTION("a box reached exactly at the horizon: exit within its bracket of T") {
    World w;
    w.scene.horizon = 1.0;
    w.scene.shapes.push_back(ccd::make_box_shape(Vec3(0.5, 0.5, 0.5), "crate"));
    ccd::RigidBody box;
    box.shape = 0;
    box.angular_velocity = Vec3(0, 0, 0.0);
    w.scene.add_rigid_body(ccd::Body{}, box);
    ccd::Body ball;
    ball.radius = 0.25;
    ball.position = Vec3(1.25, 0, 0);  // touching the face x = 1/2 at t = 1/2, then inside
    ball.velocity = Vec3(-1.0, 0, 0);
    ball.position.x() = 1.25;
    w.scene.add_rigid_body(ball, ccd::RigidBody{});
    const ccd::RigidTruthResult r = w.truth();
    REQUIRE(r.events.size() == 1);
    CHECK(std::fabs(r.events[0].enter - 0.5) <= r.errors[0].enter_error);
    CHECK(r.events[0].exit == 1.0);
  }
}

TEST_CASE("cross-path: on sphere scenes the generic bracket search agrees with the exact truth", "[truth][rigid]") {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  ccd::Scene s;
  s.horizon = 2.0;
  s.gravity = Vec3(0, -2, 0);
  s.box = ccd::WallBox{Vec3(0, 0, 0), Vec3(6, 6, 6)};
  for (int i = 0; i < 60; ++i) {
    ccd::Body b;
    b.radius = 0.2 + 0.2 * u(rng);
    b.position = Vec3(0.5 + 5 * u(rng), 0.5 + 5 * u(rng), 0.5 + 5 * u(rng));
    b.velocity = Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5) * 4.0;
    s.bodies.push_back(b);
  }
  const ccd::Trajectories traj(s);
  const std::vector<ccd::ContactEvent> exact = ccd::compute_truth(traj);
  const ccd::RigidMotion motion(s, traj);
  ccd::RigidTruthOptions o;
  o.generic_spheres = true;
  const ccd::RigidTruthResult generic = ccd::compute_rigid_truth(motion, o);
  REQUIRE(exact.size() > 20);
  // Every exact event has one generic event of its pair whose brackets hold its times;
  // every generic event is matched (tangent exact events may come out grazing).
  std::vector<bool> used(generic.events.size(), false);
  for (const ccd::ContactEvent& e : exact) {
    bool found = false;
    for (std::size_t k = 0; k < generic.events.size() && !found; ++k) {
      const ccd::ContactEvent& g = generic.events[k];
      const ccd::EventError& err = generic.errors[k];
      if (used[k] || g.a != e.a || g.b != e.b) continue;
      const double slack = 1e-12;
      if (std::fabs(g.enter - e.enter) <= err.enter_error + slack && std::fabs(g.exit - e.exit) <= err.exit_error + slack) {
        used[k] = found = true;
        if (e.exit > e.enter + 1e-6) CHECK_FALSE(err.grazing);
      }
    }
    INFO("pair " << e.a << "-" << e.b << " [" << e.enter << ", " << e.exit << "]");
    CHECK(found);
  }
  for (std::size_t k = 0; k < generic.events.size(); ++k) {
    INFO("generic event " << generic.events[k].a << "-" << generic.events[k].b << " at " << generic.events[k].enter);
    CHECK((used[k] || generic.errors[k].grazing));
  }
}

}  // namespace ccd_truth_rigid_truth_test
