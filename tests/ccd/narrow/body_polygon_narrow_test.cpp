// The narrow phase of a body against a static polygon: spheres take the exact entry,
// other shapes conservative advancement against the polygon at rest, whose bracket
// [toi, toi + toi_error] holds the hand-worked first contact (rigid_scenery_scenes.hpp).
#include <ccd/narrow/body_polygon_narrow.hpp>
#include <ccd/narrow/narrow_table.hpp>

#include "../scene/rigid_scenery_scenes.hpp"

#include <ccd/motion/rigid_motion.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

namespace {

struct Fixture {
  ccd::Scene scene = ccd::test::rigid_static_cases();
  ccd::Trajectories traj{scene};
  ccd::RigidMotion rigid{scene, traj};
  std::vector<ccd::BodyState> start;
  ccd::ContactResult query(std::uint32_t body, double t0, double t1, bool sample = false) {
    ccd::NarrowInput in;
    in.start = start;
    in.t0 = t0;
    in.t1 = t1;
    in.sample = sample;
    in.motion = &rigid;
    return ccd::narrow_table().find_polygon(rigid.kind(body))(in, body, scene.scenery[body]);
  }
};

void check_bracket(const ccd::ContactResult& c, double exact) {
  INFO("toi " << c.toi << " error " << c.toi_error << " exact " << exact);
  REQUIRE(c.status == ccd::QueryStatus::Hit);
  CHECK(c.toi <= exact);
  CHECK(exact <= c.toi + c.toi_error);
  CHECK(c.toi_error < 1e-6);
}

}  // namespace

TEST_CASE("body-polygon narrow phase: rigid shapes bracket the first contact", "[narrow][rigid][scenery]") {
  Fixture f;
  SECTION("a cube's face lands flat at 3/2") {
    CHECK(f.query(0, 0.0, 1.0).status == ccd::QueryStatus::Miss);
    check_bracket(f.query(0, 1.0, 2.0), 1.5);
    // Contact exactly at the step's end: reported (no overlap inside the step to bracket it).
    const ccd::ContactResult end = f.query(0, 1.25, 1.5);
    REQUIRE(end.status == ccd::QueryStatus::Hit);
    CHECK(end.toi <= 1.5);
    CHECK(end.toi >= 1.5 - 1e-6);
    CHECK(f.query(0, 1.75, 2.0).status == ccd::QueryStatus::Overlapping);
  }
  SECTION("a spinning stick's tip reaches a polygon edge at 1 - c; in contact at t = 0") {
    const double c = ccd::test::stick_edge_half_width();
    check_bracket(f.query(1, 0.5, 1.0), 1.0 - c);
    const ccd::ContactResult at0 = f.query(1, 0.0, 0.25);
    CHECK(at0.status == ccd::QueryStatus::Overlapping);
    CHECK(at0.toi == 0.0);
  }
  SECTION("corner on vertex at 1/2, and far from the origin") {
    check_bracket(f.query(2, 0.0, 1.0), 0.5);
    check_bracket(f.query(3, 1.0, 2.0), 1.5);
  }
  SECTION("sample tests: certified apart is a miss, touching or overlapping is a contact") {
    CHECK(f.query(0, 1.0, 1.0, true).status == ccd::QueryStatus::Miss);
    CHECK(f.query(0, 1.75, 1.75, true).status == ccd::QueryStatus::Overlapping);
    CHECK(f.query(2, 0.5, 0.5, true).status == ccd::QueryStatus::Overlapping);  // corner exactly on vertex
  }
}

TEST_CASE("body-polygon narrow phase: a sphere in a rigid scene takes the exact entry", "[narrow][rigid][scenery]") {
  ccd::Scene s = ccd::test::rigid_static_cases();
  ccd::Body ball;
  ball.radius = 0.5;
  ball.position = ccd::Vec3(0, 0, 2);  // above case 0's floor (shared with the cube), falling at 1
  ball.velocity = ccd::Vec3(0, 0, -1);
  s.add_rigid_body(ball, ccd::RigidBody{});
  const ccd::Trajectories traj(s);
  const ccd::RigidMotion rigid(s, traj);
  ccd::NarrowInput in;
  in.t0 = 1.0;
  in.t1 = 2.0;
  in.motion = &rigid;
  const auto body = static_cast<std::uint32_t>(s.bodies.size() - 1);
  const ccd::ContactResult c = ccd::narrow_table().find_polygon(rigid.kind(body))(in, body, s.scenery[0]);
  REQUIRE(c.status == ccd::QueryStatus::Hit);
  CHECK(c.toi == Approx(1.5).margin(1e-12));
  CHECK(c.toi_error == 0.0);
}
