// The certified truth of rigid bodies against static polygons: brackets that hold the
// hand-worked times (face on face, a spinning tip across an edge, corner on vertex, t = 0,
// the horizon, far from the origin), the grazing flag for a body resting exactly on a
// polygon, the cross-path test against the exact sphere-polygon truth, and random scenes
// checked against certified distances at dense sample times.
#include <ccd/truth/rigid_static_truth.hpp>

#include "../scene/rigid_scenery_scenes.hpp"
#include "../scene/scenery_support.hpp"

#include <ccd/queries/convex_distance.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <random>

namespace ccd_truth_rigid_static_truth_test {

using ccd::Vec3;

namespace {

struct World {
  ccd::Scene scene;
  ccd::Trajectories traj;
  std::unique_ptr<ccd::RigidMotion> rigid;
  ccd::RigidStaticTruthResult truth(ccd::RigidTruthOptions o = {}) {
    traj = ccd::Trajectories(scene);
    rigid = std::make_unique<ccd::RigidMotion>(scene, traj);
    return ccd::compute_rigid_static_truth(*rigid, scene.scenery, o);
  }
};

// The events of one body, in order.
std::vector<std::size_t> of_body(const ccd::RigidStaticTruthResult& r, std::uint32_t body) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < r.events.size(); ++i)
    if (r.events[i].body == body) out.push_back(i);
  return out;
}

// A certified (not grazing) event whose brackets hold enter and exit, each narrow.
void check_event(const ccd::RigidStaticTruthResult& r, std::size_t i, double enter, double exit) {
  INFO("event " << i << ": body " << r.events[i].body << " [" << r.events[i].enter << ", " << r.events[i].exit << "]");
  CHECK_FALSE(r.errors[i].grazing);
  CHECK(r.events[i].polygon == r.events[i].body);
  CHECK(std::fabs(r.events[i].enter - enter) <= r.errors[i].enter_error);
  CHECK(std::fabs(r.events[i].exit - exit) <= r.errors[i].exit_error);
  CHECK(r.errors[i].enter_error < 1e-6);
  CHECK(r.errors[i].exit_error < 1e-6);
}

}  // namespace

TEST_CASE("rigid static truth: constructed cases with hand-worked times", "[truth][rigid][scenery]") {
  World w;
  w.scene = ccd::test::rigid_static_cases();
  const ccd::RigidStaticTruthResult r = w.truth();
  REQUIRE(r.events.size() == r.errors.size());
  const double c = ccd::test::stick_edge_half_width();
  SECTION("a cube's face lands flat on a floor: [3/2, 2], exit exactly the horizon") {
    const auto e = of_body(r, 0);
    REQUIRE(e.size() == 1);
    check_event(r, e[0], 1.5, 2.0);
    CHECK(r.events[e[0]].exit == 2.0);
    CHECK(r.errors[e[0]].exit_error == 0.0);
  }
  SECTION("a spinning stick's tips cross a polygon edge: from t = 0 (exact), at 1, up to the horizon") {
    const auto e = of_body(r, 1);
    REQUIRE(e.size() == 3);
    check_event(r, e[0], 0.0, c);
    CHECK(r.events[e[0]].enter == 0.0);
    CHECK(r.errors[e[0]].enter_error == 0.0);
    check_event(r, e[1], 1.0 - c, 1.0 + c);
    check_event(r, e[2], 2.0 - c, 2.0);
    CHECK(r.events[e[2]].exit == 2.0);
  }
  SECTION("a cube's corner meets a triangle's vertex at 1/2; its face leaves the plane at 3/2") {
    const auto e = of_body(r, 2);
    REQUIRE(e.size() == 1);
    check_event(r, e[0], 0.5, 1.5);
  }
  SECTION("far from the origin (2^20): the same event as near it") {
    const auto e = of_body(r, 3);
    REQUIRE(e.size() == 1);
    check_event(r, e[0], 1.5, 2.0);
  }
  SECTION("a face reaching the floor exactly at the horizon: one event whose bracket holds T") {
    const auto e = of_body(r, 4);
    REQUIRE(e.size() == 1);
    CHECK(r.events[e[0]].enter - r.errors[e[0]].enter_error <= 2.0);
    CHECK(r.events[e[0]].enter + r.errors[e[0]].enter_error >= 2.0);
    CHECK(r.errors[e[0]].enter_error < 1e-6);
  }
  CHECK(r.events.size() == 7);
  CHECK(r.evaluations > 0);
}

