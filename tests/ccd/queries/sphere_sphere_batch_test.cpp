// The batched sphere-sphere query and its certified filter against the scalar exact
// query: every answer bit for bit (status and toi), on adversarial dyadic cases and on
// random pairs, and the filter's verdicts must actually settle pairs (else it is dead code).
#include <ccd/queries/sphere_pair_filter.hpp>
#include <ccd/queries/sphere_sphere_batch.hpp>
#include <ccd/queries/sphere_sphere_contact.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace ccd_queries_sphere_sphere_batch_test {

using ccd::MovingSphere;
using ccd::Vec3;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

MovingSphere sphere(Vec3 p, Vec3 v, double r) {
  MovingSphere s;
  s.position = p;
  s.velocity = v;
  s.radius = r;
  return s;
}

bool same_bits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

// Every pair of `pairs` answered by the batch and by the scalar query: identical.
// Returns how many pairs the filter settled (Apart or Contact).
std::size_t check_batch(const ccd::LinearSpherePairs& pairs, double S) {
  std::vector<ccd::SphereSphereContact> out(pairs.size());
  ccd::sphere_sphere_first_contact_batch(pairs, S, out);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const ccd::SphereSphereContact want = ccd::sphere_sphere_first_contact(pairs.a(i), pairs.b(i), S);
    INFO("pair " << i << " toi " << out[i].toi << " want " << want.toi);
    REQUIRE(out[i].status == want.status);
    REQUIRE(same_bits(out[i].toi, want.toi));
  }
  return pairs.size();
}

// The filter's verdict on one linear pair (block of one).
ccd::PairVerdict verdict_of(const MovingSphere& a, const MovingSphere& b, double S) {
  ccd::RelativeMotionBlock k;
  k.count = 1;
  k.dx[0] = b.position.x() - a.position.x();
  k.dy[0] = b.position.y() - a.position.y();
  k.dz[0] = b.position.z() - a.position.z();
  k.vx[0] = b.velocity.x() - a.velocity.x();
  k.vy[0] = b.velocity.y() - a.velocity.y();
  k.vz[0] = b.velocity.z() - a.velocity.z();
  k.radius_sum[0] = a.radius + b.radius;
  double P = 0.0;
  for (int c = 0; c < 3; ++c)
    P = std::max({P, std::fabs(a.position[c]) + std::fabs(a.velocity[c]) * S,
                  std::fabs(b.position[c]) + std::fabs(b.velocity[c]) * S});
  k.magnitude[0] = P;
  k.model[0] = 0.0;
  ccd::PairVerdict v{};
  ccd::classify_relative_motion(k, S, &v);
  return v;
}

}  // namespace

