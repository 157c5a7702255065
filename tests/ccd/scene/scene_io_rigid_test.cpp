// ccdlab-scene/2: shapes, orientation and prescribed spin.
#include "scene_error.hpp"

#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

namespace ccd_scene_scene_io_rigid_test {

using ccd::InputError;
using ccd::Vec3;
using nlohmann::json;

namespace {

using ccd::test::error_of;

json rigid_scene() {
  return json::parse(R"({"format": "ccdlab-scene/2", "horizon": 2.0,
    "box": {"min": [0, 0, 0], "max": [20, 20, 20]}, "gravity": [0, -9.81, 0],
    "shapes": [{"name": "stick", "kind": "capsule", "half_length": 1.0, "radius": 0.05},
               {"name": "crate", "kind": "box", "half_extents": [0.5, 0.3, 0.2]},
               {"name": "rock",  "kind": "hull", "points": [[0.3, 0, 0], [0, 0.4, 0], [0, 0, 0.2], [-0.2, -0.1, -0.1]]},
               {"name": "ball",  "kind": "sphere", "radius": 0.25}],
    "bodies": [{"shape": "crate", "position": [5, 5, 5], "velocity": [1, 0, 0],
                "orientation": [1, 0, 0, 0], "angular_velocity": [0, 0, 6.3],
                "angular_velocity_changes": [{"t": 1.0, "angular_velocity": [2, 0, 0]}]},
               {"radius": 0.5, "position": [8, 5, 5]},
               {"shape": "stick", "position": [12, 5, 5], "orientation": [0, 0, 0, 1]},
               {"shape": "rock", "position": [15, 5, 5]},
               {"shape": "ball", "position": [15, 15, 5]}]})");
}

}  // namespace

TEST_CASE("a ccdlab-scene/2 file parses: shapes, enclosing radii, normalised orientation", "[scene][rigid]") {
  json j = rigid_scene();
  j["bodies"][2]["orientation"] = {0, 0, 0, 1.0000001};  // |q| 1e-7 from 1: normalised
  const ccd::Scene s = ccd::scene_from_json(j, "s.json");
  REQUIRE(s.shapes.size() == 4);
  REQUIRE(s.bodies.size() == 5);
  CHECK(s.kind(0) == ccd::ShapeKind::Box);
  CHECK(s.kind(1) == ccd::ShapeKind::Sphere);
  CHECK(s.kind(2) == ccd::ShapeKind::Capsule);
  CHECK(s.kind(3) == ccd::ShapeKind::Hull);
  CHECK(s.kind(4) == ccd::ShapeKind::Sphere);
  CHECK(s.bodies[0].radius == s.shapes[1].enclosing_radius());
  CHECK(s.bodies[1].radius == 0.5);
  CHECK(s.bodies[2].radius == s.shapes[0].enclosing_radius());
  CHECK(s.bodies[4].radius == 0.25);
  CHECK(s.rigid[2].orientation.norm() == Approx(1.0).epsilon(1e-15));
  CHECK(s.rigid[2].orientation.z() == Approx(1.0).epsilon(1e-15));
  REQUIRE(s.rigid[0].angular_velocity_changes.size() == 1);
  CHECK(s.rigid[0].angular_velocity_changes[0].angular_velocity == Vec3(2, 0, 0));
  CHECK(s.is_rigid());
  CHECK(s.has_non_spheres());
}

TEST_CASE("a normalised orientation reads back bit for bit, so a written scene keeps its digest", "[scene][rigid]") {
  // Generators normalise their quaternions in memory; normalising them again on reading
  // moves their last bits in many cases, and the written scene would be another scene.
  json j = rigid_scene();
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 500; ++trial) {
    const double w = u(rng), x = u(rng), y = u(rng), z = u(rng);
    const Eigen::Quaterniond q = Eigen::Quaterniond(w, x, y, z).normalized();
    j["bodies"][2]["orientation"] = {q.w(), q.x(), q.y(), q.z()};
    const ccd::Scene a = ccd::scene_from_json(j, "s.json");
    REQUIRE(a.rigid[2].orientation.coeffs() == q.coeffs());
    const ccd::Scene b = ccd::scene_from_json(ccd::scene_to_json(a), "s.json");
    REQUIRE(b.rigid[2].orientation.coeffs() == q.coeffs());
    REQUIRE(ccd::scene_digest(a) == ccd::scene_digest(b));
  }
  // Not yet normalised (|q| - 1 about 1e-9, within the reader's tolerance): normalised.
  j["bodies"][2]["orientation"] = {0.5, 0.5, 0.5, 0.500000002};
  const ccd::Scene c = ccd::scene_from_json(j, "s.json");
  CHECK(c.rigid[2].orientation.w() != 0.5);
  CHECK(std::fabs(c.rigid[2].orientation.squaredNorm() - 1.0) <= 1e-15);
}

