#include <bounds/rounding.hpp>
#include <bounds/trapezoid.hpp>
#include <bounds/wall_fold.hpp>
#include <tests/bounds/bound_test_support.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <optional>
#include <random>

namespace bounds_trapezoid_test {

using ccd::Trapezoid;
using ccd::PairTest;
using ccd::Vec3;

namespace {

Trapezoid random_trapezoid(std::mt19937_64& rng, double t0, double t1) {
  std::uniform_real_distribution<double> u(-2.0, 2.0), w(0.0, 1.0);
  Trapezoid z;
  z.t0 = t0;
  z.t1 = t1;
  const Vec3 c0(u(rng), u(rng), u(rng)), c1(u(rng), u(rng), u(rng));
  const Vec3 h0(w(rng), w(rng), w(rng)), h1(w(rng), w(rng), w(rng));
  z.lo0 = c0 - h0;
  z.hi0 = c0 + h0;
  z.lo1 = c1 - h1;
  z.hi1 = c1 + h1;
  return z;
}

// Largest per-axis gap between two boxes (<= 0: they overlap as closed boxes).
double gap(const ccd::Aabb& a, const ccd::Aabb& b) {
  return std::max((a.lo - b.hi).maxCoeff(), (b.lo - a.hi).maxCoeff());
}

}  // namespace

TEST_CASE("trapezoid_overlap agrees with dense sampling in time", "[bounds][trapezoid]") {
  std::mt19937_64 rng(11);
  constexpr int samples = 1001;
  int possible = 0, disjoint = 0;
  for (int i = 0; i < 3000; ++i) {
    const double t0 = 0.25, t1 = 0.75;
    const Trapezoid a = random_trapezoid(rng, t0, t1);
    const Trapezoid b = random_trapezoid(rng, t0, t1);
    const PairTest o = ccd::trapezoid_overlap(a, b);
    double first_sampled = std::numeric_limits<double>::infinity();
    for (int k = 0; k < samples; ++k) {
      const double t = t0 + (t1 - t0) * k / (samples - 1);
      if (gap(a.at(t), b.at(t)) <= 0.0) {
        first_sampled = t;
        break;
      }
    }
    if (o.status == PairTest::Status::Disjoint) {
      ++disjoint;
      CHECK(first_sampled == std::numeric_limits<double>::infinity());  // never disjoint when sampled overlap
    } else {
      ++possible;
      CHECK(o.earliest >= t0);
      CHECK(o.earliest <= first_sampled);
      // The boxes touch at the reported time: the gap there is rounding only (faces ~2, so
      // a few ulps of 4).
      CHECK(gap(a.at(o.earliest), b.at(o.earliest)) <= 64 * std::numeric_limits<double>::epsilon() * 4);
      // ... and not earlier: just before it they are apart (unless it is t0).
      if (o.earliest > t0 + 1e-9) CHECK(gap(a.at(o.earliest - 1e-9), b.at(o.earliest - 1e-9)) > 0.0);
    }
  }
  CHECK(possible > 300);  // both outcomes exercised
  CHECK(disjoint > 300);
}

TEST_CASE("trapezoid_overlap named cases", "[bounds][trapezoid]") {
  Trapezoid a{0.0, 1.0, Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(0, 0, 0), Vec3(1, 1, 1)};
  SECTION("tangent exactly at the end: possible at t1") {
    // b slides in x from 3 to 1 (its lo face): touches a's hi face x = 1 at t = 1.
    Trapezoid b{0.0, 1.0, Vec3(3, 0, 0), Vec3(4, 1, 1), Vec3(1, 0, 0), Vec3(2, 1, 1)};
    const auto o = ccd::trapezoid_overlap(a, b);
    REQUIRE(o.status == PairTest::Status::Possible);
    CHECK(o.earliest == Approx(1.0));
  }
  SECTION("stationary and separated on one axis: disjoint") {
    Trapezoid b{0.0, 1.0, Vec3(0, 2, 0), Vec3(1, 3, 1), Vec3(0, 2, 0), Vec3(1, 3, 1)};
    CHECK(ccd::trapezoid_overlap(a, b).status == PairTest::Status::Disjoint);
  }
  SECTION("coincident: possible at t0") {
    const auto o = ccd::trapezoid_overlap(a, a);
    CHECK(o.status == PairTest::Status::Possible);
    CHECK(o.earliest == 0.0);
  }
  SECTION("passing through on different axes at different times: disjoint") {
    // Overlap in x only for t in [0, 0.125], in y only for t in [8/9, 1]: never both.
    Trapezoid b{0.0, 1.0, Vec3(0.5, 5, 0), Vec3(1.5, 6, 1), Vec3(4.5, 1, 0), Vec3(5.5, 2, 1)};
    b.lo0.y() = 5;
    b.hi0.y() = 6;
    b.lo1.y() = 0.5;
    b.hi1.y() = 1.5;
    CHECK(ccd::trapezoid_overlap(a, b).status == PairTest::Status::Disjoint);
  }
}

TEST_CASE("fold_interval encloses the reflected interval", "[bounds][wall_fold]") {
  // Triangle-wave reference: fold x into [L, H] by repeated reflection.
  const auto fold = [](double x, double L, double H) {
    const double w = H - L;
    double y = std::fmod(x - L, 2 * w);
    if (y < 0) y += 2 * w;
    return y <= w ? L + y : L + 2 * w - y;
  };
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-30.0, 30.0);
  const double L = 1.0, H = 9.0;
  for (int i = 0; i < 20000; ++i) {
    double lo = u(rng), hi = lo + std::abs(u(rng)) * (i % 3 == 0 ? 0.1 : 1.0);
    const ccd::Interval f = ccd::fold_interval(lo, hi, L, H);
    CHECK(f.lo >= L - 1e-12);
    CHECK(f.hi <= H + 1e-12);
    for (int k = 0; k <= 20; ++k) {
      const double x = lo + (hi - lo) * k / 20;
      const double y = fold(x, L, H);
      // 1e-12: the reference's fmod rounding on |x| <= 60.
      if (!(y >= f.lo - 1e-12 && y <= f.hi + 1e-12)) FAIL("x " << x << " folds to " << y << " outside [" << f.lo << ", " << f.hi << "]");
    }
  }
  SECTION("inside: unchanged") {
    const auto f = ccd::fold_interval(2, 3, L, H);
    CHECK(f.lo == 2);
    CHECK(f.hi == 3);
  }
  SECTION("short overshoot folds onto the clipped interval") {
    const auto f = ccd::fold_interval(5, 10, L, H);  // 10 mirrors to 8, inside [5, 9]
    CHECK(f.lo == 5);
    CHECK(f.hi == 9);
  }
  SECTION("long overshoot extends below") {
    const auto f = ccd::fold_interval(8, 12, L, H);  // 12 mirrors to 6
    CHECK(f.lo == 6);
    CHECK(f.hi == 9);
  }
}

