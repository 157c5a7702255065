#include <bounds/oriented_trapezoid.hpp>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

namespace bounds_oriented_trapezoid_test {

using ccd::OrientedTrapezoid;
using ccd::PairTest;
using ccd::Vec3;

namespace {

Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
}

struct Box {
  Eigen::Matrix3d axes;
  Vec3 c, h;
  Vec3 project(const Vec3& x) const {
    const Vec3 local = axes.transpose() * (x - c);
    return c + axes * local.cwiseMax(-h).cwiseMin(h);
  }
};

Box at(const OrientedTrapezoid& z, double t) {
  const double u = (t - z.t0) / (z.t1 - z.t0);
  return {z.axes, z.c0 + (z.c1 - z.c0) * u, z.h0 + (z.h1 - z.h0) * u};
}

// Exact static overlap of two boxes inflated by `pad`: two convex polytopes intersect
// iff an edge of one meets the other (a vertex of one inside the other lies on such an
// edge; otherwise a vertex of the intersection is an edge-face crossing). Each edge is
// clipped against the other box's three slabs (Liang-Barsky) in that box's frame.
bool edge_hits(const Box& from, const Box& to, double pad) {
  for (int e = 0; e < 12; ++e) {
    const int axis = e / 4;  // the edge runs along `axis`; the other two signs pick it
    const int o1 = (axis + 1) % 3, o2 = (axis + 2) % 3;
    Vec3 lp = Vec3::Zero(), lq = Vec3::Zero();
    lp[axis] = -from.h[axis];
    lq[axis] = from.h[axis];
    lp[o1] = lq[o1] = (e & 1 ? 1 : -1) * from.h[o1];
    lp[o2] = lq[o2] = (e & 2 ? 1 : -1) * from.h[o2];
    const Vec3 p = to.axes.transpose() * (from.c + from.axes * lp - to.c);
    const Vec3 q = to.axes.transpose() * (from.c + from.axes * lq - to.c);
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 3 && lo <= hi; ++k) {
      const double d = q[k] - p[k], w = to.h[k] + pad;
      if (d == 0.0) {
        if (std::abs(p[k]) > w) hi = -1.0;
        continue;
      }
      double a = (-w - p[k]) / d, b = (w - p[k]) / d;
      if (a > b) std::swap(a, b);
      lo = std::max(lo, a);
      hi = std::min(hi, b);
    }
    if (lo <= hi) return true;
  }
  return false;
}

bool overlap(const Box& a, const Box& b, double pad) { return edge_hits(a, b, pad) || edge_hits(b, a, pad); }

OrientedTrapezoid random_oriented(std::mt19937_64& rng, const Eigen::Matrix3d& axes) {
  std::uniform_real_distribution<double> u(-2.0, 2.0), w(0.05, 1.0);
  OrientedTrapezoid z;
  z.t0 = 0.0;
  z.t1 = 1.0;
  z.axes = axes;
  z.c0 = Vec3(u(rng), u(rng), u(rng));
  z.c1 = Vec3(u(rng), u(rng), u(rng));
  z.h0 = Vec3(w(rng), w(rng), w(rng));
  z.h1 = Vec3(w(rng), w(rng), w(rng));
  return z;
}

}  // namespace

TEST_CASE("oriented_trapezoid_overlap agrees with sampled box distances", "[bounds][oriented_trapezoid]") {
  std::mt19937_64 rng(3);
#ifdef CCDLAB_SANITIZED
  constexpr int cases = 300;  // 1001 samples per case: about 20 s for 300 under ASan + UBSan
#else
  constexpr int cases = 3000;
#endif
  int possible = 0, disjoint = 0;
  for (int i = 0; i < cases; ++i) {
    const Eigen::Matrix3d ra = random_rotation(rng);
    // Every third pair shares an axis direction (parallel edges: degenerate cross axes).
    const Eigen::Matrix3d rb = i % 3 == 0 ? Eigen::Matrix3d(ra * Eigen::AngleAxisd(1.0, Vec3::UnitZ()))
                                          : random_rotation(rng);
    const OrientedTrapezoid a = random_oriented(rng, ra), b = random_oriented(rng, rb);
    const PairTest o = ccd::oriented_trapezoid_overlap(a, b);
    double first_sampled = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= 1000; ++k) {
      const double t = k / 1000.0;
      if (overlap(at(a, t), at(b, t), 0.0)) {
        first_sampled = t;
        break;
      }
    }
    if (o.status == PairTest::Status::Disjoint) {
      ++disjoint;
      CHECK(first_sampled == std::numeric_limits<double>::infinity());
    } else {
      ++possible;
      CHECK(o.earliest <= first_sampled);
      // At the reported time the boxes touch, up to the 1e-9 parallel epsilon (times
      // half-widths <= 1, on up to 15 axes) and the rounding slack: padded by 1e-7 they overlap.
      CHECK(overlap(at(a, o.earliest), at(b, o.earliest), 1e-7));
      // ... and just before it they are apart (unless it is t0).
      if (o.earliest > 1e-6) CHECK_FALSE(overlap(at(a, o.earliest - 1e-6), at(b, o.earliest - 1e-6), 0.0));
    }
  }
  CHECK(possible > cases / 10);
  CHECK(disjoint > cases / 10);
}

