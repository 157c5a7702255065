// `tumble`: the shapes and scenery it promises (docs/generators.md) and the contacts it
// makes (certified rigid static truth, ccd/truth/rigid_static_truth.hpp).
#include "generator_test_support.hpp"

#include <ccd/motion/rigid_motion.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/truth/rigid_static_truth.hpp>

#include <catch2/catch.hpp>

namespace generators_tumble_test {

using ccdlab::testing::make;

TEST_CASE("tumble: four shapes in turn above a floor polygon and a ramp", "[generators][scenery][rigid]") {
  const ccd::Scene s = make("tumble", {{"bodies", 8}, {"seed", 3}, {"horizon", 2.0}});
  REQUIRE(s.bodies.size() == 8);
  REQUIRE(s.shapes.size() == 4);
  REQUIRE(s.scenery.size() == 2);
  CHECK(s.has_non_spheres());
  REQUIRE(s.box);
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    CHECK(s.rigid[i].shape == static_cast<std::int32_t>(i % 4));
    CHECK(s.bodies[i].radius == s.shapes[i % 4].enclosing_radius());
    // Starts in the upper half of the box, above the ramp's highest edge.
    CHECK(s.bodies[i].position.y() - s.bodies[i].radius >= 0.75 * s.box->max.x() - 1e-12);
  }
  // The scene is valid as written (the reader checks every field and the scenery).
  const ccd::Scene back = ccd::scene_from_json(ccd::scene_to_json(s), "tumble");
  CHECK(ccd::scene_digest(back) == ccd::scene_digest(s));  // the same scene, read back
  CHECK(back.scenery.size() == 2);
  CHECK(back.has_non_spheres());
  // Gravity brings the bodies through the ramp or down to the floor within the horizon.
  const ccd::Trajectories traj(s);
  const ccd::RigidMotion motion(s, traj);
  const ccd::RigidStaticTruthResult r = ccd::compute_rigid_static_truth(motion, s.scenery);
  CHECK(!r.events.empty());
}

}  // namespace generators_tumble_test
