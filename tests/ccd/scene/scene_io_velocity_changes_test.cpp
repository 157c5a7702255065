// The scene field `velocity_changes` (docs/formats.md): read, written, validated.
#include "scene_error.hpp"

#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>

#include <catch2/catch.hpp>
#include <limits>

namespace ccd_scene_scene_io_velocity_changes_test {

using nlohmann::json;

namespace {

using ccd::test::error_of;

json scene_with_jumps() {
  return json::parse(R"({"format": "ccdlab-scene/1", "horizon": 2.0,
    "bodies": [{"radius": 0.5, "position": [1,2,3], "velocity": [0,0,1],
                "velocity_changes": [{"t": 0.5, "velocity": [1, 0, 0]}, {"t": 1.25, "velocity": [0, -2, 0]}]},
               {"radius": 0.25, "position": [5,5,5]}]})");
}

}  // namespace

TEST_CASE("velocity changes are read, written back and digested", "[scene][velocity_changes]") {
  const ccd::Scene s = ccd::scene_from_json(scene_with_jumps(), "s.json");
  REQUIRE(s.bodies[0].velocity_changes.size() == 2);
  CHECK(s.bodies[0].velocity_changes[1].t == 1.25);
  CHECK(s.bodies[0].velocity_changes[1].velocity == ccd::Vec3(0, -2, 0));
  CHECK(s.bodies[1].velocity_changes.empty());
  CHECK(s.has_velocity_changes());
  CHECK(s.motion_kind() == ccd::MotionKind::PiecewiseQuadratic);
  const ccd::Scene back = ccd::scene_from_json(ccd::scene_to_json(s), "s.json");
  REQUIRE(back.bodies[0].velocity_changes.size() == 2);
  CHECK(back.bodies[0].velocity_changes[0].t == 0.5);
  CHECK(back.bodies[0].velocity_changes[0].velocity == ccd::Vec3(1, 0, 0));
  CHECK(ccd::scene_digest(back) == ccd::scene_digest(s));
  // A scene without changes does not write the field (its digest stays what it was).
  ccd::Scene plain = s;
  plain.bodies[0].velocity_changes.clear();
  CHECK_FALSE(ccd::scene_to_json(plain)["bodies"][0].contains("velocity_changes"));
  CHECK_FALSE(plain.has_velocity_changes());
  CHECK(ccd::scene_digest(plain) != ccd::scene_digest(s));
}

TEST_CASE("bad velocity changes name the file, the field and the indices", "[scene][velocity_changes]") {
  json j = scene_with_jumps();
  auto& ch = j["bodies"][0]["velocity_changes"];
  SECTION("out of order") {
    ch[1]["t"] = 0.5;
    CHECK(error_of(j) == "s.json: bodies[0].velocity_changes[1].t: must increase strictly and lie in (0, horizon)");
  }
  SECTION("at t = 0") {
    ch[0]["t"] = 0.0;
    CHECK(error_of(j) == "s.json: bodies[0].velocity_changes[0].t: must increase strictly and lie in (0, horizon)");
  }
  SECTION("at the horizon") {
    ch[1]["t"] = 2.0;
    CHECK(error_of(j) == "s.json: bodies[0].velocity_changes[1].t: must increase strictly and lie in (0, horizon)");
  }
  SECTION("missing velocity") {
    ch[0].erase("velocity");
    CHECK(error_of(j) == "s.json: bodies[0].velocity_changes[0].velocity: missing required field");
  }
  SECTION("a string for a number") {
    ch[1]["velocity"][1] = "fast";
    CHECK(error_of(j) == "s.json: bodies[0].velocity_changes[1].velocity[1]: must be a number");
  }
  SECTION("unknown field") {
    ch[0]["when"] = 1;
    CHECK(error_of(j) == "s.json: bodies[0].velocity_changes[0].when: unknown field (known: t, velocity)");
  }
  SECTION("not an array") {
    j["bodies"][0]["velocity_changes"] = 3;
    CHECK(error_of(j) == "s.json: bodies[0].velocity_changes: must be an array");
  }
  SECTION("a velocity that travels beyond the limit") {
    ch[1]["velocity"] = {1e30, 0, 0};
    CHECK(error_of(j) == "s.json: bodies[0].velocity_changes[1].velocity: |velocity| * horizon is 2e+30 m, above the "
                         "limit 1e+30 m");
  }
}

TEST_CASE("non-finite velocity changes built in memory are rejected", "[scene][velocity_changes]") {
  ccd::Scene s = ccd::scene_from_json(scene_with_jumps(), "s.json");
  auto error = [&] {
    try {
      ccd::validate_scene(s, "s.json");
    } catch (const ccd::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  SECTION("time NaN") {
    s.bodies[0].velocity_changes[0].t = std::numeric_limits<double>::quiet_NaN();
    CHECK(error() == "s.json: bodies[0].velocity_changes[0].t: must increase strictly and lie in (0, horizon)");
  }
  SECTION("velocity infinite") {
    s.bodies[0].velocity_changes[1].velocity.z() = std::numeric_limits<double>::infinity();
    CHECK(error() == "s.json: bodies[0].velocity_changes[1].velocity[2]: must be finite");
  }
}

}  // namespace ccd_scene_scene_io_velocity_changes_test
