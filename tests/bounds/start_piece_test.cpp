// StepContext::start_piece: every bound built from the exact pieces (the registry's Exact
// entries: swept_aabb, capsule, obb_sat) gives the same boxes and the same pair tests, bit
// for bit, whether it walks from the state cursor's pieces or searches for them; and
// Bound::test_pairs gives the pair-by-pair answers. Scenes: hand-made dyadic bodies with a
// wall reflection exactly at t = 1 and an acceleration change at t = 2 (windows that start,
// end or contain those breaks, start at t = 0, end at the horizon or are empty), and
// random gases with walls, gravity and acceleration changes.
#include <tests/bounds/bound_test_support.hpp>
#include <tests/ccd/scene/body_builder.hpp>

#include <ccd/motion/state_cursor.hpp>

#include <catch2/catch.hpp>
#include <cstring>
#include <random>
#include <vector>

namespace bounds_start_piece_test {

using ccd::Vec3;

namespace {

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

bool same_box(const ccd::Aabb& x, const ccd::Aabb& y) {
  for (int k = 0; k < 3; ++k)
    if (!same_bits(x.lo[k], y.lo[k]) || !same_bits(x.hi[k], y.hi[k])) return false;
  return true;
}

// One window [u0, u1] of `scene`: each Exact bound prepared with and without the cursor's
// pieces, and refreshed with them. Returns the number of Possible pairs seen.
std::size_t check_window(const ccd::Scene& scene, const ccd::Trajectories& m, double u0, double u1) {
  std::vector<ccd::BodyState> start;
  ccd::StateCursor cursor(m);
  cursor.evaluate(u0, start);
  ccd::StepContext searched;
  searched.t0 = u0;
  searched.t1 = u1;
  searched.start = start;
  searched.exact = &m;
  searched.walls = scene.box;
  const ccd::RigidMotion motion(scene, m);
  searched.motion = &motion;
  ccd::StepContext walked = searched;
  walked.start_piece = cursor.pieces();
  std::vector<ccd::BodyPair> pairs;
  for (std::uint32_t i = 0; i < m.size(); ++i)
    for (std::uint32_t j = i + 1; j < m.size(); ++j) pairs.push_back({i, j});
  std::vector<std::uint32_t> all(m.size());
  for (std::uint32_t i = 0; i < m.size(); ++i) all[i] = i;
  std::size_t possible = 0;
  std::size_t bounds = 0;
  for (const ccd::BoundInfo& info : ccd::bound_registry()) {
    if (info.knowledge != ccd::Knowledge::Exact) continue;
    ++bounds;
    INFO(info.name << " window [" << u0 << ", " << u1 << "]");
    const auto a = info.make();
    const auto b = info.make();
    const auto c = info.make();
    std::vector<ccd::Aabb> boxes_a, boxes_b;
    a->prepare(searched, boxes_a);
    b->prepare(walked, boxes_b);
    std::vector<ccd::Aabb> boxes_c(m.size());
    c->refresh(walked, all, boxes_c);
    REQUIRE(boxes_a.size() == m.size());
    REQUIRE(boxes_b.size() == m.size());
    for (std::size_t i = 0; i < m.size(); ++i) {
      INFO("body " << i);
      REQUIRE(same_box(boxes_a[i], boxes_b[i]));
      REQUIRE(same_box(boxes_a[i], boxes_c[i]));
    }
    std::vector<ccd::BodyPair> passed;
    std::vector<double> earliest;
    b->test_pairs(pairs, passed, earliest);
    REQUIRE(passed.size() == earliest.size());
    std::size_t next = 0;
    for (const ccd::BodyPair& p : pairs) {
      INFO("pair " << p.a << " " << p.b);
      const ccd::PairTest ta = a->test(p.a, p.b);
      const ccd::PairTest tb = b->test(p.a, p.b);
      const ccd::PairTest tc = c->test(p.a, p.b);
      REQUIRE(ta.status == tb.status);
      REQUIRE(same_bits(ta.earliest, tb.earliest));
      REQUIRE(ta.status == tc.status);
      REQUIRE(same_bits(ta.earliest, tc.earliest));
      if (ta.possible()) {
        ++possible;
        REQUIRE(next < passed.size());
        REQUIRE(passed[next].a == p.a);
        REQUIRE(passed[next].b == p.b);
        REQUIRE(same_bits(earliest[next], ta.earliest));
        ++next;
      }
    }
    REQUIRE(next == passed.size());
  }
  REQUIRE(bounds >= 3);  // swept_aabb, capsule, obb_sat
  return possible;
}

}  // namespace

TEST_CASE("bounds from the cursor's pieces: dyadic breaks at window ends", "[bounds][start_piece]") {
  using ccd::test::body;
  ccd::Scene s;
  s.horizon = 4.0;
  s.box = ccd::WallBox{Vec3(0, 0, 0), Vec3(16, 16, 16)};
  // 0, 1: 0 reaches the wall plane x = 0.5 at t = 1 and reflects; 1 waits beside the wall
  // (the capsules of 0 and 1 touch: distance 1 = R at t = 1).
  s.bodies.push_back(body(0.5, Vec3(1.5, 4, 4), Vec3(-1, 0, 0)));
  s.bodies.push_back(body(0.5, Vec3(0.5, 5, 4)));
  // 2: an acceleration change at t = 2, towards body 3.
  ccd::Body b = body(0.5, Vec3(8, 4, 4), Vec3(0, 1, 0));
  b.acceleration_changes.push_back({2.0, Vec3(0.5, 0, 0)});
  s.bodies.push_back(b);
  s.bodies.push_back(body(0.5, Vec3(9.5, 7, 4)));
  // 4: starts on the wall plane y = 1 moving into it (reflects at t = 0); 5 at rest.
  s.bodies.push_back(body(1, Vec3(8, 1, 12), Vec3(0, -2, 0)));
  s.bodies.push_back(body(1, Vec3(8, 4, 12)));
  // 6: far corner, tangent to 7 at t = 2 (closest distance exactly R = 1).
  s.bodies.push_back(body(0.5, Vec3(12, 14, 14), Vec3(-1, 0, 0)));
  s.bodies.push_back(body(0.5, Vec3(10, 13, 14)));
  const ccd::Trajectories m(s);
  REQUIRE(m.pieces(0).size() == 2);
  REQUIRE(m.pieces(0)[0].t1 == 1.0);
  REQUIRE(m.pieces(2).size() == 2);
  REQUIRE(m.pieces(2)[0].t1 == 2.0);
  std::size_t possible = 0;
  const double windows[][2] = {{0, 1},   {1, 2},     {0.5, 2.5}, {0, 4},   {2, 4},
                               {3, 4},   {4, 4},     {1, 1},     {0, 0},   {0.25, 0.75}};
  for (const auto& w : windows) possible += check_window(s, m, w[0], w[1]);
  CHECK(possible > 0);
}

TEST_CASE("bounds from the cursor's pieces: random gases", "[bounds][start_piece]") {
  std::mt19937_64 rng(1801);
  for (const bool gravity : {false, true}) {
    const ccd::test::Step st = ccd::test::random_gas(rng, 40, 0.0, 0.5, 4.0, true, gravity, 3);
    const double h = st.scene.horizon;
    std::size_t possible = 0;
    for (int k = 0; k < 4; ++k) possible += check_window(st.scene, st.traj, h * k / 4, h * (k + 1) / 4);
    CHECK(possible > 0);
  }
}

}  // namespace bounds_start_piece_test
