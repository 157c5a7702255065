// The truth through velocity changes (scene field `velocity_changes`), on dyadic cases
// whose answer is worked by hand: a contact that begins exactly at a jump, a jump that
// turns an approach into a separation exactly at contact distance (a touching instant),
// a tangency at a jump, a jump at t = 0+ and one just before the horizon, both bodies
// jumping, a jump at a wall reflection. Every number is a dyadic rational: times at a
// break (a jump, a tangency) are checked exactly, transversal crossings inside a piece
// to 1e-15 s (docs/truth.md: accurate to about 1e-15 of the horizon).
#include <ccd/motion/rotation.hpp>
#include <ccd/truth/ground_truth.hpp>
#include <ccd/truth/pair_contact.hpp>
#include <ccd/truth/rigid_truth.hpp>

#include <tests/ccd/scene/body_builder.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

namespace ccd_truth_velocity_changes_truth_test {

using ccd::Vec3;
using ccd::test::body;

namespace {

Approx crossing(double t) { return Approx(t).epsilon(0).margin(1e-15); }

// Bodies a (moving) and b; radii 1/2, so contact distance 1.
std::vector<ccd::ContactEvent> truth_of(const ccd::Scene& s) {
  const ccd::Trajectories traj(s);
  const auto events = ccd::compute_truth(traj);
  CHECK(events == ccd::compute_truth_all_pairs(traj));  // the truth's broad phase lost nothing
  return events;
}

ccd::Scene pair_scene(double horizon, ccd::Body a, ccd::Body b) {
  ccd::Scene s;
  s.horizon = horizon;
  s.bodies = {std::move(a), std::move(b)};
  return s;
}

}  // namespace

TEST_CASE("velocity changes: the truth is the hand-worked answer", "[truth][velocity_changes]") {
  const ccd::Body still = body(0.5, Vec3(2, 0, 0));
  SECTION("approach turned into a separation exactly at contact distance: a touching instant") {
    ccd::Body a = body(0.5, Vec3(0, 0, 0), Vec3(4, 0, 0));  // |d| = 1 at t = 1/4
    a.velocity_changes = {{0.25, Vec3(-1, 0, 0)}};
    const auto e = truth_of(pair_scene(1.0, a, still));
    REQUIRE(e.size() == 1);
    CHECK(e[0].enter == 0.25);
    CHECK(e[0].exit == 0.25);
  }
  SECTION("turned sideways at contact distance: a touching instant") {
    ccd::Body a = body(0.5, Vec3(0, 0, 0), Vec3(4, 0, 0));
    a.velocity_changes = {{0.25, Vec3(0, 2, 0)}};  // |d|^2 = 1 + 4 s^2 afterwards
    const auto e = truth_of(pair_scene(1.0, a, still));
    REQUIRE(e.size() == 1);
    CHECK(e[0].enter == 0.25);
    CHECK(e[0].exit == 0.25);
  }
  SECTION("contact begins exactly at a jump and goes on") {
    ccd::Body a = body(0.5, Vec3(0, 0, 0), Vec3(4, 0, 0));
    a.velocity_changes = {{0.25, Vec3(2, 0, 0)}};  // x = 1 + 2 (t - 1/4): leaves at x = 3, t = 5/4
    const auto e = truth_of(pair_scene(2.0, a, still));
    REQUIRE(e.size() == 1);
    CHECK(e[0].enter == 0.25);
    CHECK(e[0].exit == crossing(1.25));
  }
  SECTION("a jump stops an approach just short: no contact") {
    ccd::Body a = body(0.5, Vec3(0, 0, 0), Vec3(4, 0, 0));
    a.velocity_changes = {{0.25 - 0x1p-40, Vec3(0, 0, 0)}};  // stops 2^-38 short of contact
    CHECK(truth_of(pair_scene(1.0, a, still)).empty());
  }
  SECTION("tangent at a jump: a pass whose closest approach is the jump") {
    ccd::Body a = body(0.5, Vec3(1, -1, 0), Vec3(0, 4, 0));  // at (1, 0, 0) at t = 1/4, |d| = 1
    a.velocity_changes = {{0.25, Vec3(0, 8, 0)}};
    const auto e = truth_of(pair_scene(1.0, a, still));
    REQUIRE(e.size() == 1);
    CHECK(e[0].enter == 0.25);
    CHECK(e[0].exit == 0.25);
  }
  SECTION("a jump at t = 0+ pulls an overlapping pair apart") {
    ccd::Body a = body(0.5, Vec3(1, 0, 0), Vec3(1, 0, 0));  // touching at 0, sinking in
    a.velocity_changes = {{0x1p-30, Vec3(-1, 0, 0)}};     // back out at 2^-29
    const auto e = truth_of(pair_scene(1.0, a, still));
    REQUIRE(e.size() == 1);
    CHECK(e[0].enter == 0.0);
    CHECK(e[0].exit == crossing(0x1p-29));
  }
  SECTION("a jump at t = 0+ starts an approach") {
    ccd::Body a = body(0.5, Vec3(0, 0, 0));
    a.velocity_changes = {{0x1p-30, Vec3(4, 0, 0)}};
    const auto e = truth_of(pair_scene(1.0, a, still));
    REQUIRE(e.size() == 1);
    CHECK(e[0].enter == crossing(0.25 + 0x1p-30));
    CHECK(e[0].exit == crossing(0.75 + 0x1p-30));
  }
  SECTION("a jump just before the horizon: contact exactly at T") {
    ccd::Body a = body(0.5, Vec3(0.5, 0, 0));
    a.velocity_changes = {{1.0 - 0x1p-20, Vec3(0x1p19, 0, 0)}};  // covers the last 1/2 m in 2^-20 s
    const auto e = truth_of(pair_scene(1.0, a, still));
    REQUIRE(e.size() == 1);
    CHECK(e[0].enter == 1.0);
    CHECK(e[0].exit == 1.0);
  }
  SECTION("both bodies jump, at different times") {
    ccd::Body a = body(0.5, Vec3(0, 0, 0), Vec3(1, 0, 0));
    a.velocity_changes = {{0.5, Vec3(2, 0, 0)}};  // x_a = 1/2 + 2 (t - 1/2)
    ccd::Body b = body(0.5, Vec3(4, 0, 0));
    b.velocity_changes = {{0.25, Vec3(-2, 0, 0)}};  // x_b = 4 - 2 (t - 1/4)
    // From t = 1/2 the gap x_b - x_a is 3 - 4 (t - 1/2): 1 at t = 1, -1 at t = 3/2.
    const auto e = truth_of(pair_scene(2.0, a, b));
    REQUIRE(e.size() == 1);
    CHECK(e[0].enter == crossing(1.0));
    CHECK(e[0].exit == crossing(1.5));
  }
  SECTION("a jump under gravity: contact at the top of the new arc, tangent") {
    ccd::Scene s;
    s.horizon = 2.0;
    s.gravity = Vec3(0, -2, 0);
    ccd::Body a = body(0.5, Vec3(0, 0, 0), Vec3(0, 1, 0));  // at t = 1/2: y = 1/4, v = 0
    a.velocity_changes = {{0.5, Vec3(0, 1, 0)}};           // top 1/4 higher at t = 1
    ccd::Body b = body(0.5, Vec3(0, 1.5, 0), Vec3(0, 0, 0));
    b.acceleration = Vec3(0, 2, 0);  // cancels gravity: b stays at y = 3/2
    s.bodies = {a, b};
    const auto e = truth_of(s);
    REQUIRE(e.size() == 1);
    CHECK(e[0].enter == 1.0);
    CHECK(e[0].exit == 1.0);
  }
  SECTION("a jump at a wall reflection: contact begins as the body turns") {
    ccd::Scene s;
    s.horizon = 1.0;
    s.box = ccd::WallBox{Vec3(0, -4, -4), Vec3(4, 4, 4)};
    ccd::Body a = body(0.5, Vec3(3, 0, 0), Vec3(2, 0, 0));  // reaches the plane x = 3.5 at 1/4
    a.velocity_changes = {{0.25, Vec3(4, 0, 0)}};          // into the wall: reflects at once, -4
    ccd::Body b = body(0.5, Vec3(1.5, 0, 0));              // contact when x_a = 2.5, t = 1/2
    s.bodies = {a, b};
    const auto e = truth_of(s);
    REQUIRE(e.size() == 1);
    CHECK(e[0].enter == crossing(0.5));
    CHECK(e[0].exit == 1.0);  // the horizon
  }
}

TEST_CASE("velocity changes: pair_first_contact starts at the jump that begins a contact", "[truth][velocity_changes]") {
  ccd::Body a = body(0.5, Vec3(0, 0, 0), Vec3(4, 0, 0));
  a.velocity_changes = {{0.25, Vec3(2, 0, 0)}};
  const ccd::Trajectories traj(pair_scene(2.0, a, body(0.5, Vec3(2, 0, 0))));
  CHECK(ccd::pair_first_contact(traj, 0, 1, 0.0, 2.0) == 0.25);
  CHECK(ccd::pair_first_contact(traj, 0, 1, 0.5, 2.0) == 0.5);  // already in contact at the window's start
  CHECK_FALSE(ccd::pair_first_contact(traj, 0, 1, 1.5, 2.0).has_value());
}

TEST_CASE("velocity changes: rigid bodies, centres jump and orientations do not", "[truth][velocity_changes][rigid]") {
  // Two unit crates (half extents 1/2); crate 0 turns about x (a quarter turn keeps its
  // x extent), moves at 4 m/s and slows to 2 m/s at t = 1/4, when its face reaches crate
  // 1's: contact from 1/4 until x_0 = 3 at t = 5/4 (certified brackets hold both).
  ccd::Scene s;
  s.horizon = 2.0;
  s.shapes.push_back(ccd::make_box_shape(Vec3(0.5, 0.5, 0.5), "crate"));
  ccd::RigidBody spin;
  spin.shape = 0;
  spin.angular_velocity = Vec3(M_PI, 0, 0);
  ccd::Body moving = body(0, Vec3(0, 0, 0), Vec3(4, 0, 0));
  moving.velocity_changes = {{0.25, Vec3(2, 0, 0)}};
  s.add_rigid_body(moving, spin);
  ccd::RigidBody still;
  still.shape = 0;
  s.add_rigid_body(body(0, Vec3(2, 0, 0)), still);
  const ccd::Trajectories traj(s);
  const ccd::RigidMotion motion(s, traj);
  const ccd::RigidTruthResult truth = ccd::compute_rigid_truth(motion);
  REQUIRE(truth.events.size() == 1);
  CHECK_FALSE(truth.errors[0].grazing);
  CHECK(std::fabs(truth.events[0].enter - 0.25) <= truth.errors[0].enter_error + 1e-12);
  CHECK(std::fabs(truth.events[0].exit - 1.25) <= truth.errors[0].exit_error + 1e-12);
  CHECK(truth.errors[0].enter_error <= 1e-8);
  // The orientation is the one without the velocity change, bit for bit.
  ccd::Scene plain = s;
  plain.bodies[0].velocity_changes.clear();
  const ccd::Rotations with(s), without(plain);
  for (const double t : {0.0, 0.25, 0.5, 1.0, 1.75})
    CHECK(with.orientation(0, t).coeffs() == without.orientation(0, t).coeffs());
}

}  // namespace ccd_truth_velocity_changes_truth_test
