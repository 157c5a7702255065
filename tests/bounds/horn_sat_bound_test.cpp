#include <bounds/horn_bound.hpp>
#include <bounds/horn_sat_bound.hpp>
#include <tests/bounds/bound_test_support.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

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

// Every output of `a` and `b` (boxes, trapezoids, window, pair tests) is the same, bit for bit.
bool same_bits(const void* x, const void* y, std::size_t size) { return std::memcmp(x, y, size) == 0; }

long differences(const ccd::HornSatBound& a, const std::vector<ccd::Aabb>& boxes_a, const ccd::HornSatBound& b,
                 const std::vector<ccd::Aabb>& boxes_b) {
  long diff = 0;
  const auto n = static_cast<std::uint32_t>(boxes_a.size());
  if (boxes_b.size() != n) return 1;
  for (std::uint32_t i = 0; i < n; ++i) {
    diff += !same_bits(&boxes_a[i], &boxes_b[i], sizeof(ccd::Aabb));
    const ccd::Window wa = a.window(i), wb = b.window(i);
    diff += wa.t0 != wb.t0 || wa.t1 != wb.t1;
    for (int j = 0; j < a.pieces(); ++j) {
      const ccd::OrientedTrapezoid x = a.trapezoid(i, j), y = b.trapezoid(i, j);
      diff += !same_bits(&x.t0, &y.t0, sizeof(double)) || !same_bits(&x.t1, &y.t1, sizeof(double)) ||
              !same_bits(x.axes.data(), y.axes.data(), sizeof(double) * 9) ||
              !same_bits(x.c0.data(), y.c0.data(), sizeof(ccd::Vec3)) ||
              !same_bits(x.c1.data(), y.c1.data(), sizeof(ccd::Vec3)) ||
              !same_bits(x.h0.data(), y.h0.data(), sizeof(ccd::Vec3)) ||
              !same_bits(x.h1.data(), y.h1.data(), sizeof(ccd::Vec3));
    }
  }
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t k = i + 1; k < n; ++k) {
      const ccd::PairTest x = a.test(i, k), y = b.test(i, k);
      diff += x.status != y.status || !same_bits(&x.earliest, &y.earliest, sizeof(double));
    }
  return diff;
}

bool is_identity(const Eigen::Matrix3d& m) { return m == Eigen::Matrix3d::Identity(); }

TEST_CASE("horn_sat keeps frames across steps with the outputs of a fresh bound", "[bounds][horn_sat]") {
  // One bound stepped through 40 steps (frames kept from step to step) against a fresh
  // bound per step, in a walled box: half the bodies coast (their velocity is the same
  // between wall hits: frames kept), the others accelerate (new velocity every step), some are kicked (a velocity
  // change), and
  // walls fold some horns (the identity frame) and reflect bodies. A frame kept for a
  // velocity that changed, or kept through a folded step, changes the trapezoids' axes.
  std::mt19937_64 rng(3535);
  const int steps = 40;
  const double dt = 1.0 / 64;
  ccd::test::Step st = ccd::test::random_gas(rng, 160, 0.0, dt, 20.0, true, false, 2);
  st.scene.horizon = steps * dt;
  for (std::size_t i = 0; i < st.scene.bodies.size(); i += 2) {  // coasting bodies, some kicked
    st.scene.bodies[i].acceleration.setZero();
    st.scene.bodies[i].acceleration_changes.clear();
    if (i % 4 == 0) st.scene.bodies[i].velocity_changes.push_back({steps * dt / 2 + dt / 5, ccd::test::random_vec(rng, 30.0)});
  }
  for (std::size_t i = 1; i < st.scene.bodies.size(); i += 2) {  // accelerations that change mid-run
    std::vector<ccd::AccelerationChange>& ch = st.scene.bodies[i].acceleration_changes;
    ch.clear();
    for (int c = 1; c <= 3; ++c) ch.push_back({steps * dt * c / 4 + dt / 3, ccd::test::random_vec(rng, 15.0)});
  }
  ccd::HornSatBound kept(4);
  std::vector<ccd::Aabb> kept_boxes;
  std::vector<Eigen::Matrix3d> last(st.scene.bodies.size(), Eigen::Matrix3d::Zero());
  std::vector<ccd::Vec3> last_velocity(st.scene.bodies.size(), ccd::Vec3::Constant(std::nan("")));
  long diff = 0, reused = 0, renewed = 0, unfolded_same_velocity = 0;
  for (int k = 0; k < steps; ++k) {
    st.finish(k * dt, (k + 1) * dt);
    const ccd::StepContext ctx = st.context(ccd::Knowledge::Bounded);
    kept.prepare(ctx, kept_boxes);
    ccd::HornSatBound fresh(4);
    std::vector<ccd::Aabb> fresh_boxes;
    fresh.prepare(ctx, fresh_boxes);
    diff += differences(kept, kept_boxes, fresh, fresh_boxes);
    for (std::uint32_t i = 0; i < st.start.size(); ++i) {
      const Eigen::Matrix3d& f = fresh.trapezoid(i, 0).axes;
      const bool same_velocity = same_bits(st.start[i].velocity.data(), last_velocity[i].data(), sizeof(ccd::Vec3));
      if (!is_identity(f)) {
        reused += same_velocity && f == last[i];
        renewed += !same_velocity;
        unfolded_same_velocity += same_velocity && is_identity(last[i]);
      }
      last[i] = f;
      last_velocity[i] = st.start[i].velocity;
    }
    // A scheduler's refresh of some bodies over the second half of the step, on top.
    std::vector<std::uint32_t> some;
    for (std::uint32_t i = static_cast<std::uint32_t>(k % 3); i < st.start.size(); i += 3) some.push_back(i);
    st.finish(k * dt + dt / 2, (k + 1) * dt);
    const ccd::StepContext late = st.context(ccd::Knowledge::Bounded);
    kept.refresh(late, some, kept_boxes);
    fresh.refresh(late, some, fresh_boxes);
    diff += differences(kept, kept_boxes, fresh, fresh_boxes);
  }
  CHECK(diff == 0);
  // The run exercises each case: frames kept, frames renewed, and a fold between two
  // steps of the same velocity (a kept frame would be the stale identity).
  CHECK(reused > 500);
  CHECK(renewed > 500);
  CHECK(unfolded_same_velocity > 0);
}

}  // namespace bounds_horn_sat_bound_test