TEST_CASE("horn trapezoids contain bounded-acceleration motions", "[bounds][trapezoid][containment]") {
  // Checked directly on the trapezoids (not only their hull): at every sampled time the
  // body lies in the trapezoid of its sub-interval, walls and acceleration changes included.
  std::mt19937_64 rng(99);
  std::vector<Trapezoid> z;
  long failed = 0;
  for (int rep = 0; rep < 24; ++rep) {
    const double h = rep % 3 == 0 ? 0.5 : 1.0 / 60;
    const int m = 1 + rep % 6;
    const ccd::test::Step st = ccd::test::random_gas(rng, 400, h, 2 * h, 40.0, rep % 4 != 0, rep % 2 == 0, 4);
    z.resize(m);
    for (std::size_t i = 0; i < st.start.size(); ++i) {
      ccd::horn_trapezoids(st.start[i], st.t0, st.t1, st.A, st.scene.box, m, z.data());
      for (int j = 0; j < m; ++j) {
        for (int k = 0; k <= 16; ++k) {
          const double t = z[j].t0 + (z[j].t1 - z[j].t0) * k / 16;
          const ccd::Aabb b = z[j].at(t);
          const Vec3 c = st.traj.position(i, t);
          const double r = st.traj.radius(i);
          if (!((b.lo.array() <= c.array() - r).all() && (c.array() + r <= b.hi.array()).all())) ++failed;
        }
      }
    }
  }
  CHECK(failed == 0);
}

