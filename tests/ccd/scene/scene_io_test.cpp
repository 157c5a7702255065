#include "scene_error.hpp"

#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_io.hpp>

#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>

namespace ccd_scene_scene_io_test {

using ccd::InputError;
using nlohmann::json;

namespace {

using ccd::test::error_of;

json valid_scene() {
  return json::parse(R"({"format": "ccdlab-scene/1", "horizon": 2.0, "gravity": [0, -9.81, 0],
    "box": {"min": [0,0,0], "max": [10,10,10]},
    "bodies": [{"radius": 0.5, "position": [1,2,3], "velocity": [0,0,1], "acceleration": [0,0,0]},
               {"radius": 0.25, "position": [5,5,5]}], "comment": "extra fields are kept"})");
}

// Parses j and returns the error message, or "" when it parses.
}  // namespace

TEST_CASE("a valid scene parses with defaults filled in", "[scene]") {
  const ccd::Scene s = ccd::scene_from_json(valid_scene(), "s.json");
  CHECK(s.horizon == 2.0);
  CHECK(s.gravity.y() == -9.81);
  REQUIRE(s.box);
  REQUIRE(s.bodies.size() == 2);
  CHECK(s.bodies[1].velocity.isZero(0.0));
  CHECK(s.bodies[1].acceleration.isZero(0.0));
  CHECK(s.motion_kind() == ccd::MotionKind::SharedAcceleration);
}

TEST_CASE("a scene survives a JSON round trip bit for bit", "[scene]") {
  json j = valid_scene();
  j["bodies"][0]["position"] = {1.0 + 0.1 + 0.2, 1.0 + 1.0 / 3.0, 5.0};
  const ccd::Scene a = ccd::scene_from_json(j, "s.json");
  const ccd::Scene b = ccd::scene_from_json(ccd::scene_to_json(a), "s.json");
  CHECK(a.bodies[0].position == b.bodies[0].position);
  CHECK(a.bodies[1].radius == b.bodies[1].radius);
}

TEST_CASE("bad scenes name the file, the field and the body index", "[scene]") {
  json j = valid_scene();
  SECTION("missing radius") {
    j["bodies"][1].erase("radius");
    CHECK(error_of(j) == "s.json: bodies[1].radius: missing required field");
  }
  SECTION("radius <= 0") {
    j["bodies"][1]["radius"] = 0.0;
    CHECK(error_of(j) == "s.json: bodies[1].radius: must be > 0");
  }
  SECTION("horizon <= 0") {
    j["horizon"] = -1.0;
    CHECK(error_of(j) == "s.json: horizon: must be > 0");
  }
  SECTION("missing horizon") {
    j.erase("horizon");
    CHECK(error_of(j) == "s.json: horizon: missing required field");
  }
  SECTION("wrong format") {
    j["format"] = "ccdlab-scene/3";
    CHECK(error_of(j).find("format") != std::string::npos);
  }
  SECTION("a string where a number belongs") {
    j["bodies"][0]["velocity"][2] = "fast";
    CHECK(error_of(j) == "s.json: bodies[0].velocity[2]: must be a number");
  }
  SECTION("position of the wrong length") {
    j["bodies"][0]["position"] = {1, 2};
    CHECK(error_of(j) == "s.json: bodies[0].position: must be an array of 3 numbers");
  }
  SECTION("body outside the box") {
    j["bodies"][1]["position"] = {9.9, 5, 5};
    CHECK(error_of(j).rfind("s.json: bodies[1].position: body must start inside the box", 0) == 0);
  }
  SECTION("box with min >= max") {
    j["box"]["max"][2] = 0.0;
    CHECK(error_of(j).rfind("s.json: box: min must be < max", 0) == 0);
  }
  SECTION("acceleration changes out of order") {
    j["bodies"][0]["acceleration_changes"] = json::parse(R"([{"t": 1.0, "acceleration": [0,0,0]},
                                                            {"t": 0.5, "acceleration": [0,0,0]}])");
    CHECK(error_of(j) == "s.json: bodies[0].acceleration_changes[1].t: must increase strictly and lie in (0, horizon)");
  }
}

