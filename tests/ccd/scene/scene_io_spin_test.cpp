// ccdlab-scene/2 with free spin and mass properties: the fields, their defaults, the
// round trip, and every refusal naming the file, the field and the index.
#include "scene_error.hpp"

#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>

#include <catch2/catch.hpp>
#include <cmath>

namespace ccd_scene_scene_io_spin_test {

using ccd::Vec3;
using nlohmann::json;

namespace {

using ccd::test::error_of;

json spin_scene() {
  return json::parse(R"({"format": "ccdlab-scene/2", "horizon": 2.0,
    "shapes": [{"name": "crate", "kind": "box", "half_extents": [0.5, 0.25, 0.125]},
               {"name": "rock", "kind": "hull", "points": [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]]},
               {"name": "wedge", "kind": "hull", "points": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]}],
    "bodies": [{"shape": "crate", "position": [0, 0, 0], "angular_velocity": [1, 2, 3], "spin": "free"},
               {"shape": "crate", "position": [4, 0, 0], "angular_velocity": [1, 2, 3], "spin": "free", "mass": 2.0},
               {"shape": "rock", "position": [8, 0, 0], "spin": "free", "density": 500, "angular_velocity": [0, 1, 0]},
               {"shape": "crate", "position": [12, 0, 0], "spin": "prescribed", "inertia": [1, 2, 2.5]},
               {"shape": "wedge", "position": [16, 0, 0]}]})");
}

}  // namespace

TEST_CASE("free spin and mass properties parse, default and round-trip", "[scene][rigid][spin]") {
  const ccd::Scene s = ccd::scene_from_json(spin_scene(), "s.json");
  CHECK(s.rigid[0].spin == ccd::SpinModel::Free);
  CHECK(s.rigid[3].spin == ccd::SpinModel::Prescribed);
  CHECK(s.rigid[4].spin == ccd::SpinModel::Prescribed);  // the default
  Vec3 m0, m1, m3;
  Eigen::Matrix3d axes;
  s.principal_inertia(0, m0, axes);
  // Default density 1000: a 1 x 0.5 x 0.25 crate weighs 125 kg; I_xx = m (0.25 + 0.0625) / 12.
  CHECK(m0[0] == Approx(125.0 * (0.25 + 0.0625) / 12.0));
  s.principal_inertia(1, m1, axes);
  CHECK((m1 - m0 * (2.0 / 125.0)).norm() <= 1e-14 * m1.norm());
  s.principal_inertia(3, m3, axes);
  CHECK(m3 == Vec3(1, 2, 2.5));
  const json back = ccd::scene_to_json(s);
  CHECK(back["bodies"][0]["spin"] == "free");
  CHECK(back["bodies"][1]["mass"] == 2.0);
  CHECK(back["bodies"][2]["density"] == 500.0);
  CHECK(back["bodies"][3]["inertia"] == json::array({1.0, 2.0, 2.5}));
  CHECK_FALSE(back["bodies"][3].contains("spin"));  // the default is not written
  CHECK_FALSE(back["bodies"][4].contains("mass"));
  CHECK(ccd::scene_digest(ccd::scene_from_json(back, "b.json")) == ccd::scene_digest(s));
}

TEST_CASE("a version-2 file without the new fields reads and writes as before", "[scene][rigid][spin]") {
  json j = spin_scene();
  for (json& b : j["bodies"])
    for (const char* k : {"spin", "mass", "density", "inertia"}) b.erase(k);
  j["shapes"].erase(2);
  j["bodies"].erase(4);
  const ccd::Scene s = ccd::scene_from_json(j, "s.json");
  for (const ccd::RigidBody& r : s.rigid) {
    CHECK(r.spin == ccd::SpinModel::Prescribed);
    CHECK_FALSE(r.mass);
    CHECK_FALSE(r.inertia);
  }
  const json back = ccd::scene_to_json(s);
  for (const json& b : back["bodies"])
    for (const char* k : {"spin", "mass", "density", "inertia"}) CHECK_FALSE(b.contains(k));
}