TEST_CASE("batched sphere contact: adversarial dyadic cases equal the scalar exact query", "[queries][batch]") {
  // Each case: a, b, the duration, and (in the comment) the exact answer.
  struct Case {
    MovingSphere a, b;
    double S;
  };
  const double far = 1099511627776.0;  // 2^40: far from the origin
  const std::vector<Case> cases = {
      // Tangent: b passes a at centre distance exactly 2 = r_a + r_b: touches at t = 4.
      {sphere(Vec3(0, 0, 0), Vec3(0, 0, 0), 1), sphere(Vec3(4, 2, 0), Vec3(-1, 0, 0), 1), 8},
      // The same far from the origin (all coordinates + 2^40: still exact dyadics).
      {sphere(Vec3(far, far, far), Vec3(0, 0, 0), 1), sphere(Vec3(far + 4, far + 2, far), Vec3(-1, 0, 0), 1), 8},
      // Misses the tangency by 2^-20 (miss), and overlaps it by 2^-20 (contact).
      {sphere(Vec3(0, 0, 0), Vec3(0, 0, 0), 1), sphere(Vec3(4, 2 + 0x1p-20, 0), Vec3(-1, 0, 0), 1), 8},
      {sphere(Vec3(0, 0, 0), Vec3(0, 0, 0), 1), sphere(Vec3(4, 2 - 0x1p-20, 0), Vec3(-1, 0, 0), 1), 8},
      // Coincident centres: Overlapping at 0.
      {sphere(Vec3(1, 2, 3), Vec3(1, 0, 0), 0.5), sphere(Vec3(1, 2, 3), Vec3(0, 1, 0), 0.25), 1},
      // Zero relative velocity, apart (Miss) and overlapping (Overlapping).
      {sphere(Vec3(0, 0, 0), Vec3(3, 1, 2), 1), sphere(Vec3(5, 0, 0), Vec3(3, 1, 2), 1), 1},
      {sphere(Vec3(0, 0, 0), Vec3(3, 1, 2), 1), sphere(Vec3(1.5, 0, 0), Vec3(3, 1, 2), 1), 1},
      // Zero velocity both, touching exactly at t = 0 (distance == R): Overlapping at 0.
      {sphere(Vec3(0, 0, 0), Vec3(0, 0, 0), 1), sphere(Vec3(2, 0, 0), Vec3(0, 0, 0), 1), 1},
      // Touching at t = 0 and separating; touching at 0 and approaching.
      {sphere(Vec3(0, 0, 0), Vec3(-1, 0, 0), 1), sphere(Vec3(2, 0, 0), Vec3(1, 0, 0), 1), 1},
      {sphere(Vec3(0, 0, 0), Vec3(1, 0, 0), 1), sphere(Vec3(2, 0, 0), Vec3(-1, 0, 0), 1), 1},
      // Contact exactly at the end of the window: gap 2, closing speed 2, S = 1 -> Hit at 1.
      {sphere(Vec3(0, 0, 0), Vec3(1, 0, 0), 1), sphere(Vec3(4, 0, 0), Vec3(-1, 0, 0), 1), 1},
      // ... and just after it (S = 1 - 2^-30): Miss.
      {sphere(Vec3(0, 0, 0), Vec3(1, 0, 0), 1), sphere(Vec3(4, 0, 0), Vec3(-1, 0, 0), 1), 1 - 0x1p-30},
      // Equal coordinates and parallel motion along one axis, head-on: Hit at 1.5.
      {sphere(Vec3(0, 7, 7), Vec3(1, 0, 0), 0.5), sphere(Vec3(4, 7, 7), Vec3(-1, 0, 0), 0.5), 4},
      // Deep overlap far from the origin, moving fast.
      {sphere(Vec3(-far, 0, far), Vec3(1024, 0, 0), 4), sphere(Vec3(-far + 1, 0, far), Vec3(-1024, 0, 0), 4), 2},
      // Zero duration: contact only if touching at 0.
      {sphere(Vec3(0, 0, 0), Vec3(1, 0, 0), 1), sphere(Vec3(3, 0, 0), Vec3(-1, 0, 0), 1), 0},
      {sphere(Vec3(0, 0, 0), Vec3(1, 0, 0), 1), sphere(Vec3(1, 0, 0), Vec3(-1, 0, 0), 1), 0},
      // Tiny spheres, large coordinates: apart by far more than the rounding.
      {sphere(Vec3(far, 0, 0), Vec3(0, 0, 0), 0x1p-20), sphere(Vec3(far + 1, 0, 0), Vec3(0, 0, 0), 0x1p-20), 1},
      // Passing through each other within the window: Hit at 0.5 (gap 1, closing 2).
      {sphere(Vec3(0, 0, 0), Vec3(1, 0, 0), 0.5), sphere(Vec3(2, 0, 0), Vec3(-1, 0, 0), 0.5), 4},
      // Non-finite data: the scalar query's Miss.
      {sphere(Vec3(std::nan(""), 0, 0), Vec3(0, 0, 0), 1), sphere(Vec3(1, 0, 0), Vec3(0, 0, 0), 1), 1},
      {sphere(Vec3(0, 0, 0), Vec3(inf, 0, 0), 1), sphere(Vec3(1, 0, 0), Vec3(0, 0, 0), 1), 0},
      {sphere(Vec3(0, 0, 0), Vec3(0, 0, 0), inf), sphere(Vec3(1, 0, 0), Vec3(0, 0, 0), 1), 1},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    INFO("case " << i);
    ccd::LinearSpherePairs pairs;
    pairs.push_back(cases[i].a, cases[i].b);
    check_batch(pairs, cases[i].S);
  }
  SECTION("the worked answers") {
    // Tangent at t = 4: the exact query reports the touch, and so does the batch.
    ccd::LinearSpherePairs pairs;
    pairs.push_back(cases[0].a, cases[0].b);
    std::vector<ccd::SphereSphereContact> out(1);
    ccd::sphere_sphere_first_contact_batch(pairs, 8, out);
    CHECK(out[0].status == ccd::ContactStatus::Hit);
    CHECK(out[0].toi == Approx(4.0).margin(1e-6));
    // Touching at t = 0 exactly: Overlapping; the filter leaves the touch to the solver.
    CHECK(verdict_of(cases[7].a, cases[7].b, 1) == ccd::PairVerdict::Solve);
    CHECK(verdict_of(cases[6].a, cases[6].b, 1) == ccd::PairVerdict::Contact);
    CHECK(verdict_of(cases[5].a, cases[5].b, 1) == ccd::PairVerdict::Apart);
    CHECK(verdict_of(cases[0].a, cases[0].b, 8) == ccd::PairVerdict::Solve);
  }
  SECTION("a negative or non-finite duration: the scalar query's answer (Miss)") {
    ccd::LinearSpherePairs pairs;
    pairs.push_back(cases[6].a, cases[6].b);
    check_batch(pairs, -1.0);
    check_batch(pairs, inf);
    check_batch(pairs, std::nan(""));
  }
  SECTION("accelerating spheres are refused, sizes must match") {
    ccd::LinearSpherePairs pairs;
    MovingSphere a = cases[0].a;
    a.acceleration = Vec3(0, 0, -1);
    CHECK_THROWS_AS(pairs.push_back(a, cases[0].b), std::invalid_argument);
    pairs.push_back(cases[0].a, cases[0].b);
    std::vector<ccd::SphereSphereContact> out(2);
    CHECK_THROWS_AS(ccd::sphere_sphere_first_contact_batch(pairs, 1.0, out), std::invalid_argument);
  }
}

