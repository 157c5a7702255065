// Bound::volumes for every bound of the registry: the volumes hold the body over their time
// spans (sampled, on random gases and on spinning shapes), their hulls give the box the
// bound wrote (or, for the bounds whose box is cut down further, contain it), and a pair
// the bound's test lets through has volumes that meet.
#include <bounds/registry.hpp>
#include <bounds/volume.hpp>
#include <tests/bounds/bound_test_support.hpp>
#include <tests/bounds/rigid_bound_support.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace bounds_volumes_test {

using ccd::Vec3;
using ccd::Volume;

namespace {

// How a bound's box relates to the hull of its volumes: equal (the box is built as that
// hull, up to the rounding slack) or larger than the box (capsule: its box is also cut by
// the swept box; horn_sat: each oriented trapezoid is drawn as the box on its axes that
// holds both its ends, whose world hull is larger than the trapezoid's).
bool box_is_volumes_hull(const std::string& spec) {
  return spec.rfind("capsule", 0) != 0 && spec.rfind("horn_sat", 0) != 0;
}

double magnitude(const ccd::Aabb& box) { return box.lo.cwiseAbs().cwiseMax(box.hi.cwiseAbs()).maxCoeff(); }

ccd::Aabb hull_of(const std::vector<Volume>& vs) {
  ccd::Aabb h = vs.front().hull();
  for (const Volume& v : vs) h.merge(v.hull());
  return h;
}

// The box the bound wrote against the hull of its volumes (see box_is_volumes_hull); the
// tolerance is 1e-12 of the coordinates (the rounding slack is 1.4e-14 of them).
void check_hull(const std::string& spec, std::size_t body, const ccd::Aabb& box, const std::vector<Volume>& vs,
                long& failed) {
  const ccd::Aabb h = hull_of(vs);
  const double tol = 1e-12 * (1.0 + std::max(magnitude(box), magnitude(h)));
  const bool inside = (h.lo.array() - tol <= box.lo.array()).all() && (box.hi.array() <= h.hi.array() + tol).all();
  const bool equal = inside && (box.lo.array() - tol <= h.lo.array()).all() && (h.hi.array() <= box.hi.array() + tol).all();
  if (!(box_is_volumes_hull(spec) ? equal : inside) && ++failed <= 3)
    FAIL_CHECK(spec << ": body " << body << ": box [" << box.lo.transpose() << "] - [" << box.hi.transpose()
                    << "] against the volumes' hull [" << h.lo.transpose() << "] - [" << h.hi.transpose() << "]");
}

// Whether the ball (x, r) at time t lies in one of the volumes whose span holds t.
bool held(const std::vector<Volume>& vs, double t, const Vec3& x, double r) {
  const double tol = 1e-9 * (1.0 + x.cwiseAbs().maxCoeff() + r);
  return std::any_of(vs.begin(), vs.end(), [&](const Volume& v) { return v.t0 <= t && t <= v.t1 && v.contains(x, r, tol); });
}

// A pair the test lets through has two volumes whose spans and hulls meet.
bool volumes_meet(const std::vector<Volume>& va, const std::vector<Volume>& vb) {
  for (const Volume& x : va)
    for (const Volume& y : vb)
      if (x.t0 <= y.t1 && y.t0 <= x.t1 && x.hull().overlaps(y.hull())) return true;
  return false;
}

std::vector<double> samples(const ccd::Window& w, int n) {
  std::vector<double> ts;
  if (w.t1 == w.t0) return {w.t0};
  for (int k = 0; k < n; ++k) ts.push_back(k + 1 == n ? w.t1 : w.t0 + (w.t1 - w.t0) * k / (n - 1));
  return ts;
}

}  // namespace

TEST_CASE("every bound's volumes hold the body and give its box", "[bounds][volumes]") {
  const std::string spec = GENERATE(from_range(ccd::test::bound_specs()));
  const ccd::BoundSpec bs = ccd::parse_bound(spec);
  std::mt19937_64 rng(0x5EED ^ std::hash<std::string>{}(spec));
  auto bound = bs.make();
  std::vector<ccd::Aabb> boxes;
  std::vector<Volume> vs, wa, wb;
  long checked = 0, failed = 0, pairs = 0;
  for (int rep = 0; rep < 8; ++rep) {
    for (const double h : {1.0 / 30, 0.5}) {
      const double t0 = (rep % 2) * h;
      const ccd::test::Step st =
          ccd::test::random_gas(rng, 200, t0, t0 + h, rep % 3 == 0 ? 0.0 : 50.0, rep % 4 != 3, rep % 2 == 0, 3);
      const ccd::StepContext ctx = st.context(bs.info->knowledge);
      bound->prepare(ctx, boxes);
      for (std::uint32_t i = 0; i < boxes.size(); ++i) {
        vs.clear();
        bound->volumes(i, vs);
        REQUIRE(!vs.empty());
        const ccd::Window w = bound->window(i);
        CHECK(vs.front().t0 == w.t0);
        CHECK(vs.back().t1 == w.t1);
        check_hull(spec, i, boxes[i], vs, failed);
        for (const double t : samples(w, 33)) {
          ++checked;
          if (!held(vs, t, st.traj.position(i, t), st.traj.radius(i)) && ++failed <= 3)
            FAIL_CHECK(spec << ": body " << i << " leaves its volumes at t = " << t << " (h = " << h << ")");
        }
      }
      for (std::uint32_t a = 0; a + 1 < boxes.size(); ++a)
        for (std::uint32_t b = a + 1; b < boxes.size(); ++b) {
          if (!boxes[a].overlaps(boxes[b]) || !bound->test(a, b).possible()) continue;
          ++pairs;
          wa.clear();
          wb.clear();
          bound->volumes(a, wa);
          bound->volumes(b, wb);
          if (!volumes_meet(wa, wb) && ++failed <= 3) FAIL_CHECK(spec << ": pair " << a << "-" << b << " passes the test, its volumes are apart");
        }
    }
  }
  CHECK(failed == 0);
  CHECK(checked > 1000);
  CHECK(pairs > 10);
}

