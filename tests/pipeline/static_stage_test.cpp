// The step pipeline's static stages (scenery): the static index's pairs equal brute force
// over the pipeline's boxes, the bound's static test only filters them, and the kinematic
// principle (PipelineOptions::kinematic) leaves every body's first static contact in
// every step unchanged (same time, for every conservative continuous bound) while it
// skips tests. Scene: balls falling fast through a stack of thin horizontal plates and
// random tilted polygons (a pinball of plates: several plates per body and step). The
// body-polygon narrow phase is the narrow table's polygon column.
#include <bounds/registry.hpp>
#include <ccd/broad_phase/registry.hpp>
#include <ccd/motion/state_cursor.hpp>
#include <ccd/narrow/sphere_polygon_narrow.hpp>
#include <ccd/narrow/sphere_sphere_narrow.hpp>
#include <pipeline/step_pipeline.hpp>
#include <tests/bounds/bound_test_support.hpp>
#include <tests/ccd/scene/scenery_support.hpp>

#include <catch2/catch.hpp>
#include <map>
#include <string>
#include <random>
#include <stdexcept>

namespace pipeline_static_stage_test {

using namespace ccd;


TEST_CASE("static stages: index pairs equal brute force, kinematic keeps first contacts", "[pipeline][scenery]") {
  const Scene scene = test::plates_scene(1406, 40);
  const Trajectories motion(scene);
  const double A = scene.max_acceleration();
  const auto& info = GENERATE(from_range(bound_registry().begin(), bound_registry().end()));
  CAPTURE(info.name);
  const bool sample = info.knowledge == Knowledge::Instant;
  StepPipeline plain(info.make(), info.knowledge, parse_broad_phase("grid").make());
  PipelineOptions k_options;
  k_options.kinematic = true;
  StepPipeline kinematic(info.make(), info.knowledge, parse_broad_phase("grid").make(), narrow_table(), k_options);
  plain.set_scenery(scene.scenery);
  kinematic.set_scenery(scene.scenery);
  StateCursor cursor(motion);
  std::vector<BodyState> start;
  StepResult a, b;
  std::uint64_t saved = 0, contacts = 0;
  const double dt = 0.0625;
  for (int k = 0; k < 16; ++k) {
    StepContext ctx;
    ctx.t0 = k * dt;
    ctx.t1 = sample ? ctx.t0 : (k + 1) * dt;
    cursor.evaluate(ctx.t0, start);
    ctx.start = start;
    ctx.exact = info.knowledge == Knowledge::Exact ? &motion : nullptr;
    ctx.acceleration_bound = A;
    ctx.walls = scene.box;
    const ccd::RigidMotion scene_motion(scene, motion);
    ctx.motion = &scene_motion;
    plain.run(ctx, a, nullptr, cursor.pieces());
    kinematic.run(ctx, b, nullptr, cursor.pieces());
    // Index pairs: brute force over the pipeline's boxes, sorted by body then polygon.
    std::vector<StaticPair> brute;
    for (std::uint32_t i = 0; i < motion.size(); ++i)
      for (std::uint32_t p = 0; p < scene.scenery.size(); ++p)
        if (plain.boxes()[i].overlaps(polygon_box(scene.scenery[p]))) brute.push_back({i, p});
    REQUIRE(a.scenery.candidates == brute);
    CHECK(b.scenery.candidates == brute);
    CHECK(a.scenery.passed == b.scenery.passed);
    for (const StaticPair& p : a.scenery.passed) CHECK(std::binary_search(brute.begin(), brute.end(), p));
    // First contact per body: the same with and without the kinematic principle.
    std::map<std::uint32_t, double> first_a, first_b;
    for (const StaticContact& c : a.scenery.contacts) {
      auto [it, fresh] = first_a.emplace(c.pair.body, c.contact.toi);
      if (!fresh) it->second = std::min(it->second, c.contact.toi);
    }
    for (const StaticContact& c : b.scenery.contacts) {
      auto [it, fresh] = first_b.emplace(c.pair.body, c.contact.toi);
      if (!fresh) it->second = std::min(it->second, c.contact.toi);
    }
    CHECK(first_a == first_b);
    CHECK(a.scenery.tests_saved == 0);
    CHECK(b.scenery.contacts.size() <= a.scenery.contacts.size());
    saved += b.scenery.tests_saved;
    contacts += a.scenery.contacts.size();
  }
  CHECK(contacts > 0);
  // Bounds whose static test carries timing (an earliest time later than the window's
  // start) see several plates per body and step: the principle skips some. The box
  // default (horn_sat, obb_sat) says "from t0" for every polygon: nothing to skip.
  const std::string name(info.name);
  if (name == "capsule" || name == "swept_aabb" || name == "horn" || name == "enclosing_sphere") CHECK(saved > 0);
  else CHECK(saved == 0);
}

namespace {

std::uint64_t polygon_calls = 0;

// The exact sphere x polygon entry, counted.
ContactResult counted_sphere_polygon(const NarrowInput& in, std::uint32_t body, const StaticPolygon& polygon) {
  ++polygon_calls;
  return sphere_polygon_narrow(in, body, polygon);
}

}  // namespace

TEST_CASE("static stages: the narrow phase is the table's polygon column", "[pipeline][scenery]") {
  const Scene scene = test::plates_scene(1406, 40);
  const Trajectories motion(scene);
  const ccd::RigidMotion scene_motion(scene, motion);
  NarrowTable counted = narrow_table();
  counted.add_polygon(ShapeKind::Sphere, &counted_sphere_polygon);
  NarrowTable no_polygons;  // the body pairs' entry only
  no_polygons.add(ShapeKind::Sphere, ShapeKind::Sphere, &sphere_sphere_narrow);
  const BoundSpec capsule = parse_bound("capsule");
  StepPipeline plain(capsule.make(), capsule.info->knowledge, parse_broad_phase("grid").make());
  StepPipeline with_counted(capsule.make(), capsule.info->knowledge, parse_broad_phase("grid").make(), counted);
  StepPipeline without(capsule.make(), capsule.info->knowledge, parse_broad_phase("grid").make(), no_polygons);
  for (StepPipeline* p : {&plain, &with_counted, &without}) p->set_scenery(scene.scenery);
  StateCursor cursor(motion);
  std::vector<BodyState> start;
  StepResult a, b, c;
  std::uint64_t passed = 0;
  bool refused = false;
  polygon_calls = 0;
  for (int k = 0; k < 16; ++k) {
    StepContext ctx;
    ctx.t0 = k * 0.0625;
    ctx.t1 = (k + 1) * 0.0625;
    cursor.evaluate(ctx.t0, start);
    ctx.start = start;
    ctx.exact = &motion;
    ctx.walls = scene.box;
    ctx.motion = &scene_motion;
    plain.run(ctx, a, nullptr, cursor.pieces());
    with_counted.run(ctx, b, nullptr, cursor.pieces());
    passed += a.scenery.passed.size();
    // One call of the table's entry per passed pair, and the same contacts.
    CHECK(polygon_calls == passed);
    REQUIRE(a.scenery.contacts.size() == b.scenery.contacts.size());
    for (std::size_t i = 0; i < a.scenery.contacts.size(); ++i) {
      CHECK(a.scenery.contacts[i].pair == b.scenery.contacts[i].pair);
      CHECK(a.scenery.contacts[i].contact.toi == b.scenery.contacts[i].contact.toi);
    }
    // A table without the body's polygon entry: the static stage names the missing one.
    if (!a.scenery.passed.empty() && !refused) {
      CHECK_THROWS_WITH(without.run(ctx, c, nullptr, cursor.pieces()),
                        Catch::Contains("no narrow phase for sphere x polygon"));
      refused = true;
    }
  }
  CHECK(passed > 0);
  CHECK(refused);
}

}  // namespace pipeline_static_stage_test
