// The scene digest: a function of the scene, not of how its file is written.
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/util/sha256.hpp>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

namespace ccd_scene_scene_digest_test {

using nlohmann::json;

namespace {

const char* kScene = R"({"format": "ccdlab-scene/1", "horizon": 2.0, "gravity": [0, 0, -9.81],
  "box": {"min": [0, 0, 0], "max": [10, 10, 10]},
  "bodies": [{"radius": 0.5, "position": [1, 1, 1], "velocity": [1, 0, 0]},
             {"radius": 0.25, "position": [5, 5, 5], "velocity": [0, 1, 0]}]})";

ccd::Scene parse(const json& j) { return ccd::scene_from_json(j, "s.json"); }

}  // namespace

TEST_CASE("the scene digest is SHA-256 of the canonical scene text", "[scene][digest]") {
  const ccd::Scene s = parse(json::parse(kScene));
  const std::string digest = ccd::scene_digest(s);
  CHECK(digest.size() == 64);
  CHECK(digest == ccd::sha256_hex(ccd::canonical_scene_text(s)));
  // Canonical text: compact, keys sorted.
  CHECK(ccd::canonical_scene_text(s).rfind("{\"bodies\":[{\"acceleration\":[0.0,0.0,0.0]", 0) == 0);
}

TEST_CASE("the same scene written differently has the same digest, any change changes it", "[scene][digest]") {
  const json j = json::parse(kScene);
  const std::string digest = ccd::scene_digest(parse(j));
  SECTION("spelling: 1 vs 1.0 vs 1e0, key order, whitespace") {
    json k = json::parse(R"({"bodies": [{"velocity": [1e0, 0.0, 0], "position": [1.0, 1, 1], "radius": 5e-1},
      {"position": [5, 5, 5], "radius": 0.25, "velocity": [0, 1, 0]}], "box": {"max": [10, 10, 10],
      "min": [0, 0, 0]}, "gravity": [0, 0, -9.81], "horizon": 2, "format": "ccdlab-scene/1"})");
    CHECK(ccd::scene_digest(parse(k)) == digest);
  }
  SECTION("one ulp of one radius") {
    json k = j;
    k["bodies"][1]["radius"] = std::nextafter(0.25, 1.0);
    CHECK(ccd::scene_digest(parse(k)) != digest);
  }
  SECTION("the horizon") {
    json k = j;
    k["horizon"] = 3.0;
    CHECK(ccd::scene_digest(parse(k)) != digest);
  }
  SECTION("the order of the bodies (indices name the pairs of a truth)") {
    json k = j;
    std::swap(k["bodies"][0], k["bodies"][1]);
    CHECK(ccd::scene_digest(parse(k)) != digest);
  }
}

}  // namespace ccd_scene_scene_digest_test
