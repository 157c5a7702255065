// The step pipeline on a scene that wraps around (the image layer,
// pipeline/periodic_images.hpp): every bound x every broad phase on a dense gas whose
// bodies cross the seam. Every broad phase reports the same body pairs as brute force over
// the same images, and the contacts are exactly the pairs in contact among ALL pairs by
// the periodic truth (nearest image), with the truth's first contact time.
#include <bounds/registry.hpp>
#include <ccd/broad_phase/registry.hpp>
#include <ccd/motion/state_cursor.hpp>
#include <pipeline/step_pipeline.hpp>
#include <ccd/truth/contact_function.hpp>
#include <ccd/truth/pair_contact.hpp>
#include <generators/registry.hpp>

#include <catch2/catch.hpp>
#include <set>
#include <vector>

namespace pipeline_periodic_images_test {

namespace {

std::set<ccd::BodyPair> as_set(const std::vector<ccd::BodyPair>& v) { return {v.begin(), v.end()}; }

}  // namespace

TEST_CASE("the step pipeline on a wrapped scene equals brute force and the periodic truth", "[pipeline][periodic]") {
#ifdef CCDLAB_SANITIZED
  const int bodies = 80;  // all pairs per step and per method: smaller under the sanitizers
#else
  const int bodies = 150;
#endif
  const ccd::Scene scene = ccdlab::generate_scene(
      "gas", nlohmann::json{{"bodies", bodies}, {"seed", 8}, {"fraction", 0.1}, {"speed_max", 20.0}, {"wrap", 1}});
  const ccd::Trajectories motion(scene);
  REQUIRE(motion.periodic() != nullptr);
  const auto n = static_cast<std::uint32_t>(motion.size());
  const auto& bound_info = GENERATE(from_range(ccd::bound_registry().begin(), ccd::bound_registry().end()));
  const auto& broad_info = GENERATE(from_range(ccd::broad_phase_registry().begin(), ccd::broad_phase_registry().end()));
  CAPTURE(bound_info.name, broad_info.name);
  const bool sample = bound_info.knowledge == ccd::Knowledge::Instant;
  long touching_total = 0, across_seam = 0;
  std::size_t images = 0;  // (at t = 0 the gas starts inside the cell: instant boxes have none)
  for (const double t0 : {0.0, 0.5, 0.875}) {
    const double t1 = sample ? t0 : t0 + 0.125;
    CAPTURE(t0);
    std::vector<ccd::BodyState> start;
    ccd::StateCursor(motion).evaluate(t0, start);
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
    ccd::StepPipeline reference(bound_info.make(), bound_info.knowledge, ccd::find_broad_phase("brute").make());
    ccd::StepResult step, ref;
    pipeline.run(ctx, step);
    reference.run(ctx, ref);
    images += pipeline.boxes().size() - n;
    // Each body pair once, the same pairs as brute force.
    CHECK(as_set(step.bodies.candidates).size() == step.bodies.candidates.size());
    CHECK(as_set(step.bodies.candidates) == as_set(ref.bodies.candidates));
    CHECK(as_set(step.bodies.passed) == as_set(ref.bodies.passed));

    std::set<ccd::BodyPair> touching;
    for (std::uint32_t a = 0; a < n; ++a)
      for (std::uint32_t b = a + 1; b < n; ++b)
        if (sample ? ccd::in_contact(motion, a, b, t0) : ccd::pair_first_contact(motion, a, b, t0, t1).has_value())
          touching.insert({a, b});
    std::set<ccd::BodyPair> found;
    for (const ccd::PairContact& c : step.bodies.contacts) {
      found.insert(c.pair);
      if (!sample) {
        const auto toi = ccd::pair_first_contact(motion, c.pair.a, c.pair.b, t0, t1);
        REQUIRE(toi);
        CHECK(c.contact.toi == Approx(*toi).epsilon(0).margin(1e-12));
      }
      CHECK(c.contact.signed_distance <= 1e-9);
      const ccd::Vec3 d = motion.position(c.pair.b, c.contact.toi) - motion.position(c.pair.a, c.contact.toi);
      if (d.cwiseAbs().maxCoeff() > 0.5 * (scene.box->max - scene.box->min).minCoeff()) ++across_seam;
    }
    CHECK(found == touching);
    touching_total += static_cast<long>(touching.size());
  }
  CHECK(images > 0);
  CHECK(touching_total >= 10);
  CHECK(across_seam >= 1);  // the scene tests the seam
}

}  // namespace pipeline_periodic_images_test