TEST_CASE("NaN and infinity are rejected wherever they appear", "[scene]") {
  // JSON has no NaN literal; a scene built in memory can still carry one.
  ccd::Scene s = ccd::scene_from_json(valid_scene(), "s.json");
  s.bodies[1].velocity.x() = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(ccd::validate_scene(s, "s.json"), "s.json: bodies[1].velocity[0]: must be finite");
  s.bodies[1].velocity.x() = 0.0;
  s.gravity.z() = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH(ccd::validate_scene(s, "s.json"), "s.json: gravity[2]: must be finite");
  // A number too large for a double is rejected by the reader with the file named.
  const std::string path = "scene_io_test_overflow.json";
  {
    std::ofstream(path) << R"({"format": "ccdlab-scene/1", "horizon": 1e999, "bodies": []})";
  }
  CHECK_THROWS_WITH(ccd::load_scene(path), Catch::Matchers::StartsWith(path + ": malformed JSON"));
  std::remove(path.c_str());
}

TEST_CASE("malformed JSON names the file", "[scene]") {
  const std::string path = std::string(CCDLAB_SOURCE_DIR) + "/tests/ccd/scene/no-such-file.json";
  CHECK_THROWS_WITH(ccd::load_scene(path), path + ": cannot open file: No such file or directory");
}

TEST_CASE("a body with no room between two walls must not move along that axis", "[scene]") {
  // Found by fuzzing: a body whose centre lies on both wall planes (box width = diameter)
  // was reflected from one wall into the other at t = 0 and left the box.
  ccd::Scene s;
  s.horizon = 1.0;
  s.box = ccd::WallBox{ccd::Vec3(0, 0, 0), ccd::Vec3(1, 4, 4)};
  s.bodies.push_back({0.5, ccd::Vec3(0.5, 2, 2), ccd::Vec3(100, 0, 0), ccd::Vec3::Zero(), {}});
  CHECK_THROWS_WITH(ccd::validate_scene(s, "s.json"),
                    "s.json: bodies[0].velocity[0]: must be 0: the body fills the box on this axis (no room to "
                    "move between the walls)");
  s.bodies[0].velocity = ccd::Vec3(0, 3, -1);  // across the other axes it may move
  CHECK_NOTHROW(ccd::validate_scene(s, "s.json"));
  SECTION("room is judged on the exact wall planes, not their roundings") {
    // min + r = 2^53 + 1.25 rounds to 2^53 + 2, and so does max - r = 2^53 + 2.75: the
    // rounded planes coincide, the exact ones are 1.5 apart, so the body may move.
    const double two53 = 0x1p53;
    s.box = ccd::WallBox{ccd::Vec3(two53, 0, 0), ccd::Vec3(two53 + 4, 4, 4)};
    s.bodies[0] = {1.25, ccd::Vec3(two53 + 2, 2, 2), ccd::Vec3(1, 0, 0), ccd::Vec3::Zero(), {}};
    REQUIRE(s.box->min.x() + 1.25 == s.box->max.x() - 1.25);
    CHECK_NOTHROW(ccd::validate_scene(s, "s.json"));
  }
}

TEST_CASE("a misspelt field in a scene is an error with the nearest known name", "[scene]") {
  json j = valid_scene();
  SECTION("in a body") {
    j["bodies"][1]["velocty"] = json::array({1, 0, 0});
    CHECK(error_of(j) == R"(s.json: bodies[1].velocty: unknown field (did you mean "velocity"?))");
  }
  SECTION("at the top") {
    j["gravty"] = json::array({0, -9.81, 0});
    CHECK(error_of(j) == R"(s.json: gravty: unknown field (did you mean "gravity"?))");
  }
  SECTION("in the box") {
    j["box"] = {{"min", {-100, -100, -100}}, {"max", {100, 100, 100}}, {"restitution", 1}};
    CHECK(error_of(j) == "s.json: box.restitution: unknown field (known: min, max, boundary)");
  }
  SECTION("in an acceleration change") {
    j["bodies"][0]["acceleration_changes"] = json::array({{{"t", 0.5}, {"acceleration", {1, 0, 0}}, {"when", 1}}});
    CHECK(error_of(j) == "s.json: bodies[0].acceleration_changes[0].when: unknown field (known: t, acceleration)");
  }
  SECTION("comment is allowed anywhere") {
    j["comment"] = "a note";
    j["bodies"][0]["comment"] = "body zero";
    CHECK(error_of(j).empty());
  }
}

}  // namespace ccd_scene_scene_io_test
