// `obb` (bounds/obb_bound.hpp) against the certified overlap of the shapes at the sample:
// on dyadic pairs in exact orientations (touching faces, parallel edges, overlapping, a
// dyadic gap; near and far from the origin) and random pairs it reports every pair that
// may touch; for two crates it is exact (the box is the shape); through the step pipeline
// on a spinning-sticks scene it never reports fewer pairs than touch.
#include <bounds/obb_bound.hpp>
#include <tests/bounds/rigid_bound_support.hpp>

#include <catch2/catch.hpp>

namespace bounds_obb_bound_test {

TEST_CASE("obb reports every touching pair of dyadic and random shapes", "[bounds][obb][zero_miss]") {
  const ccd::Vec3 offset = GENERATE(ccd::Vec3(0, 0, 0), ccd::Vec3(1048576, -1048576, 1048576));
  ccd::ObbBound bound;
  ccd::test::check_every_touching_pair(bound, offset, 41);
}

TEST_CASE("obb is exact for crates", "[bounds][obb]") {
  // Two crates (shape 0) only: the oriented box is the shape, so the test reports a pair
  // exactly when it may touch (up to the SAT's 1e-9 parallel-edge epsilon; gaps below are
  // 1e-7 or more, or zero).
  std::mt19937_64 rng(43);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  ccd::Scene s;
  ccd::test::add_test_shapes(s);
  for (int k = 0; k < 3000; ++k) {
    for (int i = 0; i < 2; ++i) {
      ccd::Quat q(u(rng), u(rng), u(rng), u(rng));
      q.normalize();
      const ccd::Vec3 c = ccd::Vec3(0, 8.0 * k, 0) + (i ? ccd::Vec3(u(rng), u(rng), 0.5 * u(rng)) : ccd::Vec3::Zero());
      s.add_rigid_body(ccd::test::body_at(c), ccd::test::shaped(0, q));
    }
  }
  ccd::test::RigidStep st(std::move(s));
  ccd::ObbBound bound;
  std::vector<ccd::Aabb> boxes;
  bound.prepare(st.context(ccd::Knowledge::Instant, 0.0, 0.0), boxes);
  long wrong = 0, touching = 0, apart = 0;
  for (std::uint32_t a = 0; a < st.traj.size(); a += 2) {
    const ccd::ConvexDistance d = st.distance(a, a + 1, 0.0);
    const bool reported = boxes[a].overlaps(boxes[a + 1]) && bound.test(a, a + 1).possible();
    if (d.status != ccd::ConvexDistance::Status::Separated) {
      ++touching;
      if (!reported) ++wrong;
    } else if (d.lower > 1e-7) {
      ++apart;
      if (reported) ++wrong;
    }
  }
  CHECK(wrong == 0);
  CHECK(touching > 300);
  CHECK(apart > 300);
}

TEST_CASE("obb through the pipeline: never fewer candidates than touching pairs", "[bounds][obb][pipeline]") {
  ccd::test::check_pipeline_superset("obb");
}

}  // namespace bounds_obb_bound_test