TEST_CASE("batched sphere contact: near-tangent passes at every scale of the gap", "[queries][batch]") {
  // b passes a at centre distance 2 + g (R = 2) for g = +-2^-k, k = 1..52, at several
  // offsets from the origin: the exact answer flips with the sign of g; the filter must
  // settle the wide gaps and leave the narrow ones to the solver, always agreeing.
  ccd::LinearSpherePairs pairs;
  for (const double offset : {0.0, 1024.0, 0x1p30, -0x1p45})
    for (int k = 1; k <= 52; ++k)
      for (const double sign : {1.0, -1.0}) {
        const double g = sign * std::ldexp(1.0, -k);
        pairs.push_back(sphere(Vec3(offset, offset, 0), Vec3(0, 0, 0), 1),
                        sphere(Vec3(offset + 4, offset + 2 + g, 0), Vec3(-1, 0, 0), 1));
      }
  check_batch(pairs, 8.0);
  std::size_t apart = 0, solve = 0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const ccd::PairVerdict v = verdict_of(pairs.a(i), pairs.b(i), 8.0);
    apart += v == ccd::PairVerdict::Apart;
    solve += v == ccd::PairVerdict::Solve;
    // A pass with the gap positive must never be called a contact, nor a negative gap apart.
    const bool overlapping_pass = (i % 2) == 1;
    if (overlapping_pass) CHECK(v != ccd::PairVerdict::Apart);
    CHECK(v != ccd::PairVerdict::Contact);  // none touches at t = 0
  }
  CHECK(apart > 0);
  CHECK(solve > 0);
}

TEST_CASE("batched sphere contact: random pairs equal the scalar exact query", "[queries][batch]") {
#ifdef CCDLAB_SANITIZED
  constexpr std::size_t n = 3000;
#else
  constexpr std::size_t n = 20000;
#endif
  std::mt19937_64 gen(18);
  std::uniform_real_distribution<double> pos(0, 10), vel(-10, 10), rad(0.5, 1.5), scale_pick(0, 1);
  ccd::LinearSpherePairs pairs;
  for (std::size_t i = 0; i < n; ++i) {
    // Mostly the kernel benchmark's distribution; one pair in four far from the origin,
    // one in eight on a dyadic grid (equal coordinates, exact touches).
    const double u = scale_pick(gen);
    const double shift = u < 0.25 ? 0x1p32 : 0.0;
    MovingSphere s[2];
    for (MovingSphere& x : s) {
      x.position = Vec3(pos(gen) + shift, pos(gen), pos(gen) - shift);
      x.velocity = Vec3(vel(gen), vel(gen), vel(gen));
      x.radius = rad(gen);
      if (u > 0.875) {
        x.position = (x.position * 4).array().round() / 4;
        x.velocity = (x.velocity * 2).array().round() / 2;
        x.radius = std::round(x.radius * 4) / 4;
      }
    }
    pairs.push_back(s[0], s[1]);
  }
  check_batch(pairs, 1.0);
  std::size_t counts[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) ++counts[static_cast<int>(verdict_of(pairs.a(i), pairs.b(i), 1.0))];
  // The filter settles most pairs (apart and overlapping ones), the solver the rest.
  CHECK(counts[0] > n / 2);
  CHECK(counts[1] > 0);
  CHECK(counts[2] > 0);
  CHECK(counts[2] < n / 4);
}

}  // namespace ccd_queries_sphere_sphere_batch_test
