// `frame_aabb` (bounds/frame_aabb_bound.hpp) against the certified overlap of the shapes at
// the sample: on dyadic pairs in exact orientations (touching faces, parallel edges,
// overlapping, a dyadic gap; near and far from the origin) and on random pairs, it reports
// every pair that may touch; its box lies inside the enclosing sphere's box; through the
// step pipeline on a spinning-sticks scene it never reports fewer pairs than touch.
#include <bounds/aabb_bound.hpp>
#include <bounds/frame_aabb_bound.hpp>
#include <tests/bounds/rigid_bound_support.hpp>

#include <catch2/catch.hpp>

namespace bounds_frame_aabb_bound_test {

TEST_CASE("frame_aabb reports every touching pair of dyadic and random shapes", "[bounds][frame_aabb][zero_miss]") {
  const ccd::Vec3 offset = GENERATE(ccd::Vec3(0, 0, 0), ccd::Vec3(1048576, -1048576, 1048576));
  ccd::FrameAabbBound bound;
  ccd::test::check_every_touching_pair(bound, offset, 31);
}

TEST_CASE("frame_aabb's box lies inside the enclosing sphere's box", "[bounds][frame_aabb]") {
  std::mt19937_64 rng(32);
  ccd::test::RigidStep st(ccd::test::random_pairs(rng, 500, ccd::Vec3(3, -5, 7)));
  ccd::FrameAabbBound frame;
  ccd::AabbBound sphere_box;
  std::vector<ccd::Aabb> a, b;
  frame.prepare(st.context(ccd::Knowledge::Instant, 0.0, 0.0), a);
  sphere_box.prepare(st.context(ccd::Knowledge::Instant, 0.0, 0.0), b);
  long strictly = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK((b[i].lo.array() <= a[i].lo.array()).all());
    CHECK((a[i].hi.array() <= b[i].hi.array()).all());
    if (st.rigid.kind(i) != ccd::ShapeKind::Sphere && (a[i].hi - a[i].lo).sum() < 0.99 * (b[i].hi - b[i].lo).sum())
      ++strictly;
  }
  CHECK(strictly > 500);
}

TEST_CASE("frame_aabb through the pipeline: never fewer candidates than touching pairs", "[bounds][frame_aabb][pipeline]") {
  ccd::test::check_pipeline_superset("frame_aabb");
}

}  // namespace bounds_frame_aabb_bound_test
