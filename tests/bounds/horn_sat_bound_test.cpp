#include <bounds/horn_bound.hpp>
#include <bounds/horn_sat_bound.hpp>
#include <tests/bounds/bound_test_support.hpp>

#include <catch2/catch.hpp>

namespace bounds_horn_sat_bound_test {

using ccd::Vec3;

TEST_CASE("horn_sat trapezoids contain bounded-acceleration motion", "[bounds][horn_sat][containment]") {
  std::mt19937_64 rng(555);
  long failed = 0;
  for (int rep = 0; rep < 12; ++rep) {
    const double h = rep % 3 == 0 ? 0.5 : 1.0 / 60;
    ccd::HornSatBound bound(1 + rep % 5);
    std::vector<ccd::Aabb> boxes;
    const ccd::test::Step st = ccd::test::random_gas(rng, 400, h, 2 * h, 40.0, rep % 4 != 0, rep % 2 == 0, 3);
    bound.prepare(st.context(ccd::Knowledge::Bounded), boxes);
    for (std::uint32_t i = 0; i < st.start.size(); ++i) {
      const double r = st.traj.radius(i);
      for (int j = 0; j < bound.pieces(); ++j) {
        const ccd::OrientedTrapezoid z = bound.trapezoid(i, j);
        for (int k = 0; k <= 8; ++k) {
          const double t = z.t0 + (z.t1 - z.t0) * k / 8;
          const double u = (t - z.t0) / (z.t1 - z.t0);
          const Vec3 local = z.axes.transpose() * (st.traj.position(i, t) - (z.c0 + (z.c1 - z.c0) * u));
          const Vec3 half = z.h0 + (z.h1 - z.h0) * u;
          failed += !((local.cwiseAbs().array() + r <= half.array()).all());
        }
      }
    }
  }
  CHECK(failed == 0);
}

TEST_CASE("horn and horn_sat agree for axis-aligned velocities", "[bounds][horn_sat]") {
  // Velocities along coordinate axes make the oriented frames coordinate frames: both
  // bounds cover the same cubes, so they must accept the same pairs (up to the 1e-9 SAT
  // epsilon: pairs within 1e-6 of tangency are skipped) and report the same earliest time.
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<ccd::BodyState> s;
  for (int i = 0; i < 600; ++i) {
    Vec3 v = Vec3::Zero();
    v[i % 3] = (u(rng) - 0.5) * 40;
    s.push_back({Vec3(u(rng), u(rng), u(rng)) * 4, v, 0.05 + 0.2 * u(rng)});
  }
  ccd::StepContext ctx;
  ctx.t0 = 0.0;
  ctx.t1 = 0.05;
  ctx.start = s;
  ctx.acceleration_bound = 20.0;
  ccd::HornBound horn(3);
  ccd::HornSatBound sat(3);
  std::vector<ccd::Aabb> b1, b2;
  horn.prepare(ctx, b1);
  sat.prepare(ctx, b2);
  int agree = 0, accepted = 0;
  for (std::uint32_t a = 0; a < s.size(); ++a) {
    for (std::uint32_t b = a + 1; b < s.size(); ++b) {
      const ccd::PairTest r1 = horn.test(a, b), r2 = sat.test(a, b);
      const bool h1 = r1.possible(), h2 = r2.possible();
      const double e1 = r1.earliest, e2 = r2.earliest;
      if (h1) CHECK(h2);  // conservative at least where horn is
      if (h1 == h2) ++agree;
      if (h1 && h2) {
        ++accepted;
        CHECK(e2 <= e1);
        CHECK(e2 >= e1 - 1e-6);
      }
    }
  }
  CHECK(accepted > 100);
  CHECK(agree >= static_cast<int>(s.size() * (s.size() - 1) / 2) - 20);  // only near-tangent pairs may differ
}

}  // namespace bounds_horn_sat_bound_test
