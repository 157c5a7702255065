// Every generator's scene through the binary scene format (ccd/scene/scene_binary.hpp): the
// sphere scenes read back bit for bit with the digest of their JSON file; the others
// (shapes, spin, scenery) are refused by name.
#include "../ccd/scene/binary_scene_support.hpp"
#include "generator_test_support.hpp"

#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_binary.hpp>
#include <ccd/scene/scene_digest.hpp>

#include <catch2/catch.hpp>
#include <set>
#include <string>

namespace generators_binary_round_trip_test {

using nlohmann::json;

TEST_CASE("every sphere generator's scene round-trips through the binary format", "[generators][binary]") {
  std::set<std::string> packed, refused;
  for (const ccdlab::Generator& g : ccdlab::generators()) {
    for (const json& offset : {json(0.0), json::array({1e6, -2e6, 0.1})}) {
      const std::string name(g.name);
      CAPTURE(name, offset.dump());
      json params = {{"bodies", 40}, {"seed", 7}, {"offset", offset}};
      if (name == "lattice") params["speed"] = 1.0;
      const ccd::Scene generated = ccdlab::testing::make(name, params);
      // The scene as `ccdlab scene` writes it and every command reads it back.
      const ccd::Scene scene = ccd::scene_from_json(json::parse(ccd::scene_to_json(generated).dump(1)), "g.json");
      if (const auto no = ccd::binary_scene_unsupported(scene)) {
        refused.insert(name);
        CHECK_THROWS_AS(ccd::scene_to_binary(scene, "g.json"), ccd::InputError);
        continue;
      }
      packed.insert(name);
      std::string stored;
      const ccd::Scene back = ccd::scene_from_binary(ccd::scene_to_binary(scene, "g.json"), "g.ccds", &stored);
      CHECK(ccd::test::same_bits(back, scene));
      CHECK(stored == ccd::scene_digest(scene));
      CHECK(ccd::scene_digest(back) == stored);
    }
  }
  // The sphere generators (gravity in rain, acceleration changes in swarm, touching bodies
  // in lattice, tangent passes in grazing) pack; the rigid and scenery ones do not.
  CHECK(packed == std::set<std::string>{"gas", "rain", "bullets", "swarm", "lattice", "mixed", "grazing"});
  CHECK(refused == std::set<std::string>{"sticks", "plates", "crates", "rocks", "floor_ramp", "bowl", "pinball", "tumble"});
}

}  // namespace generators_binary_round_trip_test
