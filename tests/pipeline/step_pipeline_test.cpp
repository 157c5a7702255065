// The step pipeline against brute-force references on a generated gas with walls:
// every bound x every broad phase. Stage by stage:
//  - candidates are the pairs of overlapping boxes (brute force over the pipeline's boxes);
//  - passed are the candidates whose bound test is Possible, in candidate order;
//  - contacts are the passed pairs the narrow phase finds, and, since every bound here is
//    conservative (instant bounds at the sample, the others over the step), they are
//    exactly the pairs of ALL pairs in contact: at t0 for a sample test, within [t0, t1]
//    for a step.
#include <bounds/registry.hpp>
#include <ccd/broad_phase/registry.hpp>
#include <ccd/motion/state_cursor.hpp>
#include <pipeline/step_pipeline.hpp>
#include <ccd/truth/contact_function.hpp>
#include <ccd/truth/pair_contact.hpp>
#include <generators/registry.hpp>

#include <catch2/catch.hpp>
#include <algorithm>
#include <set>
#include <vector>

namespace pipeline_step_pipeline_test {

namespace {

std::set<ccd::BodyPair> as_set(const std::vector<ccd::BodyPair>& v) { return {v.begin(), v.end()}; }

}  // namespace

TEST_CASE("the step pipeline equals the brute-force reference at every stage", "[pipeline]") {
  const ccd::Scene scene = ccdlab::generate_scene("gas", nlohmann::json{{"bodies", 300}, {"seed", 5}, {"fraction", 0.1}, {"speed_max", 20.0}});
  const ccd::Trajectories motion(scene);
  const auto n = static_cast<std::uint32_t>(motion.size());
  const double t0 = 0.5, h = 0.1;
  std::vector<ccd::BodyState> start;
  ccd::StateCursor cursor(motion);
  cursor.evaluate(t0, start);

  const auto& bound_info = GENERATE(from_range(ccd::bound_registry().begin(), ccd::bound_registry().end()));
  const auto& broad_info = GENERATE(from_range(ccd::broad_phase_registry().begin(), ccd::broad_phase_registry().end()));
  CAPTURE(bound_info.name, broad_info.name);
  const bool sample = bound_info.knowledge == ccd::Knowledge::Instant;
  const double t1 = sample ? t0 : t0 + h;

  ccd::StepContext ctx;
  ctx.t0 = t0;
  ctx.t1 = t1;
  ctx.start = start;
  ctx.exact = bound_info.knowledge == ccd::Knowledge::Exact ? &motion : nullptr;
  ctx.acceleration_bound = scene.max_acceleration();
  ctx.walls = scene.box;
  const ccd::RigidMotion scene_motion(scene, motion);
  ctx.motion = &scene_motion;
  ccd::StepPipeline pipeline(bound_info.make(), bound_info.knowledge, broad_info.make());
  CHECK(pipeline.sample_test() == sample);
  ccd::StepResult step;
  ccd::StepTimes times;
  pipeline.run(ctx, step, &times, cursor.pieces());

  // Broad phase: every pair of overlapping boxes, once.
  const std::vector<ccd::Aabb>& boxes = pipeline.boxes();
  REQUIRE(boxes.size() == n);
  std::set<ccd::BodyPair> overlapping;
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      if (boxes[a].overlaps(boxes[b])) overlapping.insert({a, b});
  CHECK(step.bodies.candidates.size() == overlapping.size());
  CHECK(as_set(step.bodies.candidates) == overlapping);

  // Bound test: the Possible candidates, in candidate order.
  std::vector<ccd::BodyPair> possible;
  for (const ccd::BodyPair& p : step.bodies.candidates)
    if (pipeline.bound().test(p.a, p.b).possible()) possible.push_back(p);
  CHECK(step.bodies.passed == possible);

  // Narrow phase: exactly the pairs in contact, among all pairs.
  std::set<ccd::BodyPair> touching;
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      if (sample ? ccd::in_contact(motion, a, b, t0) : ccd::pair_first_contact(motion, a, b, t0, t1).has_value())
        touching.insert({a, b});
  std::set<ccd::BodyPair> found;
  for (const ccd::PairContact& c : step.bodies.contacts) {
    found.insert(c.pair);
    CHECK(c.contact.found());
    CHECK(c.contact.toi >= t0);
    CHECK(c.contact.toi <= t1);
    CHECK(c.contact.toi_error == 0.0);
    CHECK(c.contact.signed_distance <= 1e-9);  // touching or deeper at the reported time
  }
  CHECK(found == touching);
  CHECK(touching.size() >= 5);  // the scene is dense enough to have contacts in the step
  CHECK(times.bound >= 0.0);
  CHECK(times.broad >= 0.0);
  CHECK(times.narrow >= 0.0);
}

TEST_CASE("the narrow phase started at earliest finds the same contacts", "[pipeline][earliest]") {
  // Every conservative space-time bound, assumptions holding (A = the scene's largest
  // acceleration): no contact before a pair test's earliest, so starting the narrow phase
  // there changes nothing but the work (same pairs, same first contact times).
  const ccd::Scene scene = ccdlab::generate_scene(
      "gas", nlohmann::json{{"bodies", 300}, {"seed", 6}, {"fraction", 0.1}, {"speed_max", 20.0}});
  const ccd::Trajectories motion(scene);
  std::vector<ccd::BodyState> start;
  long contacts = 0, later_starts = 0;
  for (const ccd::BoundInfo& info : ccd::bound_registry()) {
    if (info.knowledge == ccd::Knowledge::Instant) continue;
    for (const double t0 : {0.0, 0.5, 0.875}) {
      const double t1 = t0 + 0.125;
      ccd::StateCursor(motion).evaluate(t0, start);  // a fresh cursor: times go back per bound
      CAPTURE(info.name, t0);
      ccd::StepContext ctx;
      ctx.t0 = t0;
      ctx.t1 = t1;
      ctx.start = start;
      ctx.exact = info.knowledge == ccd::Knowledge::Exact ? &motion : nullptr;
      ctx.acceleration_bound = scene.max_acceleration();
      ctx.walls = scene.box;
      const ccd::RigidMotion scene_motion(scene, motion);
      ctx.motion = &scene_motion;
      ccd::StepPipeline from_start(info.make(), info.knowledge, ccd::find_broad_phase("grid").make());
      ccd::StepPipeline from_earliest(info.make(), info.knowledge, ccd::find_broad_phase("grid").make(),
                                      ccd::narrow_table(), ccd::PipelineOptions{true});
      ccd::StepResult a, b;
      from_start.run(ctx, a);
      from_earliest.run(ctx, b);
      CHECK(a.bodies.passed == b.bodies.passed);
      REQUIRE(a.bodies.contacts.size() == b.bodies.contacts.size());
      for (std::size_t i = 0; i < a.bodies.contacts.size(); ++i) {
        CHECK(a.bodies.contacts[i].pair == b.bodies.contacts[i].pair);
        CHECK(b.bodies.contacts[i].contact.toi == Approx(a.bodies.contacts[i].contact.toi).epsilon(0).margin(1e-12));
      }
      for (const double e : b.bodies.earliest) later_starts += e > t0;
      contacts += static_cast<long>(a.bodies.contacts.size());
    }
  }
  CHECK(contacts > 20);
  CHECK(later_starts > 100);  // the option did move narrow-phase starts
}

}  // namespace pipeline_step_pipeline_test