TEST_CASE("horn trapezoids are the per-sub-interval formula, bit for bit, folded or not", "[bounds][trapezoid]") {
  // Node j of M at s_j = h j / M (s_M = h): centre p + v s_j, half-width A s_j^2 / 2 plus the
  // rounding slack, faces widened by r. Dyadic inputs keep every product exact, so the
  // reference is the same doubles however the compiler contracts it. Covers the shared-node
  // path (no fold, M <= 16) and the per-piece loop (M = 17; a fold elsewhere in the call):
  // every unfolded axis of every sub-interval must match.
  struct Case {
    Vec3 p, v;
    double r, A, t0, h;
    bool walls;
  };
  const double far = 0x1p40;
  const std::vector<Case> cases = {
      {Vec3(1, 2, 3), Vec3(0.5, -0.25, 2), 0.5, 0.0, 0.0, 17.0 / 64, false},
      {Vec3(1, 2, 3), Vec3(0.5, -0.25, 2), 0.5, 4.0, 0.25, 17.0 / 64, true},        // walls far
      {Vec3(far, -far, 1), Vec3(1024, 0, -8), 2.0, 1.0, 1024.0, 17.0 / 64, false},  // far from the origin
      {Vec3(14.5, 2, 3), Vec3(8, 0, 0), 0.5, 0.0, 0.0, 17.0 / 64, true},  // reaches x = 15: the last pieces fold
      {Vec3(0.5, 2, 3), Vec3(0, 0, 0), 0.5, 0.0, 0.0, 17.0 / 64, true},   // at rest, tangent to the x = 0 wall
  };
  ccd::WallBox box;
  box.min = Vec3(0, 0, 0);
  box.max = Vec3(15.5, 16, 16);
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const Case& k = cases[c];
    ccd::BodyState s;
    s.position = k.p;
    s.velocity = k.v;
    s.radius = k.r;
    const std::optional<ccd::WallBox> walls = k.walls ? std::optional<ccd::WallBox>(box) : std::nullopt;
    for (const int m : {1, 4, 16, 17}) {
      INFO("case " << c << " M " << m);
      const double h = m == 17 ? k.h : 0.25;  // h j / 17 = j / 64 exactly; h j / M dyadic otherwise
      const double t1 = k.t0 + h;
      std::vector<Trapezoid> z(m);
      const bool folded = ccd::horn_trapezoids(s, k.t0, t1, k.A, walls, m, z.data());
      const double magnitude = k.p.cwiseAbs().maxCoeff() + k.r + k.v.cwiseAbs().maxCoeff() * h + k.A * h * h;
      const double slack = ccd::rounding_slack(magnitude);
      int unfolded_axes = 0;
      for (int j = 0; j < m; ++j) {
        const double sa = j == 0 ? 0.0 : h * j / m, sb = j + 1 == m ? h : h * (j + 1) / m;
        REQUIRE(z[j].t0 == k.t0 + sa);
        REQUIRE(z[j].t1 == (j + 1 == m ? t1 : k.t0 + sb));
        const double wa = 0.5 * k.A * sa * sa + slack, wb = 0.5 * k.A * sb * sb + slack;
        for (int a = 0; a < 3; ++a) {
          const double ca = k.p[a] + k.v[a] * sa, cb = k.p[a] + k.v[a] * sb;
          const double L = box.min[a] + k.r, H = box.max[a] - k.r;
          const bool folds = walls && (std::min(ca - wa, cb - wb) < L || std::max(ca + wa, cb + wb) > H);
          if (folds) {
            REQUIRE(folded);
            REQUIRE(z[j].lo0[a] == z[j].lo1[a]);  // a folded face does not move
            continue;
          }
          ++unfolded_axes;
          CHECK(z[j].lo0[a] == (ca - wa) - k.r);
          CHECK(z[j].hi0[a] == (ca + wa) + k.r);
          CHECK(z[j].lo1[a] == (cb - wb) - k.r);
          CHECK(z[j].hi1[a] == (cb + wb) + k.r);
        }
      }
      REQUIRE(unfolded_axes > 0);
      if (c == 3) REQUIRE(folded);
      if (c != 3 && c != 4) REQUIRE_FALSE(folded);
    }
  }
}

