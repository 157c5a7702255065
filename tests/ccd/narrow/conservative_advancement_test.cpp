// Conservative advancement on rigid, spinning bodies: never a miss, and the reported
// bracket [toi, toi + toi_error] holds the exact first contact.
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/narrow/conservative_advancement.hpp>
#include <ccd/narrow/narrow_table.hpp>
#include <ccd/narrow/sphere_sphere_narrow.hpp>
#include <ccd/queries/convex_distance.hpp>

#include "../scene/rigid_scenes.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

namespace ccd_narrow_conservative_advancement_test {

using ccd::Vec3;

namespace {

struct World {
  ccd::Scene scene;
  ccd::Trajectories traj;
  std::unique_ptr<ccd::RigidMotion> rigid;
  void build() {
    traj = ccd::Trajectories(scene);
    rigid = std::make_unique<ccd::RigidMotion>(scene, traj);
  }
  ccd::ContactResult step(double t0, double t1, bool sample = false) const {
    ccd::NarrowInput in;
    in.t0 = t0;
    in.t1 = t1;
    in.sample = sample;
    in.motion = rigid.get();
    return ccd::narrow_table().find(scene.kind(0), scene.kind(1))(in, 0, 1);
  }
  /// The first of the times k / 4096 in [0, 1] at which GJK certifies that bodies 0 and 1
  /// overlap; -1 when none does.
  double first_sampled_overlap() const {
    for (int k = 0; k <= 4096; ++k) {
      const double t = k / 4096.0;
      const ccd::Pose pa = rigid->pose(0, t), pb = rigid->pose(1, t);
      const ccd::ConvexDistance d =
          ccd::convex_distance(rigid->proxy(0), {pa.centre, pa.rotation}, rigid->proxy(1), {pb.centre, pb.rotation});
      if (d.status == ccd::ConvexDistance::Status::Overlapping) return t;
    }
    return -1.0;
  }
};

// The spinning stick and resting ball of rigid_scenes.hpp, over 4 s.
World spinning_stick(double omega, std::vector<ccd::AngularVelocityChange> changes = {}) {
  World w;
  w.scene = ccd::test::spinning_stick_scene(omega, 4.0, std::move(changes));
  w.build();
  return w;
}

void check_brackets(const ccd::ContactResult& r, double exact) {
  REQUIRE(r.status == ccd::QueryStatus::Hit);
  CHECK(r.toi <= exact);
  CHECK(r.toi + r.toi_error >= exact);
}

}  // namespace

TEST_CASE("a stick spinning through a resting sphere with zero translation is found", "[narrow][ca]") {
  // The stick's axis is (cos wt, sin wt, 0); the ball's centre is 3/4 cos(wt) from it, so
  // the first contact is at cos(wt) = (1/16 + 1/8) / (3/4) = 1/4.
  const double omega = M_PI;
  const World w = spinning_stick(omega);
  CHECK(w.scene.kind(0) == ccd::ShapeKind::Capsule);
  const double exact = std::acos(0.25) / omega;
  const ccd::ContactResult r = w.step(0.0, 1.0);
  check_brackets(r, exact);
  CHECK(r.toi_error < 1e-6);
  SECTION("the step ending before the contact: Miss") { CHECK(w.step(0.0, exact * 0.99).status == ccd::QueryStatus::Miss); }
  SECTION("a step starting inside the contact: Overlapping at its start") {
    const ccd::ContactResult o = w.step(0.5, 1.0);
    CHECK(o.status == ccd::QueryStatus::Overlapping);
    CHECK(o.toi == 0.5);
  }
  SECTION("sample tests") {
    CHECK(w.step(0.25, 0.25, true).status == ccd::QueryStatus::Miss);
    CHECK(w.step(0.5, 0.5, true).status == ccd::QueryStatus::Overlapping);
  }
  SECTION("fast spin: the stick turns 60 times over the step and is still caught") {
    const World fast = spinning_stick(120 * M_PI);
    check_brackets(fast.step(0.0, 1.0), std::acos(0.25) / (120 * M_PI));
  }
}

TEST_CASE("contact at an angular-velocity change, at t = 0 and at the step's end", "[narrow][ca]") {
  SECTION("the stick rests until t = 1/2, then spins at pi: contact at 1/2 + acos(1/4) / pi") {
    const World w = spinning_stick(0.0, {{0.5, Vec3(0, 0, M_PI)}});
    check_brackets(w.step(0.0, 2.0), 0.5 + std::acos(0.25) / M_PI);
    CHECK(w.step(0.0, 0.5).status == ccd::QueryStatus::Miss);
  }
  SECTION("touching at t = 0 (dyadic): the ball 3/16 from the resting stick's axis") {
    // The ball centre 3/16 above the stick's axis at x = 1/2: touching (dyadic) at t = 0.
    World w = spinning_stick(0.0);
    w.scene.bodies[1].position = Vec3(0.5, 0.1875, 0);
    w.build();
    const ccd::ContactResult r = w.step(0.0, 1.0);
    REQUIRE(r.found());
    CHECK(r.toi == 0.0);
  }
  SECTION("a box face reached exactly at the step's end (dyadic: 2 - 5/4 t = 3/4 at t = 1)") {
    World w;
    w.scene.horizon = 2.0;
    w.scene.shapes.push_back(ccd::make_box_shape(Vec3(0.5, 0.5, 0.5), "crate"));
    ccd::RigidBody box;
    box.shape = 0;
    w.scene.add_rigid_body(ccd::Body{}, box);
    ccd::Body ball;
    ball.radius = 0.25;
    ball.position = Vec3(2, 0, 0);
    ball.velocity = Vec3(-1.25, 0, 0);
    w.scene.add_rigid_body(ball, ccd::RigidBody{});
    w.build();
    const ccd::ContactResult r = w.step(0.0, 1.0);
    REQUIRE(r.found());
    CHECK(r.toi <= 1.0);
    CHECK(w.step(0.0, 0.96875).status == ccd::QueryStatus::Miss);  // 31/32: 1/32 x 5/4 short
  }
  SECTION("a near miss passing 1/4 away is a certified Miss") {
    World w = spinning_stick(0.0);
    w.scene.bodies[1].position = Vec3(-3, 0.4375, 0);  // 7/16 above the axis: gap 1/4
    w.scene.bodies[1].velocity = Vec3(2, 0, 0);
    w.build();
    CHECK(w.step(0.0, 3.0).status == ccd::QueryStatus::Miss);
  }
}

TEST_CASE("cross-path: on sphere pairs conservative advancement brackets the exact solver", "[narrow][ca]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // Draws in a fixed order, z first (the order of a function's arguments is unspecified:
  // GCC and clang would draw different scenes from the same seed).
  const auto draw = [&] {
    const double z = u(rng), y = u(rng), x = u(rng);
    return Vec3(x, y, z);
  };
  int hits = 0;
  for (int trial = 0; trial < 200; ++trial) {
    World w;
    w.scene.horizon = 1.0;
    w.scene.gravity = Vec3(0, -1, 0) * (trial % 2);
    for (int k = 0; k < 2; ++k) {
      ccd::Body b;
      b.radius = 0.25 + 0.25 * std::fabs(u(rng));
      b.position = draw() * 0.75 + Vec3(4.0 * k, 0, 0);
      b.velocity = draw() * 2.0 + Vec3(k ? -3.0 : 3.0, 0, 0);
      w.scene.bodies.push_back(b);
    }
    w.build();
    ccd::NarrowInput in;
    in.t0 = 0.0;
    in.t1 = 1.0;
    in.motion = w.rigid.get();
    const ccd::ContactResult exact = ccd::sphere_sphere_narrow(in, 0, 1);
    const ccd::ContactResult ca = ccd::conservative_advancement(in, 0, 1);
    REQUIRE(ca.found() == exact.found());
    if (!exact.found()) continue;
    ++hits;
    CHECK(ca.toi <= exact.toi + 1e-12);
    CHECK(ca.toi + ca.toi_error >= exact.toi - 1e-12);
    if (exact.status == ccd::QueryStatus::Hit) CHECK(ca.toi_error < 1e-6);
  }
  CHECK(hits > 30);
}

TEST_CASE("the spin-axis bound: bodies turning about axes through their long side", "[narrow][ca]") {
  SECTION("a stick spinning about its own axis slides onto a ball: contact at 13/8 exactly") {
    // Stick along x spinning about x (its core stays on the axis: the spin moves no core
    // point), moving at 1/2 along y towards a ball at (0, 1, 0): gap 1 - 1/16 - 1/8 -
    // t/2 = 0 at t = 13/8.
    World w;
    w.scene.horizon = 4.0;
    w.scene.shapes.push_back(ccd::make_capsule_shape(1.0, 1.0 / 16, "stick"));
    ccd::RigidBody stick;
    stick.shape = 0;
    stick.angular_velocity = Vec3(8, 0, 0);
    ccd::Body moving;
    moving.velocity = Vec3(0, 0.5, 0);
    w.scene.add_rigid_body(moving, stick);
    ccd::Body ball;
    ball.radius = 1.0 / 8;
    ball.position = Vec3(0, 1, 0);
    w.scene.add_rigid_body(ball, ccd::RigidBody{});
    w.build();
    check_brackets(w.step(0.0, 4.0), 1.625);
    CHECK(w.step(0.0, 1.5).status == ccd::QueryStatus::Miss);
  }
  SECTION("a plate spinning about its long axis, random balls: never after the sampled first contact") {
    // A plate (1 x 1/2 x 1/32 half extents) turning at 12 rad/s about x, balls passing
    // near it; the first contact is located by dense sampling of the certified distance
    // and the advancement must report a contact no later than it.
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int hits = 0;
    for (int trial = 0; trial < 60; ++trial) {
      World w;
      w.scene.horizon = 1.0;
      w.scene.shapes.push_back(ccd::make_box_shape(Vec3(1, 0.5, 1.0 / 32), "plate"));
      ccd::RigidBody plate;
      plate.shape = 0;
      plate.angular_velocity = Vec3(12, 0, 0);
      w.scene.add_rigid_body(ccd::Body{}, plate);
      ccd::Body ball;
      ball.radius = 1.0 / 16;
      ball.position = Vec3(u(rng), 1.5 + 0.5 * u(rng), 0.25 * u(rng));
      ball.velocity = Vec3(0.25 * u(rng), -1.0 - 0.5 * std::fabs(u(rng)), 0.25 * u(rng));
      w.scene.add_rigid_body(ball, ccd::RigidBody{});
      w.build();
      const ccd::ContactResult r = w.step(0.0, 1.0);
      const double first = w.first_sampled_overlap();
      if (first < 0.0) continue;
      ++hits;
      REQUIRE(r.found());
      CHECK(r.toi <= first);
    }
    CHECK(hits > 20);
  }
}

TEST_CASE("the relative bound: spinning sticks and boxes against moving balls and crates", "[narrow][ca]") {
  // The relative (body-frame) bound advances by the speed of the other body's points about
  // the spin axis; an overestimate steps past the first contact. Random spinning sticks and
  // crates, moving, against balls and spinning crates passing near their axes: the
  // advancement must report a contact no later than the first sampled certified overlap.
  std::mt19937_64 rng(1313);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto unit = [&] {
    Vec3 v;
    do v = Vec3(u(rng), u(rng), u(rng));
    while (v.squaredNorm() > 1.0 || v.squaredNorm() < 1e-2);
    return v.normalized();
  };
  int hits = 0;
  for (int trial = 0; trial < 120; ++trial) {
    World w;
    w.scene.horizon = 1.0;
    w.scene.shapes.push_back(trial % 2 ? ccd::make_capsule_shape(1.0, 0.05, "stick")
                                       : ccd::make_box_shape(Vec3(1.0, 0.2, 0.1), "crate"));
    w.scene.shapes.push_back(ccd::make_box_shape(Vec3(0.1, 0.08, 0.05), "small"));
    ccd::RigidBody spinning;
    spinning.shape = 0;
    spinning.angular_velocity = (4.0 + 20.0 * std::fabs(u(rng))) * unit();
    ccd::Body a;
    a.velocity = 0.5 * u(rng) * unit();
    w.scene.add_rigid_body(a, spinning);
    ccd::Body b;
    b.position = (0.2 + 1.2 * std::fabs(u(rng))) * unit();
    b.velocity = 0.5 * u(rng) * unit();
    if (trial % 3 == 0) {
      b.radius = 0.08;
      w.scene.add_rigid_body(b, ccd::RigidBody{});
    } else {
      ccd::RigidBody small;
      small.shape = 1;
      small.angular_velocity = 6.0 * u(rng) * unit();
      w.scene.add_rigid_body(b, small);
    }
    w.build();
    const double first = w.first_sampled_overlap();
    if (first <= 0.0) continue;
    ++hits;
    const ccd::ContactResult r = w.step(0.0, 1.0);
    REQUIRE(r.found());
    CHECK(r.toi <= first);
  }
  CHECK(hits > 30);
}

}  // namespace ccd_narrow_conservative_advancement_test
