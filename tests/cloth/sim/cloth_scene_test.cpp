#include <cloth/sim/cloth_scene.hpp>

#include <ccd/io/input_error.hpp>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

namespace cloth_sim_cloth_scene_test {

using ccd::cloth::parse_cloth_scene;
using nlohmann::json;

namespace {

json good() {
  return {{"format", "ccdlab-cloth/1"},
          {"grid", {{"nx", 4}, {"ny", 3}, {"origin", {0, 1, 0}}, {"du", {0.25, 0, 0}}, {"dv", {0, 0, 0.25}}}},
          {"particle_mass", 0.01},
          {"springs",
           {{"structural", {{"stiffness", 100}, {"damping", 0.1}}},
            {"shear", {{"stiffness", 10}, {"damping", 0}}},
            {"bend", {{"stiffness", 1}, {"damping", 0}}}}},
          {"air_damping", 0.001},
          {"pinned", {0, 3}},
          {"spin", {{"particles", {8, 11}}, {"center", {0, 1, 0}}, {"axis", {2, 0, 0}}, {"rate", 1.5}}},
          {"gravity", {0, -9.81, 0}},
          {"spheres", {{{"center", {0, 0, 0}}, {"radius", 0.5}}}},
          {"floor", -1},
          {"thickness", 0.01},
          {"step", 0.005},
          {"steps", 10}};
}

std::string error_of(const json& j) {
  try {
    parse_cloth_scene(j.dump(), "c.json");
  } catch (const ccd::InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("cloth scene files: fields read and every error named", "[cloth][sim]") {
  const auto s = parse_cloth_scene(good().dump(), "c.json");
  CHECK(s.nx == 4);
  CHECK(s.particle_count() == 12);
  CHECK(s.spin->axis == ccd::Vec3(1, 0, 0));  // normalised
  CHECK(s.spheres.size() == 1);
  CHECK(*s.floor == -1);
  CHECK(s.pinned.size() == 2);
  CHECK(s.air_damping == 0.001);
  json j = good();
  j["grid"]["nx"] = 1;
  CHECK(error_of(j) == "c.json: grid.nx: must be an integer in [2, 1000]");
  j = good();
  j["colour"] = "red";
  CHECK_THAT(error_of(j), Catch::StartsWith("c.json: colour: unknown field"));
  j = good();
  j["springs"]["bend"]["stifness"] = 1;
  CHECK(error_of(j) == "c.json: springs.bend.stifness: unknown field (did you mean \"stiffness\"?)");
  j = good();
  j["pinned"][1] = 12;
  CHECK(error_of(j) == "c.json: pinned[1]: must be an integer in [0, 11]");
  j = good();
  j["spin"]["particles"][0] = 3;
  CHECK(error_of(j) == "c.json: spin.particles[0]: particle is also pinned");
  j = good();
  j["spheres"][0]["radius"] = 0;
  CHECK(error_of(j) == "c.json: spheres[0].radius: must be > 0");
  j = good();
  j["grid"]["dv"] = {0.5, 0, 0};
  CHECK(error_of(j) == "c.json: grid.dv: must not be parallel to grid.du (nor zero)");
  j = good();
  j.erase("step");
  CHECK(error_of(j) == "c.json: step: missing required field");
  j = good();
  j["format"] = "ccdlab-scene/1";
  CHECK(error_of(j) == "c.json: format: must be \"ccdlab-cloth/1\"");
}

}  // namespace cloth_sim_cloth_scene_test