TEST_CASE("trapezoid_sequence_overlap splits at the union of both bodies' breakpoints", "[bounds][trapezoid][windows]") {
  // a: the unit box at rest over [0, 1], as two pieces split at 1/2.
  const Trapezoid a0{0.0, 0.5, Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(0, 0, 0), Vec3(1, 1, 1)};
  const Trapezoid a1{0.5, 1.0, Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(0, 0, 0), Vec3(1, 1, 1)};
  const Trapezoid a[] = {a0, a1};
  SECTION("b over a later window touches at its own end, t = 3/4") {
    // b's lo face x goes from 3 at t = 1/4 to 1 at t = 3/4: touches a's face x = 1 at 3/4.
    const Trapezoid b[] = {{0.25, 0.75, Vec3(3, 0, 0), Vec3(4, 1, 1), Vec3(1, 0, 0), Vec3(2, 1, 1)}};
    const PairTest o = ccd::trapezoid_sequence_overlap(a, 2, b, 1);
    REQUIRE(o.possible());
    CHECK(o.earliest <= 0.75);  // never after the exact contact (dyadic, so exact in double)
    CHECK(o.earliest >= 0.75 - 1e-14);
    const PairTest swapped = ccd::trapezoid_sequence_overlap(b, 1, a, 2);
    REQUIRE(swapped.possible());
    CHECK(swapped.earliest <= 0.75);
  }
  SECTION("b stops 2^-20 short of a: disjoint") {
    const Trapezoid b[] = {{0.25, 0.75, Vec3(3, 0, 0), Vec3(4, 1, 1), Vec3(1 + 0x1p-20, 0, 0), Vec3(2, 1, 1)}};
    CHECK_FALSE(ccd::trapezoid_sequence_overlap(a, 2, b, 1).possible());
  }
  SECTION("contact exactly at a's breakpoint t = 1/2, inside b's piece") {
    // lo face from 2 at 1/4 to 0 at 3/4: x = 1 at t = 1/2.
    const Trapezoid b[] = {{0.25, 0.75, Vec3(2, 0, 0), Vec3(3, 1, 1), Vec3(0, 0, 0), Vec3(1, 1, 1)}};
    const PairTest o = ccd::trapezoid_sequence_overlap(a, 2, b, 1);
    REQUIRE(o.possible());
    CHECK(o.earliest <= 0.5);
    CHECK(o.earliest >= 0.5 - 1e-14);
  }
  SECTION("far from the origin (2^20): the same contact time") {
    const Vec3 off(0x1p20, -0x1p20, 0x1p20);
    const Trapezoid f0{0.0, 0.5, off, off + Vec3(1, 1, 1), off, off + Vec3(1, 1, 1)};
    const Trapezoid f1{0.5, 1.0, off, off + Vec3(1, 1, 1), off, off + Vec3(1, 1, 1)};
    const Trapezoid fa[] = {f0, f1};
    const Trapezoid b[] = {{0.25, 0.75, off + Vec3(2, 0, 0), off + Vec3(3, 1, 1), off, off + Vec3(1, 1, 1)}};
    const PairTest o = ccd::trapezoid_sequence_overlap(fa, 2, b, 1);
    REQUIRE(o.possible());
    CHECK(o.earliest <= 0.5);
    CHECK(o.earliest >= 0.5 - 1e-9);
  }
  SECTION("windows that share no time: disjoint, even for coincident boxes") {
    const Trapezoid b[] = {{2.0, 3.0, Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(0, 0, 0), Vec3(1, 1, 1)}};
    CHECK_FALSE(ccd::trapezoid_sequence_overlap(a, 2, b, 1).possible());
  }
  SECTION("windows that share one instant: tested at that instant") {
    const Trapezoid b[] = {{1.0, 2.0, Vec3(0.5, 0, 0), Vec3(1.5, 1, 1), Vec3(5, 0, 0), Vec3(6, 1, 1)}};
    const PairTest o = ccd::trapezoid_sequence_overlap(a, 2, b, 1);
    REQUIRE(o.possible());
    CHECK(o.earliest == 1.0);
  }
}

TEST_CASE("trapezoid_sequence_overlap agrees with dense sampling over different windows", "[bounds][trapezoid][windows]") {
  // Random pieces over two overlapping windows with unrelated breakpoints (3 and 5 pieces):
  // never disjoint where sampling finds an overlap, and never later than the first one.
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int possible = 0, disjoint = 0;
  const auto sequence = [&](double t0, double t1, int m, std::vector<Trapezoid>& out) {
    out.clear();
    for (int j = 0; j < m; ++j) {
      const double s0 = t0 + (t1 - t0) * j / m, s1 = j + 1 == m ? t1 : t0 + (t1 - t0) * (j + 1) / m;
      Trapezoid z = random_trapezoid(rng, s0, s1);
      if (j > 0) {  // contiguous: starts where the previous piece ends
        z.lo0 = out.back().lo1;
        z.hi0 = out.back().hi1;
      }
      out.push_back(z);
    }
  };
  std::vector<Trapezoid> za, zb;
  for (int i = 0; i < 3000; ++i) {
    const double a0 = 0.25 * u(rng), b0 = 0.25 + 0.25 * u(rng);
    sequence(a0, a0 + 0.5, 3, za);
    sequence(b0, b0 + 0.5, 5, zb);
    const PairTest o = ccd::trapezoid_sequence_overlap(za.data(), 3, zb.data(), 5);
    const double lo = std::max(a0, b0), hi = std::min(a0 + 0.5, b0 + 0.5);
    const auto box_at = [](const std::vector<Trapezoid>& z, double t) {
      for (const Trapezoid& p : z)
        if (t <= p.t1) return p.at(std::max(t, p.t0));
      return z.back().at(z.back().t1);
    };
    double first_sampled = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= 1000; ++k) {
      const double t = lo + (hi - lo) * k / 1000;
      if (gap(box_at(za, t), box_at(zb, t)) <= 0.0) {
        first_sampled = t;
        break;
      }
    }
    if (!o.possible()) {
      ++disjoint;
      CHECK(first_sampled == std::numeric_limits<double>::infinity());
    } else {
      ++possible;
      CHECK(o.earliest >= lo);
      CHECK(o.earliest <= first_sampled);
    }
  }
  CHECK(possible > 300);
  CHECK(disjoint > 300);
}

}  // namespace bounds_trapezoid_test
