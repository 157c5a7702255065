// Walking a body's pieces from a known one (ccd/motion/piece_walk.hpp) against the searching
// Trajectories functions, index for index and bit for bit, on a hand-made dyadic scene with
// breaks exactly at window ends: a wall reflection at t = 1, an acceleration change at
// t = 2, a body that starts on a wall moving into it (it reflects at once), a resting body,
// a body far from the origin; windows of every pair of dyadic times in [0, horizon],
// including t = 0, the horizon and empty windows (u0 == u1).
#include <tests/ccd/scene/body_builder.hpp>

#include <ccd/motion/piece_walk.hpp>
#include <ccd/motion/trajectory.hpp>

#include <catch2/catch.hpp>
#include <cstring>
#include <vector>

namespace ccd_motion_piece_walk_test {

using ccd::Vec3;
using ccd::test::body;

namespace {

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

bool same_box(const ccd::Aabb& x, const ccd::Aabb& y) {
  for (int k = 0; k < 3; ++k)
    if (!same_bits(x.lo[k], y.lo[k]) || !same_bits(x.hi[k], y.hi[k])) return false;
  return true;
}

ccd::Trajectories dyadic_scene() {
  ccd::Scene s;
  s.horizon = 4.0;
  s.box = ccd::WallBox{Vec3(0, 0, 0), Vec3(16, 16, 16)};
  // 0: reaches the wall plane x = r = 0.5 at t = 1 exactly and reflects.
  s.bodies.push_back(body(0.5, Vec3(1.5, 4, 4), Vec3(-1, 0, 0)));
  // 1: an acceleration change at t = 2 (and one at t = 3.5).
  ccd::Body b = body(0.5, Vec3(8, 4, 4), Vec3(0, 1, 0), Vec3(0.5, 0, 0));
  b.acceleration_changes.push_back({2.0, Vec3(0, 0, 1)});
  b.acceleration_changes.push_back({3.5, Vec3(-1, 0, 0)});
  s.bodies.push_back(b);
  // 2: starts on the wall plane y = r = 1 moving into it: reflects at t = 0.
  s.bodies.push_back(body(1, Vec3(8, 1, 8), Vec3(0, -2, 0)));
  // 3: at rest.
  s.bodies.push_back(body(0.25, Vec3(12, 12, 12)));
  // 4: starts on the wall plane x = 15.5 moving into it, bounces between x = 0.5 and
  // x = 15.5 at 8 units/s: reflections at t = 0, 1.875 and 3.75.
  s.bodies.push_back(body(0.5, Vec3(15.5, 8, 8), Vec3(8, 0, 0)));
  return ccd::Trajectories(s);
}

ccd::Trajectories far_scene() {
  ccd::Scene s;
  s.horizon = 4.0;
  s.box = ccd::WallBox{Vec3(1048576, 1048576, 1048576), Vec3(1048576 + 64, 1048576 + 64, 1048576 + 64)};
  // Reflects off x = 1048576 + 0.5 at t = 2 exactly, gravity-like acceleration along z.
  s.bodies.push_back(body(0.5, Vec3(1048576 + 4.5, 1048576 + 32, 1048576 + 32), Vec3(-2, 0, 0), Vec3(0, 0, -0.25)));
  s.bodies.push_back(body(0.5, Vec3(1048576 + 32, 1048576 + 32, 1048576 + 32), Vec3(0.125, 0.5, 0)));
  return ccd::Trajectories(s);
}

std::vector<double> dyadic_times(double horizon) {
  std::vector<double> t;
  for (double x = 0.0; x <= horizon; x += 0.0625) t.push_back(x);
  return t;
}

void check(const ccd::Trajectories& m) {
  const std::vector<double> times = dyadic_times(m.horizon());
  std::size_t multi = 0;  // windows that meet more than one piece: the walk is exercised
  for (std::size_t i = 0; i < m.size(); ++i) {
    for (std::size_t a = 0; a < times.size(); ++a) {
      const double u0 = times[a];
      const std::size_t k = m.piece_index(i, u0);
      REQUIRE(ccd::piece_index_from(m, i, 0, u0) == k);
      for (std::size_t b = a; b < times.size(); ++b) {
        const double u1 = times[b];
        INFO("body " << i << " window [" << u0 << ", " << u1 << "]");
        REQUIRE(ccd::piece_index_from(m, i, k, u1) == m.piece_index(i, u1));
        REQUIRE(same_box(ccd::swept_bounds_from(m, i, k, u0, u1), m.swept_bounds(i, u0, u1)));
        multi += m.piece_index(i, u1) != k;
      }
    }
  }
  CHECK(multi > 0);
}

}  // namespace

TEST_CASE("piece walk: the same pieces and swept boxes as the search", "[motion][piece_walk]") {
  const ccd::Trajectories m = dyadic_scene();
  // The breaks the comments promise (so the windows really end on them).
  REQUIRE(m.pieces(0).size() == 2);
  CHECK(m.pieces(0)[0].t1 == 1.0);
  REQUIRE(m.pieces(1).size() == 3);
  CHECK(m.pieces(1)[0].t1 == 2.0);
  CHECK(m.pieces(1)[1].t1 == 3.5);
  CHECK(m.pieces(4).size() >= 3);
  check(m);
}

TEST_CASE("piece walk: far from the origin", "[motion][piece_walk]") {
  const ccd::Trajectories m = far_scene();
  REQUIRE(m.pieces(0).size() == 2);
  CHECK(m.pieces(0)[0].t1 == 2.0);
  check(m);
}

}  // namespace ccd_motion_piece_walk_test
