// sticks, plates, crates, rocks: the shapes they promise, spin within spin_max, spheres
// mixed in by fraction, and scenes the rigid truth and the runner accept.
#include "generator_test_support.hpp"

#include <ccd/truth/rigid_truth.hpp>

#include <catch2/catch.hpp>
#include <cmath>

namespace generators_spinning_test {

using ccdlab::testing::make;
using nlohmann::json;

TEST_CASE("spinning generators: shapes, spin and sphere fraction", "[generators][rigid]") {
  const ccd::Scene sticks = make("sticks", {{"bodies", 200}, {"seed", 3}, {"size", 0.5}, {"elongation", 20}});
  REQUIRE(sticks.shapes.size() == 1);
  CHECK(sticks.shapes[0].kind == ccd::ShapeKind::Capsule);
  CHECK(sticks.shapes[0].half_length == 0.5);
  CHECK(sticks.shapes[0].radius == 0.025);
  REQUIRE(sticks.rigid.size() == 200);
  for (std::size_t i = 0; i < 200; ++i) {
    CHECK(sticks.kind(i) == ccd::ShapeKind::Capsule);
    CHECK(sticks.rigid[i].angular_velocity.norm() <= 10.0);
    CHECK(std::fabs(sticks.rigid[i].orientation.norm() - 1.0) < 1e-15);
  }
  const ccd::Scene plates = make("plates", {{"bodies", 50}, {"elongation", 8}});
  CHECK(plates.shapes[0].half_extents == ccd::Vec3(1, 1, 0.125));
  const ccd::Scene crates = make("crates", {{"bodies", 50}, {"elongation", 4}});
  CHECK(crates.shapes[0].half_extents == ccd::Vec3(1, 0.5, 0.25));
  const ccd::Scene rocks = make("rocks", {{"bodies", 100}, {"spheres", 0.5}});
  CHECK(rocks.shapes.size() == 8);
  std::size_t spheres = 0;
  for (std::size_t i = 0; i < 100; ++i) spheres += rocks.kind(i) == ccd::ShapeKind::Sphere;
  CHECK(spheres > 30);
  CHECK(spheres < 70);
  // No spin at all: the same positions, no rotation.
  const ccd::Scene still = make("crates", {{"bodies", 20}, {"spin_max", 0}});
  for (const ccd::RigidBody& r : still.rigid) CHECK(r.angular_velocity.isZero(0.0));
}

TEST_CASE("a spinning-sticks scene gets a certified truth with contacts", "[generators][rigid]") {
  const ccd::Scene s = make("sticks", {{"bodies", 300}, {"seed", 5}, {"spin_max", 20}, {"speed_max", 8}, {"fraction", 0.1}});
  const ccd::Trajectories traj(s);
  const ccd::RigidMotion motion(s, traj);
  const ccd::RigidTruthResult t = ccd::compute_rigid_truth(motion);
  CHECK(t.events.size() > 5);
  CHECK(t.errors.size() == t.events.size());
}

TEST_CASE("spinning generators: overlap keeps enclosing spheres that overlap at t = 0", "[generators][rigid]") {
  const json p = {{"bodies", 300}, {"seed", 2}, {"fraction", 0.1}, {"speed_max", 0}};
  const auto overlapping_pairs = [](const ccd::Scene& s) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < s.bodies.size(); ++i)
      for (std::size_t j = i + 1; j < s.bodies.size(); ++j) {
        const double R = s.bodies[i].radius + s.bodies[j].radius;
        n += (s.bodies[i].position - s.bodies[j].position).squaredNorm() < R * R;
      }
    return n;
  };
  json with = p;
  with["overlap"] = 1;
  CHECK(overlapping_pairs(make("sticks", p)) == 0);
  CHECK(overlapping_pairs(make("sticks", with)) > 10);
  // Overlap changes the placement only: the other draws (here the spins) are taken as before
  // for the first body, which is never redrawn.
  CHECK(make("sticks", with).rigid[0].angular_velocity == make("sticks", p).rigid[0].angular_velocity);
}

TEST_CASE("spinning generators: wrap = 1 loops the box around, the draws unchanged", "[generators][rigid][periodic]") {
  for (const char* name : {"sticks", "plates", "crates", "rocks"}) {
    for (const int free : {0, 1}) {
      CAPTURE(name, free);
      const json p = {{"bodies", 40}, {"seed", 4}, {"free", free}};
      json w = p;
      w["wrap"] = 1;
      const ccd::Scene walls = make(name, p), wrapped = make(name, w);
      CHECK_FALSE(walls.wraps());
      REQUIRE(wrapped.wraps());
      for (int k = 0; k < 3; ++k) CHECK(wrapped.box->wraps(k));
      CHECK(wrapped.box->min == walls.box->min);
      CHECK(wrapped.box->max == walls.box->max);
      REQUIRE(wrapped.bodies.size() == walls.bodies.size());
      for (std::size_t i = 0; i < walls.bodies.size(); ++i) {
        CHECK(wrapped.bodies[i].position == walls.bodies[i].position);
        CHECK(wrapped.bodies[i].velocity == walls.bodies[i].velocity);
        CHECK(wrapped.rigid[i].angular_velocity == walls.rigid[i].angular_velocity);
        CHECK(wrapped.rigid[i].spin == walls.rigid[i].spin);
        // The edge rule of a wrapped box: at least 4 x the enclosing radius.
        CHECK(4.0 * wrapped.bodies[i].radius <= (wrapped.box->max - wrapped.box->min).minCoeff());
      }
    }
  }
}

}  // namespace generators_spinning_test