TEST_CASE("rigid static truth: resting exactly on a polygon is grazing, 1/64 above is no event", "[truth][rigid][scenery]") {
  World w;
  w.scene = ccd::test::resting_scene();
  ccd::RigidTruthOptions o;
  o.max_evaluations = 4096;  // distance exactly 0 throughout: the search cannot certify anything
  const ccd::RigidStaticTruthResult r = w.truth(o);
  REQUIRE(r.events.size() == 1);
  CHECK(r.events[0].body == 0);
  CHECK(r.events[0].polygon == 0);
  CHECK(r.errors[0].grazing);
  CHECK(r.grazing == 1);
  // The unresolved run covers the whole horizon.
  CHECK(r.events[0].enter - r.errors[0].enter_error <= 0.0);
  CHECK(r.events[0].exit + r.errors[0].exit_error >= 1.0);
}

TEST_CASE("rigid static truth: threads and windows do not change the result", "[truth][rigid][scenery]") {
  World w;
  w.scene = ccd::test::rigid_static_cases();
  ccd::RigidTruthOptions one;
  one.threads = 1;
  one.windows = 1;
  ccd::RigidTruthOptions many;
  many.threads = 3;
  many.windows = 7;
  const auto a = w.truth(one);
  const auto b = w.truth(many);
  REQUIRE(a.events.size() == b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    CHECK(a.events[i].body == b.events[i].body);
    CHECK(a.events[i].polygon == b.events[i].polygon);
    // Different windows start the search elsewhere: the brackets must meet.
    CHECK(std::fabs(a.events[i].enter - b.events[i].enter) <= a.errors[i].enter_error + b.errors[i].enter_error);
    CHECK(std::fabs(a.events[i].exit - b.events[i].exit) <= a.errors[i].exit_error + b.errors[i].exit_error);
  }
}

TEST_CASE("cross-path: spheres in a rigid scene keep the exact truth, the generic search agrees with it",
          "[truth][rigid][scenery]") {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  World w;
  w.scene.horizon = 2.0;
  w.scene.gravity = Vec3(0, 0, -4);
  w.scene.box = ccd::WallBox{Vec3(0, 0, -4), Vec3(8, 8, 8)};
  w.scene.shapes.push_back(ccd::make_box_shape(Vec3(0.25, 0.125, 0.0625), "crate"));
  w.scene.scenery.push_back(ccd::test::square_z(0, 0, 0, 8));  // every ball falls through it
  for (int k = 0; k < 8; ++k) w.scene.scenery.push_back(ccd::test::random_polygon(rng, Vec3(1 + 6 * u(rng), 1 + 6 * u(rng), 2 * u(rng)), 1.0));
  for (int i = 0; i < 12; ++i) {
    ccd::Body b;
    b.radius = 0.125 + 0.25 * u(rng);
    b.position = Vec3(1 + 6 * u(rng), 1 + 6 * u(rng), 2 + 4 * u(rng));
    b.velocity = Vec3(4 * u(rng) - 2, 4 * u(rng) - 2, -4 * u(rng));
    ccd::RigidBody r;
    if (i == 0) r.shape = 0;  // one crate makes the scene rigid
    w.scene.add_rigid_body(b, r);
  }
  const ccd::RigidStaticTruthResult r = w.truth();
  const std::vector<ccd::StaticEvent> exact = ccd::compute_static_truth(w.traj, w.scene.scenery, 1);
  std::vector<ccd::StaticEvent> spheres;
  for (std::size_t i = 0; i < r.events.size(); ++i)
    if (r.events[i].body != 0) {
      spheres.push_back(r.events[i]);
      CHECK(r.errors[i] == ccd::EventError{});
    }
  std::vector<ccd::StaticEvent> exact_spheres;
  for (const ccd::StaticEvent& e : exact)
    if (e.body != 0) exact_spheres.push_back(e);
  REQUIRE(exact_spheres.size() >= 4);
  CHECK(spheres == exact_spheres);  // bit-identical
  // The bracket search on the spheres (one point plus the radius) agrees within its errors.
  const double tol = std::ldexp(w.scene.horizon, -30);
  std::size_t compared = 0;
  for (std::uint32_t body = 1; body < w.scene.bodies.size(); ++body)
    for (std::uint32_t j = 0; j < w.scene.scenery.size(); ++j) {
      std::vector<ccd::StaticEvent> ev;
      std::vector<ccd::EventError> er;
      ccd::body_polygon_bracket_events(*w.rigid, body, w.scene.scenery[j], j, 0.0, w.scene.horizon, tol, 1000000, ev,
                                       er);
      std::vector<ccd::StaticEvent> want;
      for (const ccd::StaticEvent& e : exact_spheres)
        if (e.body == body && e.polygon == j && e.exit > e.enter) want.push_back(e);
      std::vector<std::size_t> certified;
      for (std::size_t k = 0; k < ev.size(); ++k)
        if (!er[k].grazing) certified.push_back(k);
      INFO("body " << body << " polygon " << j);
      REQUIRE(certified.size() == want.size());
      for (std::size_t k = 0; k < want.size(); ++k) {
        const std::size_t x = certified[k];
        CHECK(std::fabs(ev[x].enter - want[k].enter) <= er[x].enter_error + 1e-12);
        CHECK(std::fabs(ev[x].exit - want[k].exit) <= er[x].exit_error + 1e-12);
        ++compared;
      }
    }
  CHECK(compared >= 4);
}