TEST_CASE("a rigid scene round-trips as ccdlab-scene/2, a sphere scene stays ccdlab-scene/1", "[scene][rigid]") {
  json j = rigid_scene();
  j["bodies"][2]["orientation"] = {0.5, 0.5, 0.5, 0.5};
  const ccd::Scene a = ccd::scene_from_json(j, "s.json");
  const json out = ccd::scene_to_json(a);
  CHECK(out["format"] == "ccdlab-scene/2");
  const ccd::Scene b = ccd::scene_from_json(out, "s.json");
  CHECK(ccd::scene_to_json(b) == out);
  CHECK(ccd::scene_digest(a) == ccd::scene_digest(b));
  REQUIRE(b.shapes.size() == a.shapes.size());
  CHECK(b.shapes[2].points == a.shapes[2].points);
  CHECK(b.rigid[2].orientation.coeffs() == a.rigid[2].orientation.coeffs());

  // Spheres only, no spin: written as version 1, with no version-2 field.
  const ccd::Scene spheres = ccd::scene_from_json(
      json::parse(R"({"format": "ccdlab-scene/1", "horizon": 1, "bodies": [{"radius": 0.5, "position": [0, 0, 0]}]})"), "s.json");
  const json v1 = ccd::scene_to_json(spheres);
  CHECK(v1["format"] == "ccdlab-scene/1");
  CHECK_FALSE(v1.contains("shapes"));
  CHECK_FALSE(v1["bodies"][0].contains("orientation"));
  // A version-2 file of spheres without spin is the same scene, so the same digest.
  json as_v2 = v1;
  as_v2["format"] = "ccdlab-scene/2";
  CHECK(ccd::scene_digest(ccd::scene_from_json(as_v2, "s.json")) == ccd::scene_digest(spheres));
  CHECK(ccd::scene_from_json(as_v2, "s.json").rigid.empty());
}

TEST_CASE("bad rigid scenes name the file, the field and the index", "[scene][rigid]") {
  json j = rigid_scene();
  std::string expected;
  SECTION("unknown kind") {
    j["shapes"][1]["kind"] = "cylinder";
    expected = "s.json: shapes[1].kind: unknown shape kind \"cylinder\" (sphere, capsule, box, hull)";
  }
  SECTION("unknown shape name") {
    j["bodies"][3]["shape"] = "boulder";
    expected = "s.json: bodies[3].shape: unknown shape \"boulder\" (not in shapes)";
  }
  SECTION("duplicate shape name") {
    j["shapes"][2]["name"] = "stick";
    expected = "s.json: shapes[2].name: \"stick\" is already the name of shapes[0]";
  }
  SECTION("negative half extent") {
    j["shapes"][1]["half_extents"][2] = -0.2;
    expected = "s.json: shapes[1].half_extents[2]: must be > 0";
  }
  SECTION("zero capsule radius") {
    j["shapes"][0]["radius"] = 0.0;
    expected = "s.json: shapes[0].radius: must be > 0";
  }
  SECTION("negative half length") {
    j["shapes"][0]["half_length"] = -1.0;
    expected = "s.json: shapes[0].half_length: must be > 0";
  }
  SECTION("coplanar hull") {
    j["shapes"][2]["points"] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    expected = "s.json: shapes[2].points: all points are coplanar (the hull has no volume)";
  }
  SECTION("degenerate hull: three points") {
    j["shapes"][2]["points"] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    expected = "s.json: shapes[2].points: a hull needs at least 4 points (it has 3)";
  }
  SECTION("hull point not a 3-vector") {
    j["shapes"][2]["points"][1] = {1, 2};
    expected = "s.json: shapes[2].points[1]: must be an array of 3 numbers";
  }
  SECTION("shape and radius both") {
    j["bodies"][0]["radius"] = 0.5;
    expected = "s.json: bodies[0].radius: not allowed with shape (the shape gives the size)";
  }
  SECTION("orientation far from unit") {
    j["bodies"][0]["orientation"] = {1, 0, 0, 0.01};
    expected = "s.json: bodies[0].orientation: must be a unit quaternion (|q| is 1.000050)";
  }
  SECTION("orientation of three numbers") {
    j["bodies"][0]["orientation"] = {1, 0, 0};
    expected = "s.json: bodies[0].orientation: must be a quaternion [w, x, y, z]";
  }
  SECTION("angular velocity change at the horizon") {
    j["bodies"][0]["angular_velocity_changes"][0]["t"] = 2.0;
    expected = "s.json: bodies[0].angular_velocity_changes[0].t: must increase strictly and lie in (0, horizon)";
  }
  SECTION("a shaped body that does not fit the box: the enclosing sphere must") {
    j["bodies"][2]["position"] = {0.5, 5, 5};  // stick R = 1.05 > 0.5
    expected = "s.json: bodies[2].position: body must start inside the box (centre at least radius from every wall)";
  }
  SECTION("version-2 fields in a version-1 file") {
    j["format"] = "ccdlab-scene/1";
    expected = "s.json: shapes: needs format \"ccdlab-scene/2\"";
  }
  SECTION("spin in a version-1 file") {
    j = json::parse(R"({"format": "ccdlab-scene/1", "horizon": 1,
                        "bodies": [{"radius": 0.5, "position": [0, 0, 0], "angular_velocity": [1, 0, 0]}]})");
    expected = "s.json: bodies[0].angular_velocity: needs format \"ccdlab-scene/2\"";
  }
  SECTION("unknown format") {
    j["format"] = "ccdlab-scene/3";
    expected = "s.json: format: must be \"ccdlab-scene/1\" or \"ccdlab-scene/2\"";
  }
  CHECK(error_of(j) == expected);
}

}  // namespace ccd_scene_scene_io_rigid_test
