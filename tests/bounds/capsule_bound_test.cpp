#include <bounds/capsule_bound.hpp>
#include <ccd/queries/segment_segment.hpp>
#include <tests/bounds/bound_test_support.hpp>

#include <catch2/catch.hpp>

namespace bounds_capsule_bound_test {

using ccd::Vec3;

TEST_CASE("capsule contains the exact motion, reflections included", "[bounds][capsule][containment]") {
  std::mt19937_64 rng(123);
  ccd::CapsuleBound bound;
  std::vector<ccd::Aabb> boxes;
  long failed = 0, multi_piece = 0;
  for (int rep = 0; rep < 12; ++rep) {
    const double h = rep % 3 == 0 ? 0.5 : 1.0 / 60;
    const ccd::test::Step st = ccd::test::random_gas(rng, 500, h, 2 * h, 40.0, rep % 4 != 0, rep % 2 == 0, 3);
    bound.prepare(st.context(ccd::Knowledge::Exact), boxes);
    for (std::uint32_t i = 0; i < st.start.size(); ++i) {
      const auto& c = bound.capsule(i);
      if (st.traj.piece_at(i, st.t0).t1 < st.t1) ++multi_piece;
      for (int k = 0; k <= 32; ++k) {
        const double t = st.t0 + h * k / 32;
        const Vec3 x = st.traj.position(i, t);
        // Centre within radius - r of the segment (the whole sphere inside the capsule).
        const auto d = ccd::segment_segment_closest(c.p0, c.p1, x, x);
        if (std::sqrt(d.distance_squared) > c.radius - st.traj.radius(i)) ++failed;
      }
    }
  }
  CHECK(failed == 0);
  CHECK(multi_piece > 500);  // reflections and acceleration changes inside steps were exercised
}

TEST_CASE("capsule of linear motion is the exact swept sphere", "[bounds][capsule]") {
  // Two bodies on crossing paths that miss by 0.1 (radii 0.5 each, closest 1.1 apart):
  // the capsule test rejects them; moved 0.2 closer, it accepts.
  for (const double offset : {1.1, 0.9}) {
    ccd::Scene s;
    s.horizon = 1.0;
    s.bodies.push_back({0.5, Vec3(-5, 0, 0), Vec3(10, 0, 0), Vec3::Zero(), {}});
    s.bodies.push_back({0.5, Vec3(0, -5, offset), Vec3(0, 10, 0), Vec3::Zero(), {}});
    ccd::test::Step st;
    st.scene = s;
    st.finish(0.0, 1.0);
    ccd::CapsuleBound bound;
    std::vector<ccd::Aabb> boxes;
    bound.prepare(st.context(ccd::Knowledge::Exact), boxes);
    CHECK(bound.capsule(0).radius == Approx(0.5).epsilon(1e-12));
    CHECK(bound.test(0, 1).possible() == (offset < 1.0));
  }
}

}  // namespace bounds_capsule_bound_test
