#include <ccd/motion/trajectory.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

namespace ccd_motion_trajectory_test {

using ccd::Vec3;

namespace {

ccd::Scene box_scene(double horizon) {
  ccd::Scene s;
  s.horizon = horizon;
  s.box = ccd::WallBox{Vec3(0, 0, 0), Vec3(10, 10, 10)};
  return s;
}

constexpr double eps = std::numeric_limits<double>::epsilon();

}  // namespace

TEST_CASE("linear motion without walls is one piece", "[motion]") {
  ccd::Scene s;
  s.horizon = 3.0;
  s.bodies.push_back({1.0, Vec3(1, 2, 3), Vec3(1, -1, 0.5), Vec3::Zero(), {}});
  const ccd::Trajectories t(s);
  REQUIRE(t.pieces(0).size() == 1);
  CHECK(t.position(0, 2.0) == Vec3(3, 0, 4));
}

TEST_CASE("a body reflects exactly at the wall", "[motion]") {
  // Centre starts at x = 5 moving at +2; radius 1, wall at x = 10, so the centre touches
  // x = 9 at t = 2, comes back and reaches x = 1 at t = 6, and is at x = 3 at t = 7.
  ccd::Scene s = box_scene(7.0);
  s.bodies.push_back({1.0, Vec3(5, 5, 5), Vec3(2, 0, 0), Vec3::Zero(), {}});
  const ccd::Trajectories t(s);
  const auto ps = t.pieces(0);
  REQUIRE(ps.size() == 3);
  CHECK(ps[0].t1 == Approx(2.0).epsilon(4 * eps));
  CHECK(ps[1].t1 == Approx(6.0).epsilon(4 * eps));
  CHECK(ps[1].p.x() == 9.0);  // placed exactly on the wall
  CHECK(t.position(0, 7.0).x() == Approx(3.0).epsilon(8 * eps));
  CHECK(t.velocity(0, 7.0).x() == 2.0);
}

TEST_CASE("an elastic ball under gravity bounces back to its release height", "[motion]") {
  // Dropped from y = 5 (radius 1, floor contact at y = 1): falls 4 m in sqrt(8/9.81) s.
  ccd::Scene s = box_scene(2.0);
  s.gravity = Vec3(0, -9.81, 0);
  s.bodies.push_back({1.0, Vec3(5, 5, 5), Vec3::Zero(), Vec3::Zero(), {}});
  const ccd::Trajectories t(s);
  const double t_hit = std::sqrt(8.0 / 9.81);
  REQUIRE(t.pieces(0).size() >= 2);
  CHECK(t.pieces(0)[0].t1 == Approx(t_hit).epsilon(8 * eps));
  CHECK(t.position(0, 2.0 * t_hit).y() == Approx(5.0).epsilon(1e-12));
  CHECK(t.velocity(0, 2.0 * t_hit).y() == Approx(0.0).margin(1e-12));
}

TEST_CASE("a body at rest on the floor under gravity stays there", "[motion]") {
  ccd::Scene s = box_scene(1.0);
  s.gravity = Vec3(0, -9.81, 0);
  s.bodies.push_back({0.5, Vec3(5, 0.5, 5), Vec3(1, 0, 0), Vec3::Zero(), {}});
  const ccd::Trajectories t(s);
  CHECK(t.pieces(0).size() == 1);
  CHECK(t.position(0, 1.0) == Vec3(6, 0.5, 5));
}

TEST_CASE("a body starting on a wall and moving into it reflects at once", "[motion]") {
  ccd::Scene s = box_scene(1.0);
  s.bodies.push_back({0.5, Vec3(0.5, 5, 5), Vec3(-1, 0, 0), Vec3::Zero(), {}});
  const ccd::Trajectories t(s);
  CHECK(t.position(0, 1.0).x() == 1.5);
}

TEST_CASE("acceleration changes split the trajectory at the given times", "[motion]") {
  ccd::Scene s;
  s.horizon = 2.0;
  ccd::Body b{1.0, Vec3::Zero(), Vec3::Zero(), Vec3(2, 0, 0), {{1.0, Vec3(-2, 0, 0)}}};
  s.bodies.push_back(b);
  const ccd::Trajectories t(s);
  REQUIRE(t.pieces(0).size() == 2);
  CHECK(t.pieces(0)[1].t0 == 1.0);
  CHECK(t.position(0, 2.0).x() == Approx(2.0).epsilon(4 * eps));  // 1 + 2*1 - 1
  CHECK(t.velocity(0, 2.0).x() == Approx(0.0).margin(4 * eps));
  CHECK(s.motion_kind() == ccd::MotionKind::PiecewiseQuadratic);
}

TEST_CASE("swept bounds contain the path and the vertex of the parabola", "[motion]") {
  ccd::Scene s;
  s.horizon = 2.0;
  s.gravity = Vec3(0, -10, 0);
  s.bodies.push_back({0.5, Vec3(0, 0, 0), Vec3(1, 10, 0), Vec3::Zero(), {}});
  const ccd::Trajectories t(s);
  const ccd::Aabb b = t.swept_bounds(0, 0.0, 2.0);
  CHECK(b.hi.y() == Approx(5.5));  // apex y = 5 at t = 1, plus radius
  CHECK(b.lo.y() == Approx(-0.5));
  CHECK(b.hi.x() == Approx(2.5));
}

TEST_CASE("a reflection at an exactly representable time is exact, state and time", "[motion]") {
  // Dropped from 0.5 + 2^-3 with a = -1/4 onto the plane y = 0.5: hits at t = 1 exactly
  // with speed 1/4, and is back at the top at t = 2 with velocity 0.
  ccd::Scene s = box_scene(2.0);
  s.bodies.push_back({0.5, Vec3(5, 0.625, 5), Vec3::Zero(), Vec3(0, -0.25, 0), {}});
  const ccd::Trajectories t(s);
  REQUIRE(t.pieces(0).size() == 2);
  CHECK(t.pieces(0)[0].t1 == 1.0);
  CHECK(t.pieces(0)[1].p == Vec3(5, 0.5, 5));
  CHECK(t.pieces(0)[1].v == Vec3(0, 0.25, 0));
  CHECK(t.lows(0)[1].edge_error == 0.0);
  CHECK(t.position(0, 2.0) == Vec3(5, 0.625, 5));
}

TEST_CASE("a reflection at an irrational time records its window and error", "[motion]") {
  ccd::Scene s = box_scene(2.0);
  s.gravity = Vec3(0, -9.81, 0);
  s.bodies.push_back({1.0, Vec3(5, 5, 5), Vec3::Zero(), Vec3::Zero(), {}});
  const ccd::Trajectories t(s);
  const auto lows = t.lows(0);
  REQUIRE(lows.size() >= 2);
  // |t* - t_r| <= half an ulp of t_r, so the error is at most |v| ulp.
  const double t_r = t.pieces(0)[0].t1;
  const double ulp = std::nextafter(t_r, 10.0) - t_r;
  CHECK(lows[1].edge_window <= ulp);
  CHECK(lows[1].edge_error <= 9.81 * t_r * ulp * 1.01);
  // The exact state right after the bounce is on the plane up to that error.
  const ccd::DdVec3 p = ccd::exact_position(t.pieces(0)[1], lows[1], t_r);
  CHECK(std::fabs((p[1] - ccd::Dd(1.0)).value()) <= lows[1].edge_error);
}

TEST_CASE("bodies almost at rest on a wall rest instead of bouncing ever faster", "[motion]") {
  // Resting rule: pushed into a wall and unable to rise more than 2^-30 of the box extent.
  SECTION("reproducer: a soft landing built from decimal numbers") {
    ccd::Scene s = box_scene(1.5);
    s.box = ccd::WallBox{Vec3(0, 0, 0), Vec3(4, 4, 4)};
    s.gravity = Vec3(0, -9.81, 0);
    ccd::Body b{0.5, Vec3(2, 0.5642857142857143, 2), Vec3(0, -0.3, 0), Vec3(0, 10.51, 0), {}};
    b.acceleration_changes.push_back({0.4285714285714286, Vec3::Zero()});
    s.bodies.push_back(b);
    const ccd::Trajectories t(s);  // used to need more than 10^6 pieces
    CHECK(t.pieces(0).size() <= 3);
    CHECK(t.position(0, 1.5).y() == 0.5);
    CHECK(t.velocity(0, 1.5).y() == 0.0);
  }
  SECTION("2^-52 and 1e-10 above the floor, horizon 10") {
    const double h = GENERATE(0x1p-52, 1e-10, 0.0);
    CAPTURE(h);
    ccd::Scene s = box_scene(10.0);
    s.box = ccd::WallBox{Vec3(0, 0, 0), Vec3(4, 4, 4)};
    s.gravity = Vec3(0, -9.81, 0);
    s.bodies.push_back({0.5, Vec3(2, 0.5 + h, 2), Vec3(1, 0, 0), Vec3::Zero(), {}});
    const ccd::Trajectories t(s);
    CHECK(t.pieces(0).size() <= 4);  // the side walls still reflect the x motion
    CHECK(t.position(0, 10.0).y() == 0.5);
  }
  SECTION("above the rest height a ball keeps bouncing elastically") {
    // 2^-20 above the floor: rest height is 4 * 2^-30 = 2^-28; many exact bounces.
    ccd::Scene s = box_scene(1.0);
    s.box = ccd::WallBox{Vec3(0, 0, 0), Vec3(4, 4, 4)};
    s.bodies.push_back({0.5, Vec3(2, 0.5 + 0x1p-20, 2), Vec3::Zero(), Vec3(0, -2, 0), {}});
    const ccd::Trajectories t(s);
    // Fall time sqrt(2 h / a) = 2^-10: bounces every 2^-9 s, 512 of them over 1 s.
    CHECK(t.pieces(0).size() == 513);
    double top = 0.0;
    for (const ccd::Piece& q : t.pieces(0)) top = std::max(top, q.centre_bounds(q.t0, q.t1).hi.y());
    CHECK(top == 0.5 + 0x1p-20);
  }
  SECTION("moving fast into the floor is a reflection, not rest") {
    ccd::Scene s = box_scene(1.0);
    s.gravity = Vec3(0, -9.81, 0);
    s.bodies.push_back({0.5, Vec3(5, 0.5, 5), Vec3(0, -1, 0), Vec3::Zero(), {}});
    const ccd::Trajectories t(s);
    CHECK(t.velocity(0, 0.0).y() == 1.0);
    CHECK(t.position(0, 0.1).y() > 0.5);
  }
}

// Velocity changes (docs/formats.md, `velocity_changes`): the velocity jumps, the position
// is continuous. Dyadic data, so every state below is exact.
TEST_CASE("velocity changes split the trajectory, the position stays continuous", "[motion][velocity_changes]") {
  SECTION("free body: two jumps") {
    ccd::Scene s;
    s.horizon = 1.0;
    ccd::Body b{0.5, Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3::Zero(), {}};
    b.velocity_changes = {{0.25, Vec3(0, 2, 0)}, {0.75, Vec3(-1, 0, 0)}};
    s.bodies.push_back(b);
    const ccd::Trajectories t(s);
    const auto ps = t.pieces(0);
    REQUIRE(ps.size() == 3);
    CHECK(ps[0].t1 == 0.25);
    CHECK(ps[1].t0 == 0.25);
    CHECK(ps[1].p == Vec3(0.25, 0, 0));
    CHECK(ps[1].v == Vec3(0, 2, 0));
    CHECK(ps[2].p == Vec3(0.25, 1, 0));
    CHECK(t.velocity(0, 0.75) == Vec3(-1, 0, 0));  // the later piece at the break
    CHECK(t.position(0, 1.0) == Vec3(0, 1, 0));
  }
  SECTION("interleaved with acceleration changes, one at the same time") {
    ccd::Scene s;
    s.horizon = 1.0;
    s.gravity = Vec3(0, -2, 0);
    ccd::Body b{0.5, Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3::Zero(), {}};
    b.velocity_changes = {{0.25, Vec3(1, 0, 0)}, {0.5, Vec3(0, 0, 1)}};
    b.acceleration_changes = {{0.5, Vec3(0, 2, 4)}, {0.75, Vec3(0, 2, 0)}};
    s.bodies.push_back(b);
    const ccd::Trajectories t(s);
    const auto ps = t.pieces(0);
    REQUIRE(ps.size() == 4);  // breaks at 1/4, 1/2 (both changes at once), 3/4
    CHECK(ps[1].p == Vec3(0, 0.25 - 0.0625, 0));
    CHECK(ps[1].v == Vec3(1, 0, 0));
    CHECK(ps[1].a == Vec3(0, -2, 0));
    CHECK(ps[2].t0 == 0.5);
    CHECK(ps[2].p == Vec3(0.25, 0.1875 - 0.0625, 0));
    CHECK(ps[2].v == Vec3(0, 0, 1));
    CHECK(ps[2].a == Vec3(0, 0, 4));
    CHECK(ps[3].p == Vec3(0.25, 0.125, 0.25 + 0.125));
    CHECK(ps[3].v == Vec3(0, 0, 2));  // the acceleration change keeps the velocity reached
    CHECK(ps[3].a == Vec3::Zero());
  }
  SECTION("a jump at the instant the centre reaches a wall plane: the new velocity reflects at once") {
    ccd::Scene s = box_scene(0.5);
    s.bodies.push_back({1.0, Vec3(8.5, 5, 5), Vec3(2, 0, 0), Vec3::Zero(), {}});
    s.bodies[0].velocity_changes = {{0.25, Vec3(4, 0, 0)}};
    const ccd::Trajectories t(s);
    CHECK(t.position(0, 0.25) == Vec3(9, 5, 5));
    CHECK(t.velocity(0, 0.25) == Vec3(-4, 0, 0));
    CHECK(t.position(0, 0.5) == Vec3(8, 5, 5));
  }
  SECTION("a jump towards a wall, then a reflection") {
    ccd::Scene s = box_scene(1.5);
    s.bodies.push_back({1.0, Vec3(5, 5, 5), Vec3::Zero(), Vec3::Zero(), {}});
    s.bodies[0].velocity_changes = {{0.5, Vec3(8, 0, 0)}};
    const ccd::Trajectories t(s);
    REQUIRE(t.pieces(0).size() == 3);
    CHECK(t.pieces(0)[1].t1 == 1.0);
    CHECK(t.position(0, 1.5) == Vec3(5, 5, 5));
  }
  SECTION("a jump on a wrapped axis, then through the face") {
    ccd::Scene s;
    s.horizon = 1.5;
    s.box = ccd::WallBox{Vec3(0, 0, 0), Vec3(8, 8, 8)};
    s.box->boundary = {ccd::Boundary::Wrap, ccd::Boundary::Reflect, ccd::Boundary::Reflect};
    s.bodies.push_back({1.0, Vec3(6, 4, 4), Vec3::Zero(), Vec3::Zero(), {}});
    s.bodies[0].velocity_changes = {{0.5, Vec3(4, 0, 0)}};
    const ccd::Trajectories t(s);
    CHECK(t.position(0, 1.5) == Vec3(2, 4, 4));
  }
  SECTION("a body resting on the floor is launched by a jump") {
    ccd::Scene s = box_scene(2.0);
    s.gravity = Vec3(0, -2, 0);
    s.bodies.push_back({0.5, Vec3(5, 0.5, 5), Vec3::Zero(), Vec3::Zero(), {}});
    s.bodies[0].velocity_changes = {{0.5, Vec3(0, 1, 0)}};
    const ccd::Trajectories t(s);
    CHECK(t.position(0, 0.5) == Vec3(5, 0.5, 5));
    CHECK(t.position(0, 1.0) == Vec3(5, 0.75, 5));  // 0.5 + s - s^2, s = 1/2
    CHECK(t.position(0, 1.5) == Vec3(5, 0.5, 5));   // back on the floor at s = 1
  }
}

}  // namespace ccd_motion_trajectory_test