TEST_CASE("bad spin and mass fields name the file, the field and the index", "[scene][rigid][spin]") {
  json j = spin_scene();
  std::string expected;
  SECTION("unknown spin") {
    j["bodies"][1]["spin"] = "wobbly";
    expected = "s.json: bodies[1].spin: unknown spin \"wobbly\" (prescribed, free)";
  }
  SECTION("zero mass") {
    j["bodies"][1]["mass"] = 0.0;
    expected = "s.json: bodies[1].mass: must be > 0";
  }
  SECTION("negative density") {
    j["bodies"][2]["density"] = -1.0;
    expected = "s.json: bodies[2].density: must be > 0";
  }
  SECTION("mass and density") {
    j["bodies"][1]["density"] = 3.0;
    expected = "s.json: bodies[1].density: not allowed with mass (give one of them)";
  }
  SECTION("a non-positive principal moment") {
    j["bodies"][3]["inertia"] = {1.0, 0.0, 1.0};
    expected = "s.json: bodies[3].inertia[1]: must be > 0 (a principal moment)";
  }
  SECTION("moments violating the triangle inequality") {
    j["bodies"][3]["inertia"] = {1.0, 1.0, 2.5};
    expected = "s.json: bodies[3].inertia: violates the triangle inequality: inertia[2] must be <= the sum of the "
               "other two moments";
  }
  SECTION("inertia not a vector") {
    j["bodies"][3]["inertia"] = 2.0;
    expected = "s.json: bodies[3].inertia: must be an array of 3 numbers";
  }
  SECTION("a free hull whose centre of mass is off its origin") {
    j["bodies"][4]["spin"] = "free";
    expected = "s.json: bodies[4].spin: free spin needs the hull's centre of mass at its origin; \"wedge\" has it at "
               "(0.25, 0.25, 0.25) (shift its points, or give inertia)";
  }
  SECTION("spin in a version-1 file") {
    j = json::parse(R"({"format": "ccdlab-scene/1", "horizon": 1, "bodies": [{"radius": 1, "position": [0, 0, 0], "spin": "free"}]})");
    expected = "s.json: bodies[0].spin: needs format \"ccdlab-scene/2\"";
  }
  CHECK(error_of(j) == expected);
}

namespace {

// n (even) points on the unit sphere: a Fibonacci spiral of n / 2 and their opposites, so
// the hull's centre of mass is at the origin (as free spin needs).
json sphere_points(int n) {
  json points = json::array();
  for (int i = 0; i < n / 2; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / (n / 2), r = std::sqrt(1.0 - z * z), a = 2.399963229728653 * i;
    points.push_back({r * std::cos(a), r * std::sin(a), z});
    points.push_back({-r * std::cos(a), -r * std::sin(a), -z});
  }
  return points;
}

json free_hull_scene(int points) {
  return {{"format", "ccdlab-scene/2"},
          {"horizon", 1.0},
          {"shapes", {{{"name", "ball"}, {"kind", "hull"}, {"points", sphere_points(points)}}}},
          {"bodies",
           {{{"shape", "ball"}, {"position", {0, 0, 0}}, {"spin", "free"}, {"angular_velocity", {1, 2, 3}}},
            {{"shape", "ball"}, {"position", {5, 0, 0}}, {"spin", "free"}, {"angular_velocity", {3, 2, 1}}}}}};
}

}  // namespace

TEST_CASE("a free hull's mass properties: thousands of points load, a huge hull is refused before them",
          "[scene][spin][hostile]") {
  // 4,000 points: about 4e13 point tests by triples, 3e7 face tests by the incremental hull.
  const ccd::Scene s = ccd::scene_from_json(free_hull_scene(4000), "s.json");
  Vec3 moments;
  Eigen::Matrix3d axes;
  s.principal_inertia(0, moments, axes);
  // A ball of radius 1 and density 1000 has I = 2/5 m = 1675.5; the inscribed hull a little less.
  CHECK(moments.maxCoeff() < 1675.6);
  CHECK(moments.minCoeff() > 0.99 * 1675.5);
  // 200,000 points: refused by their count, before any face is computed.
  CHECK(error_of(free_hull_scene(200000)) ==
        "s.json: bodies[0].spin: free spin computes the mass properties of \"ball\" from its points, at most 5000 "
        "(it has 200000); give inertia, or fewer points");
  // With inertia given, nothing is computed from the points: the scene loads.
  json given = free_hull_scene(200000);
  for (json& b : given["bodies"]) b["inertia"] = {1, 1, 1};
  CHECK(error_of(given).empty());
}

}  // namespace ccd_scene_scene_io_spin_test
