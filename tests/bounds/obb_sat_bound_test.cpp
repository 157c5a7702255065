// `obb_sat:M` (bounds/obb_sat_bound.hpp) on adversarial dyadic rigid scenes: a stick
// spinning through a resting ball with zero translation, a crate doing the same, contact at
// t = 0 and at the horizon, contact when the spin stops (an angular-velocity change),
// contact across a wall reflection, all also 2^20 from the origin.
//  - containment: at 17 instants of every sub-interval, every point of every body lies in
//    that sub-interval's oriented box;
//  - zero misses against the certified rigid truth: each event's pair passes the test in
//    the step that holds its enter time, not later than enter; and through the runner
//    (step pipeline and the earliest scheduler) no event is missed, while sampling misses
//    the contacts made by rotation alone.
#include "../../experiments/method.hpp"
#include "../../experiments/runner.hpp"

#include <bounds/obb_sat_bound.hpp>
#include <ccd/truth/rigid_truth.hpp>
#include <tests/bounds/rigid_bound_support.hpp>

#include <catch2/catch.hpp>
#include <cmath>

namespace bounds_obb_sat_bound_test {

using ccd::Vec3;
using ccd::test::body_at;
using ccd::test::shaped;

namespace {

// Shapes: 0 crate (1/2, 1/4, 1/8), 1 stick (half length 1, radius 1/16), 2 plate, 3 rock,
// 4 a long crate (1, 1/8, 1/8).
ccd::Scene free_cases(const Vec3& o) {
  ccd::Scene s;
  s.horizon = 1.0;
  ccd::test::add_test_shapes(s);
  s.shapes.push_back(ccd::make_box_shape(Vec3(1, 0.125, 0.125), "long_crate"));
  const Vec3 z(0, 0, 1);
  // A stick spinning about z, no translation, a ball resting in its sweep: in contact
  // while |cos(theta)| <= 1/4 (the ball's centre 3/4 from the axis, radii 1/16 + 1/8... as
  // in tests/ccd/scene/rigid_scenes.hpp).
  s.add_rigid_body(body_at(o), shaped(1, ccd::Quat::Identity(), 32 * z));
  s.add_rigid_body(body_at(o + Vec3(0, 0.75, 0), Vec3::Zero(), 0.125), ccd::RigidBody{});
  // A long crate doing the same, slower.
  s.add_rigid_body(body_at(o + Vec3(16, 0, 0)), shaped(4, ccd::Quat::Identity(), 12 * z));
  s.add_rigid_body(body_at(o + Vec3(16, 0.75, 0), Vec3::Zero(), 0.125), ccd::RigidBody{});
  // Overlapping at t = 0 (the ball 1/32 into the stick's tip), spinning away.
  s.add_rigid_body(body_at(o + Vec3(32, 0, 0)), shaped(1, ccd::Quat::Identity(), 4 * z));
  s.add_rigid_body(body_at(o + Vec3(32 + 1 + 0.0625 + 0.125 - 0.03125, 0, 0), Vec3::Zero(), 0.125), ccd::RigidBody{});
  // Touching at the horizon: a stick spinning about its own axis, moving along it at 1 m/s,
  // its tip reaching the ball at t = 1.
  s.add_rigid_body(body_at(o + Vec3(48, 0, 0), Vec3(1, 0, 0)), shaped(1, ccd::Quat::Identity(), Vec3(16, 0, 0)));
  s.add_rigid_body(body_at(o + Vec3(48 + 2 + 0.0625 + 0.125, 0, 0), Vec3::Zero(), 0.125), ccd::RigidBody{});
  // The spin stops exactly when the contact starts (an angular-velocity change at enter).
  ccd::RigidBody stops = shaped(1, ccd::Quat::Identity(), 8 * z);
  stops.angular_velocity_changes.push_back({std::acos(0.25) / 8, Vec3::Zero()});
  s.add_rigid_body(body_at(o + Vec3(64, 0, 0)), stops);
  s.add_rigid_body(body_at(o + Vec3(64, 0.75, 0), Vec3::Zero(), 0.125), ccd::RigidBody{});
  // A plate at rest that starts to spin at t = 1/2, turned a third about the diagonal,
  // reaching a rock that tumbles above it.
  ccd::RigidBody plate = shaped(2, ccd::Quat(0.5, 0.5, 0.5, 0.5));
  plate.angular_velocity_changes.push_back({0.5, Vec3(24, 0, 0)});
  s.add_rigid_body(body_at(o + Vec3(80, 0, 0)), plate);
  s.add_rigid_body(body_at(o + Vec3(80, 0, 0.8125)), shaped(3, ccd::Quat::Identity(), Vec3(0, 4, 0)));
  return s;
}

ccd::Scene wall_cases(const Vec3& o) {
  ccd::Scene s;
  s.horizon = 1.0;
  s.box = ccd::WallBox{o, o + Vec3(8, 8, 8)};
  ccd::test::add_test_shapes(s);
  // A stick spinning about its own axis driven into the wall x = 8 (its enclosing sphere,
  // radius 17/16, reflects at t = 47/32), a ball resting against that wall just above the
  // stick's axis: the contact spans the reflection. The horizon is 2 for this scene.
  s.horizon = 2.0;
  s.add_rigid_body(body_at(o + Vec3(4, 4, 4), Vec3(2, 0, 0)), shaped(1, ccd::Quat::Identity(), Vec3(16, 0, 0)));
  s.add_rigid_body(body_at(o + Vec3(7.875, 4.125, 4), Vec3::Zero(), 0.125), ccd::RigidBody{});
  // A stick spinning about y driven into the wall x = 0, a ball waiting near that wall.
  s.add_rigid_body(body_at(o + Vec3(2, 2, 2), Vec3(-4, 0, 0)), shaped(1, ccd::Quat::Identity(), Vec3(0, 16, 0)));
  s.add_rigid_body(body_at(o + Vec3(0.5, 2, 2.5), Vec3::Zero(), 0.25), ccd::RigidBody{});
  // A crate spinning about z bouncing on the floor y = 0, a ball resting on the floor.
  s.add_rigid_body(body_at(o + Vec3(6, 2, 6), Vec3(0, -4, 0)), shaped(0, ccd::Quat::Identity(), Vec3(0, 0, 8)));
  s.add_rigid_body(body_at(o + Vec3(6.5, 0.25, 6), Vec3::Zero(), 0.25), ccd::RigidBody{});
  return s;
}

struct Case {
  const char* name;
  ccd::Scene scene;
};

std::vector<Case> cases() {
  const Vec3 far(1048576, -1048576, 1048576);
  return {{"free", free_cases(Vec3::Zero())},
          {"free, far from the origin", free_cases(far)},
          {"walls", wall_cases(Vec3::Zero())},
          {"walls, far from the origin", wall_cases(far)}};
}

}  // namespace

TEST_CASE("obb_sat's boxes hold every body over each sub-interval", "[bounds][obb_sat]") {
  for (Case& c : cases()) {
    INFO(c.name);
    ccd::test::RigidStep st(c.scene);
    for (const int m : {1, 4, 7}) {
      ccd::ObbSatBound bound(m);
      std::vector<ccd::Aabb> boxes;
      long checked = 0, outside = 0;
      for (const double h : {1.0 / 16, 0.25, 1.0}) {
        for (double t0 = 0.0; t0 < st.scene.horizon; t0 += h) {
          bound.prepare(st.context(ccd::Knowledge::Exact, t0, std::min(t0 + h, st.scene.horizon)), boxes);
          for (std::uint32_t i = 0; i < st.traj.size(); ++i) {
            const ccd::ConvexProxy p = st.rigid.proxy(i);
            for (int j = 0; j < m; ++j) {
              const ccd::OrientedBox& o = bound.box(i, j);
              const double s0 = bound.window(i).t0 + (bound.window(i).t1 - bound.window(i).t0) * j / m;
              const double s1 = j + 1 == m ? bound.window(i).t1 : bound.window(i).t0 + (bound.window(i).t1 - bound.window(i).t0) * (j + 1) / m;
              for (int k = 0; k <= 16; ++k) {
                const double t = k == 16 ? s1 : s0 + (s1 - s0) * k / 16;
                const ccd::Pose pose = st.rigid.pose(i, t);
                for (const Vec3& q : p.points) {
                  const Vec3 local = o.axes.transpose() * (pose.apply(q) - o.centre);
                  ++checked;
                  const double tol = 1e-12 * (1.0 + o.centre.cwiseAbs().maxCoeff());
                  if (((local.cwiseAbs().array() + p.radius) > o.half.array() + tol).any() && ++outside <= 3)
                    FAIL_CHECK("M = " << m << " body " << i << " leaves box " << j << " at t = " << t);
                  if (!boxes[i].overlaps({pose.apply(q), pose.apply(q)})) ++outside;
                }
              }
            }
          }
        }
      }
      CHECK(outside == 0);
      CHECK(checked > 1000);
    }
  }
}

TEST_CASE("obb_sat misses no contact of the certified rigid truth", "[bounds][obb_sat][zero_miss][rigid]") {
  for (Case& c : cases()) {
    INFO(c.name);
    ccd::test::RigidStep st(c.scene);
    const ccd::RigidTruthResult rt = ccd::compute_rigid_truth(st.rigid);
    REQUIRE(rt.events.size() >= 3);
    const double err = ccd::largest_error(rt.errors);
    // Bound level: the pair passes in the step that holds its enter time, no later.
    for (const int m : {1, 4, 7}) {
      ccd::ObbSatBound bound(m);
      std::vector<ccd::Aabb> boxes;
      for (const double h : {1.0 / 16, 0.25}) {
        for (const ccd::ContactEvent& e : rt.events) {
          const double t0 = std::min(std::floor(e.enter / h) * h, st.scene.horizon - h);
          bound.prepare(st.context(ccd::Knowledge::Exact, t0, t0 + h), boxes);
          const ccd::PairTest r = bound.test(e.a, e.b);
          INFO("M = " << m << ", h = " << h << ", pair " << e.a << ", " << e.b << ", enter " << e.enter);
          CHECK(boxes[e.a].overlaps(boxes[e.b]));
          CHECK(r.possible());
          CHECK(r.earliest <= e.enter + err);
        }
      }
    }
    // Through the runner, against the truth with its certified errors.
    const ccdlab::TruthIndex truth(rt.events);
    ccdlab::RunInput in;
    in.scene = &st.scene;
    in.motion = &st.rigid;
    in.truth = &truth;
    in.truth_error = err;
    in.acceleration_bound = st.scene.max_acceleration();
    for (const double dt : {1.0 / 16, 0.25}) {
      for (const char* method : {"obb_sat:1/brute", "obb_sat/sap", "obb_sat:7/grid", "obb_sat/brute@earliest",
                                 "obb_sat:2/sap@earliest"}) {
        INFO(method << " dt " << dt);
        const ccdlab::RunRecord r = ccdlab::run_method(in, ccdlab::parse_method(method), dt);
        CHECK(r.conservative);
        CHECK(r.bodies.missed == 0);
        CHECK(r.bodies.detected + r.bodies.initial_contacts == r.bodies.events);
        CHECK(r.self_check_unexpected == 0);
      }
      // Sampling at dt = 1/4 tunnels through the spinning contacts (rotation alone).
      if (dt == 0.25 && std::string(c.name).rfind("free", 0) == 0) {
        for (const char* method : {"sphere/brute", "frame_aabb/brute", "obb/brute"}) {
          INFO(method);
          CHECK(ccdlab::run_method(in, ccdlab::parse_method(method), dt).bodies.missed > 0);
        }
      }
    }
  }
}

}  // namespace bounds_obb_sat_bound_test
