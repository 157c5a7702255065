// `bowl`: the scenery it promises (docs/generators.md) and the contacts it makes (exact
// static truth, ccd/truth/static_truth.hpp).
#include "generator_test_support.hpp"

#include <ccd/motion/trajectory.hpp>
#include <ccd/truth/static_truth.hpp>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

namespace generators_bowl_test {

using ccdlab::testing::make;
using nlohmann::json;

TEST_CASE("bowl: a polygon floor and a triangle mesh of sides, balls inside", "[generators][scenery]") {
  const ccd::Scene s = make("bowl", {{"bodies", 30}, {"sides", 6}, {"seed", 2}});
  REQUIRE(s.scenery_mesh);
  CHECK(s.scenery_mesh->vertices.size() == 12);
  CHECK(s.scenery_mesh->triangles.size() == 12);
  REQUIRE(s.scenery.size() == 13);
  CHECK(s.scenery[0].vertices.size() == 6);
  // The scene writes back its mesh and reads back the same.
  const ccd::Scene back = ccd::scene_from_json(ccd::scene_to_json(s), "bowl");
  CHECK(ccdlab::testing::same_scene(back, s));
  const auto ev = ccd::compute_static_truth(ccd::Trajectories(s), s.scenery, 1);
  // Every ball falls onto the floor polygon within the horizon (1 s; starts at most R high).
  for (std::uint32_t i = 0; i < s.bodies.size(); ++i)
    CHECK(std::any_of(ev.begin(), ev.end(), [&](const ccd::StaticEvent& e) { return e.body == i && e.polygon == 0; }));
}

}  // namespace generators_bowl_test
