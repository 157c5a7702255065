#include <bounds/enclosing_sphere_bound.hpp>
#include <tests/bounds/bound_test_support.hpp>

#include <catch2/catch.hpp>

namespace bounds_enclosing_sphere_bound_test {

using ccd::Vec3;

TEST_CASE("enclosing sphere contains bounded-acceleration motion", "[bounds][enclosing_sphere][containment]") {
  std::mt19937_64 rng(321);
  ccd::EnclosingSphereBound bound;
  std::vector<ccd::Aabb> boxes;
  long failed = 0, boxed = 0;
  for (int rep = 0; rep < 12; ++rep) {
    const double h = rep % 3 == 0 ? 0.5 : 1.0 / 60;
    const ccd::test::Step st = ccd::test::random_gas(rng, 500, h, 2 * h, 40.0, rep % 4 != 0, rep % 2 == 0, 3);
    bound.prepare(st.context(ccd::Knowledge::Bounded), boxes);
    for (std::uint32_t i = 0; i < st.start.size(); ++i) {
      const auto& sh = bound.shape(i);
      boxed += sh.boxed;
      const double r = st.traj.radius(i);
      for (int k = 0; k <= 32; ++k) {
        const Vec3 x = st.traj.position(i, st.t0 + h * k / 32);
        const bool in = sh.boxed ? ((sh.box.lo.array() <= x.array() - r).all() && (x.array() + r <= sh.box.hi.array()).all())
                                 : (x - sh.centre).norm() <= sh.radius - r;
        failed += !in;
      }
    }
  }
  CHECK(failed == 0);
  CHECK(boxed > 100);  // the wall fallback was exercised
}

TEST_CASE("enclosing sphere radius balances the horn's ends", "[bounds][enclosing_sphere]") {
  // p = 0, v = (2, 0, 0), r = 1, A = 1, h = 1: A h < 2 |v|, so c = 1/2 + 1/8 and the
  // centre region's radius is |v| h / 2 + A h^2 / 4 = 1.25. With v = 0: c = h, A h^2 / 2.
  ccd::BodyState s[2] = {{Vec3::Zero(), Vec3(2, 0, 0), 1.0}, {Vec3(10, 0, 0), Vec3::Zero(), 1.0}};
  ccd::StepContext ctx;
  ctx.t0 = 0.0;
  ctx.t1 = 1.0;
  ctx.start = s;
  ctx.acceleration_bound = 1.0;
  ccd::EnclosingSphereBound bound;
  std::vector<ccd::Aabb> boxes;
  bound.prepare(ctx, boxes);
  CHECK(bound.shape(0).centre.x() == Approx(1.25));
  CHECK(bound.shape(0).radius == Approx(2.25));
  CHECK(bound.shape(1).radius == Approx(1.5));
  CHECK_FALSE(bound.test(0, 1).possible());  // 10 - 1.25 = 8.75 > 3.75
}

}  // namespace bounds_enclosing_sphere_bound_test