TEST_CASE("every bound's volumes hold spinning shapes", "[bounds][volumes][rigid]") {
  const std::string spec = GENERATE(from_range(ccd::test::bound_specs()));
  const ccd::BoundSpec bs = ccd::parse_bound(spec);
  std::mt19937_64 rng(0x51DE ^ std::hash<std::string>{}(spec));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  ccd::Scene s;
  s.horizon = 1.0;
  ccd::test::add_test_shapes(s);
  for (int k = 0; k < 60; ++k) {
    const int shape = k % 5 - 1;  // balls and the four shapes
    const Vec3 c(4.0 * u(rng), 4.0 * u(rng), 4.0 * u(rng));
    const Vec3 v(3.0 * u(rng), 3.0 * u(rng), 3.0 * u(rng));
    ccd::Quat q(u(rng), u(rng), u(rng), u(rng));
    q.normalize();
    if (shape < 0) s.add_rigid_body(ccd::test::body_at(c, v, 0.25), ccd::RigidBody{});
    else s.add_rigid_body(ccd::test::body_at(c, v), ccd::test::shaped(shape, q, Vec3(6.0 * u(rng), 6.0 * u(rng), 6.0 * u(rng))));
  }
  ccd::test::RigidStep st(std::move(s));
  auto bound = bs.make();
  std::vector<ccd::Aabb> boxes;
  std::vector<Volume> vs;
  long checked = 0, failed = 0;
  for (const double t0 : {0.0, 0.25, 0.75}) {
    bound->prepare(st.context(bs.info->knowledge, t0, t0 + 0.25), boxes);
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
      vs.clear();
      bound->volumes(i, vs);
      REQUIRE(!vs.empty());
      check_hull(spec, i, boxes[i], vs, failed);
      const ccd::ConvexProxy proxy = st.rigid.proxy(i);
      for (const double t : samples(bound->window(i), 17)) {
        const ccd::Pose pose = st.rigid.pose(i, t);
        for (const Vec3& p : proxy.points) {
          ++checked;
          if (!held(vs, t, pose.apply(p), proxy.radius) && ++failed <= 3)
            FAIL_CHECK(spec << ": a point of body " << i << " leaves its volumes at t = " << t);
        }
      }
    }
  }
  CHECK(failed == 0);
  CHECK(checked > 800);  // an instant bound: one sample of 60 bodies' points per step
}

TEST_CASE("a volume's hull and containment", "[bounds][volumes]") {
  const Volume box = Volume::box({Vec3(0, 0, 0), Vec3(1, 2, 4)}, 0.0, 1.0);
  CHECK(box.contains(Vec3(0.5, 1, 2), 0.5, 0.0));
  CHECK_FALSE(box.contains(Vec3(0.5, 1, 2), 0.5 + 1.0 / 1024, 0.0));
  const Volume capsule = Volume::capsule(Vec3(0, 0, 0), Vec3(4, 0, 0), 0.5, 0.0, 1.0);
  CHECK(capsule.contains(Vec3(2, 0.25, 0), 0.25, 0.0));
  CHECK_FALSE(capsule.contains(Vec3(4.25, 0.25, 0), 0.25, 0.0));
  CHECK(capsule.hull().lo == Vec3(-0.5, -0.5, -0.5));
  CHECK(capsule.hull().hi == Vec3(4.5, 0.5, 0.5));
  // Axes that permute the world axes (a third of a turn about the diagonal).
  Eigen::Matrix3d axes;
  axes << 0, 1, 0, 0, 0, 1, 1, 0, 0;
  const Volume obox = Volume::oriented_box(Vec3(1, 1, 1), axes, Vec3(0.5, 0.25, 0.125), 0.0, 0.0);
  CHECK(obox.hull().lo == Vec3(0.75, 0.875, 0.5));
  CHECK(obox.hull().hi == Vec3(1.25, 1.125, 1.5));
  CHECK(obox.contains(Vec3(1, 1, 1.375), 0.125, 0.0));
  CHECK_FALSE(obox.contains(Vec3(1.25, 1, 1), 0.125, 0.0));
  const Volume ball = Volume::sphere(Vec3(1, 1, 1), 1.0, 0.0, 0.0);
  CHECK(ball.contains(Vec3(1.5, 1, 1), 0.5, 0.0));
  CHECK_FALSE(ball.contains(Vec3(1.5, 1, 1), 0.5 + 1.0 / 1024, 0.0));
}

}  // namespace bounds_volumes_test