TEST_CASE("oriented and axis-aligned trapezoid tests agree for axis-aligned frames", "[bounds][oriented_trapezoid]") {
  // A frame that permutes and flips the axes describes the same boxes as the axis-aligned
  // trapezoid: the SAT must say Possible whenever the axis-aligned test does (conservative),
  // report the same earliest time, and say Disjoint whenever the axis-aligned test says
  // Disjoint with a margin of 1e-6 (the parallel epsilon loosens by <= 3e-9 here).
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(-2.0, 2.0), w(0.05, 1.0);
  Eigen::Matrix3d perm = Eigen::Matrix3d::Zero();
  perm(1, 0) = -1;
  perm(2, 1) = 1;
  perm(0, 2) = 1;
  int agree_possible = 0, agree_disjoint = 0;
  for (int i = 0; i < 20000; ++i) {
    ccd::Trapezoid aa, bb, aa_shrunk, bb_shrunk;
    OrientedTrapezoid oa, ob;
    for (auto* pr : {&aa, &bb}) {
      const Vec3 c0(u(rng), u(rng), u(rng)), c1(u(rng), u(rng), u(rng));
      const Vec3 h0(w(rng), w(rng), w(rng)), h1(w(rng), w(rng), w(rng));
      *pr = {0.0, 1.0, c0 - h0, c0 + h0, c1 - h1, c1 + h1};
      OrientedTrapezoid& o = pr == &aa ? oa : ob;
      o.t0 = 0.0;
      o.t1 = 1.0;
      o.axes = pr == &aa ? Eigen::Matrix3d::Identity() : perm;
      o.c0 = c0;
      o.c1 = c1;
      o.h0 = o.axes.transpose().cwiseAbs() * h0;  // half-widths along the frame's columns
      o.h1 = o.axes.transpose().cwiseAbs() * h1;
      ccd::Trapezoid& s = pr == &aa ? aa_shrunk : bb_shrunk;
      s = {0.0, 1.0, c0 - h0, c0 + h0, c1 - h1, c1 + h1};
      s.lo0.array() -= 1e-6;
      s.hi0.array() += 1e-6;
      s.lo1.array() -= 1e-6;
      s.hi1.array() += 1e-6;
    }
    const auto ref = ccd::trapezoid_overlap(aa, bb);
    const auto inflated = ccd::trapezoid_overlap(aa_shrunk, bb_shrunk);
    const auto sat = ccd::oriented_trapezoid_overlap(oa, ob);
    if (ref.status == PairTest::Status::Possible) {
      REQUIRE(sat.status == PairTest::Status::Possible);
      CHECK(sat.earliest <= ref.earliest);
      CHECK(sat.earliest >= inflated.earliest);
      ++agree_possible;
    }
    if (inflated.status == PairTest::Status::Disjoint) {
      CHECK(sat.status == PairTest::Status::Disjoint);
      ++agree_disjoint;
    }
  }
  CHECK(agree_possible > 1000);
  CHECK(agree_disjoint > 1000);
}

TEST_CASE("velocity_frame is orthonormal with v first", "[bounds][oriented_trapezoid]") {
  SECTION("zero velocity: identity") { CHECK(ccd::velocity_frame(Vec3::Zero()) == Eigen::Matrix3d::Identity()); }
  SECTION("axis-aligned velocity: identity up to signs") {
    const Eigen::Matrix3d f = ccd::velocity_frame(Vec3(-3, 0, 0));
    CHECK(f.cwiseAbs() == Eigen::Matrix3d::Identity());
  }
  SECTION("random velocities") {
    std::mt19937_64 rng(1);
    std::normal_distribution<double> g;
    for (int i = 0; i < 1000; ++i) {
      const Vec3 v(g(rng), g(rng), g(rng) * (i % 2 ? 1e-9 : 1.0));
      const Eigen::Matrix3d f = ccd::velocity_frame(v);
      CHECK((f.transpose() * f - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= 8 * std::numeric_limits<double>::epsilon());
      CHECK((f.col(0) - v.normalized()).norm() <= 8 * std::numeric_limits<double>::epsilon());
    }
  }
}

}  // namespace bounds_oriented_trapezoid_test