TEST_CASE("rigid static truth: random tumbling shapes against certified distances at dense samples",
          "[truth][rigid][scenery]") {
#ifdef CCDLAB_SANITIZED
  const int bodies = 6, samples = 256;
#else
  const int bodies = 12, samples = 1024;
#endif
  std::mt19937_64 rng(2027);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  World w;
  w.scene.horizon = 1.0;
  w.scene.gravity = Vec3(0, 0, -8);
  w.scene.box = ccd::WallBox{Vec3(0, 0, -2), Vec3(8, 8, 8)};
  w.scene.shapes.push_back(ccd::make_box_shape(Vec3(0.5, 0.25, 0.125), "crate"));
  w.scene.shapes.push_back(ccd::make_capsule_shape(0.5, 0.0625, "stick"));
  w.scene.shapes.push_back(ccd::make_box_shape(Vec3(0.5, 0.5, 0.03125), "plate"));
  w.scene.shapes.push_back(ccd::make_hull_shape({{0.5, 0, 0}, {0, 0.5, 0}, {0, 0, 0.25}, {-0.25, -0.125, -0.125}}, "rock"));
  w.scene.scenery.push_back(ccd::test::square_z(0, 0, 0, 8));
  for (int k = 0; k < 10; ++k)
    w.scene.scenery.push_back(ccd::test::random_polygon(rng, Vec3(8 * u(rng), 8 * u(rng), 1 + 4 * u(rng)), 1.0));
  for (int i = 0; i < bodies; ++i) {
    ccd::Body b;
    b.position = Vec3(1 + 6 * u(rng), 1 + 6 * u(rng), 2 + 4 * u(rng));
    b.velocity = Vec3(4 * u(rng) - 2, 4 * u(rng) - 2, -4 * u(rng));
    ccd::RigidBody r;
    r.shape = i % 4;
    r.orientation = ccd::Quat(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5).normalized();
    r.angular_velocity = Vec3(16 * u(rng) - 8, 16 * u(rng) - 8, 16 * u(rng) - 8);
    w.scene.add_rigid_body(b, r);
  }
  const ccd::RigidStaticTruthResult r = w.truth();
  REQUIRE(r.events.size() >= 4);
  std::size_t overlaps = 0;
  for (std::uint32_t body = 0; body < w.scene.bodies.size(); ++body)
    for (std::uint32_t j = 0; j < w.scene.scenery.size(); ++j)
      for (int k = 0; k <= samples; ++k) {
        const double t = static_cast<double>(k) / samples;
        const ccd::Pose p = w.rigid->pose(body, t);
        const ccd::ConvexDistance d = ccd::convex_distance(w.rigid->proxy(body), {p.centre, p.rotation},
                                                           ccd::polygon_proxy(w.scene.scenery[j]), ccd::ProxyPose{});
        if (d.status != ccd::ConvexDistance::Status::Overlapping && d.status != ccd::ConvexDistance::Status::Separated)
          continue;
        // Inside some event's outer bracket when overlapping; outside every certified core
        // [enter + enter_error, exit - exit_error] when separated.
        bool inside_outer = false, inside_core = false;
        for (std::size_t i = 0; i < r.events.size(); ++i) {
          const ccd::StaticEvent& e = r.events[i];
          if (e.body != body || e.polygon != j) continue;
          const ccd::EventError& x = r.errors[i];
          inside_outer = inside_outer || (t >= e.enter - x.enter_error && t <= e.exit + x.exit_error);
          inside_core = inside_core || (!x.grazing && t >= e.enter + x.enter_error && t <= e.exit - x.exit_error);
        }
        INFO("body " << body << " polygon " << j << " t " << t);
        if (d.status == ccd::ConvexDistance::Status::Overlapping) {
          ++overlaps;
          CHECK(inside_outer);
        } else {
          CHECK_FALSE(inside_core);
        }
      }
  CHECK(overlaps > 0);
}

}  // namespace ccd_truth_rigid_static_truth_test
