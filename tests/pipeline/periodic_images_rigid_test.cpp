// The image layer of the step pipeline with rigid bodies (pipeline/periodic_images.hpp):
// every local body (a body's unwrapped path or an image) keeps its owner's shape and spin,
// and every bound x every broad phase on a wrapped scene of spinning sticks, crates and
// plates reports the same pairs as brute force and finds every pair that the certified
// periodic truth puts in contact (overlap certified) during the step.
#include "../ccd/scene/periodic_rigid_scenes.hpp"

#include <bounds/registry.hpp>
#include <ccd/broad_phase/registry.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/motion/state_cursor.hpp>
#include <pipeline/periodic_images.hpp>
#include <pipeline/step_pipeline.hpp>
#include <ccd/truth/rigid_truth.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <set>

namespace pipeline_periodic_images_rigid_test {

namespace {

struct World {
  ccd::Scene scene;
  ccd::Trajectories traj;
  std::unique_ptr<ccd::RigidMotion> motion;
  ccd::RigidTruthResult truth;
};

// One random wrapped rigid scene and its certified truth, shared by every bound x broad phase.
const World& world() {
  static const std::unique_ptr<World> w = [] {
    auto x = std::make_unique<World>();
    x->scene = ccd::test::random_rigid_periodic_scene(3, 40);
    x->traj = ccd::Trajectories(x->scene);
    x->motion = std::make_unique<ccd::RigidMotion>(x->scene, x->traj);
    x->truth = ccd::compute_rigid_truth(*x->motion);
    return x;
  }();
  return *w;
}

ccd::StepContext context(const World& w, double t0, double t1, const std::vector<ccd::BodyState>& start, bool exact) {
  ccd::StepContext ctx;
  ctx.t0 = t0;
  ctx.t1 = t1;
  ctx.start = start;
  ctx.exact = exact ? &w.traj : nullptr;
  ctx.acceleration_bound = w.scene.max_acceleration();
  ctx.walls = w.scene.box;
  ctx.motion = w.motion.get();
  return ctx;
}

std::set<ccd::BodyPair> as_set(const std::vector<ccd::BodyPair>& v) { return {v.begin(), v.end()}; }

}  // namespace

TEST_CASE("periodic images keep their bodies' shapes and spins", "[pipeline][periodic][rigid]") {
  const World& w = world();
  const ccd::PeriodicBox& box = *w.traj.periodic();
  const double t0 = 0.75, t1 = 0.875;
  std::vector<ccd::BodyState> start;
  ccd::StateCursor(w.traj).evaluate(t0, start);
  const ccd::StepContext ctx = context(w, t0, t1, start, true);
  ccd::PeriodicImages im;
  const ccd::StepContext& local = im.begin(ctx);
  std::vector<ccd::Aabb> boxes;
  const auto bound = ccd::parse_bound("swept_aabb").make();
  bound->prepare(local, boxes);
  REQUIRE(im.add_images(boxes));
  const ccd::RigidMotion* r = &im.motion();
  REQUIRE(im.context().motion == r);
  REQUIRE(im.context().exact == &r->centres());
  REQUIRE(r->size() == im.motion().centres().size());
  REQUIRE(r->size() > w.scene.bodies.size());
  for (std::uint32_t j = 0; j < r->size(); ++j) {
    const std::uint32_t o = im.owner(j);
    CAPTURE(j, o);
    CHECK(r->kind(j) == w.motion->kind(o));
    CHECK(r->proxy(j).points.size() == w.motion->proxy(o).points.size());
    CHECK(r->proxy(j).radius == w.motion->proxy(o).radius);
    CHECK(r->enclosing_radius(j) == w.motion->enclosing_radius(o));
    for (const double t : {t0, 0.5 * (t0 + t1), t1}) {
      const ccd::Pose p = r->pose(j, t), q = w.motion->pose(o, t);
      CHECK(p.rotation == q.rotation);  // the same spin pieces, evaluated alike
      CHECK(r->pose_error(j, t) == w.motion->pose_error(o, t));
      // The centre is the owner's, moved by whole periods on each wrapped axis.
      for (int k = 0; k < 3; ++k) {
        const double periods = (p.centre[k] - q.centre[k]) / box.period[k];
        CHECK(std::fabs(periods - std::nearbyint(periods)) < 1e-12);
      }
    }
    CHECK(r->max_point_speed(j, t0, t1) >= w.motion->max_point_speed(o, t0, t1) * (1 - 1e-15));
  }
}

TEST_CASE("every bound x every broad phase on a wrapped rigid scene: brute-force pairs, no certified contact lost",
          "[pipeline][periodic][rigid]") {
  const World& w = world();
  const auto n = static_cast<std::uint32_t>(w.traj.size());
  const auto& bound_info = GENERATE(from_range(ccd::bound_registry().begin(), ccd::bound_registry().end()));
  const auto& broad_info = GENERATE(from_range(ccd::broad_phase_registry().begin(), ccd::broad_phase_registry().end()));
  CAPTURE(bound_info.name, broad_info.name);
  const bool sample = bound_info.knowledge == ccd::Knowledge::Instant;
  std::size_t images = 0, certified = 0;
  for (const double t0 : {0.0, 0.75, 1.5}) {
    const double t1 = sample ? t0 : t0 + 0.125;
    CAPTURE(t0);
    std::vector<ccd::BodyState> start;
    ccd::StateCursor(w.traj).evaluate(t0, start);
    const ccd::StepContext ctx = context(w, t0, t1, start, bound_info.knowledge == ccd::Knowledge::Exact);
    ccd::StepPipeline pipeline(bound_info.make(), bound_info.knowledge, broad_info.make());
    ccd::StepPipeline reference(bound_info.make(), bound_info.knowledge, ccd::find_broad_phase("brute").make());
    ccd::StepResult step, ref;
    pipeline.run(ctx, step);
    reference.run(ctx, ref);
    images += pipeline.boxes().size() - n;
    CHECK(as_set(step.bodies.candidates).size() == step.bodies.candidates.size());
    CHECK(as_set(step.bodies.candidates) == as_set(ref.bodies.candidates));
    CHECK(as_set(step.bodies.passed) == as_set(ref.bodies.passed));
    std::set<ccd::BodyPair> found;
    for (const ccd::PairContact& c : step.bodies.contacts) found.insert(c.pair);
    // Pairs whose overlap the truth certifies at the sample time (discrete) or somewhere in
    // the step (continuous: its enter bracket starts no later than t1).
    for (std::size_t e = 0; e < w.truth.events.size(); ++e) {
      const ccd::ContactEvent& ev = w.truth.events[e];
      const ccd::EventError& err = w.truth.errors[e];
      if (err.grazing) continue;
      const bool in_step = sample ? ev.enter + err.enter_error < t0 && t0 < ev.exit - err.exit_error
                                  : ev.enter + err.enter_error <= t1 && ev.exit - err.exit_error >= t0;
      if (!in_step) continue;
      ++certified;
      if (sample || bound_info.conservative) CHECK(found.count({ev.a, ev.b}) == 1);
    }
  }
  CHECK(images > 0);
  CHECK(certified > 0);
}

}  // namespace pipeline_periodic_images_rigid_test
