// The state cursor against Trajectories' own lookup, across wall reflections.
#include <ccd/motion/state_cursor.hpp>

#include <catch2/catch.hpp>
#include <vector>

namespace ccd_motion_state_cursor_test {

using ccd::Vec3;

TEST_CASE("the state cursor evaluates the pieces Trajectories::piece_at picks", "[motion]") {
  ccd::Scene s;
  s.horizon = 4.0;
  s.box = ccd::WallBox{Vec3(0, 0, 0), Vec3(4, 4, 4)};
  // Body 0 reflects at x = 3.5 (t = 1.5) and x = 0.5 (t = 4.5, past the horizon).
  s.bodies.push_back({0.5, Vec3(2, 2, 2), Vec3(1, 0, 0), Vec3::Zero(), {}});
  s.bodies.push_back({0.25, Vec3(1, 1, 1), Vec3(0, 0.5, 0), Vec3::Zero(), {}});
  const ccd::Trajectories m(s);
  REQUIRE(m.pieces(0).size() == 2);
  ccd::StateCursor cursor(m);
  std::vector<ccd::BodyState> out;
  // Times increase, including the break itself (the later piece is used there).
  for (double t : {0.0, 0.5, 1.5, 1.5, 2.0, 4.0}) {
    CAPTURE(t);
    cursor.evaluate(t, out);
    REQUIRE(out.size() == 2);
    for (std::uint32_t i = 0; i < 2; ++i) {
      const ccd::Piece& p = m.piece_at(i, t);
      CHECK(&m.pieces(i)[cursor.pieces()[i]] == &p);
      CHECK(out[i].position == p.position(t));
      CHECK(out[i].velocity == p.velocity(t));
      CHECK(out[i].radius == m.radius(i));
    }
  }
  cursor.evaluate(2.0, out);
  CHECK(out[0].position == Vec3(3, 2, 2));  // reflected at 1.5: 3.5 - 0.5
  CHECK(out[0].velocity == Vec3(-1, 0, 0));
}

}  // namespace ccd_motion_state_cursor_test
