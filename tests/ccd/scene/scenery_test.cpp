// The scenery fields of a scene (docs/scenery.md): reading, validation with the field and
// the reason, writing back, the digest, and the polygon helpers of ccd/scene/scenery.hpp.
#include "scene_error.hpp"

#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/scene/scenery.hpp>

#include <catch2/catch.hpp>

namespace ccd_scene_scenery_test {

using ccd::Vec3;
using nlohmann::json;

namespace {

using ccd::test::error_of;

json scene_with_scenery() {
  return json::parse(R"({"format": "ccdlab-scene/2", "horizon": 2.0, "gravity": [0, 0, -1],
    "box": {"min": [-4, -4, 0], "max": [4, 4, 8]},
    "bodies": [{"radius": 0.5, "position": [0, 0, 2]}],
    "scenery": [{"polygon": [[-2, -2, 0], [2, -2, 0], [2, 2, 0], [-2, 2, 0]]},
                {"polygon": [[0, 0, 1], [1, 0, 1.5], [0, 1, 1]], "comment": "a ramp"}],
    "scenery_mesh": {"vertices": [[3, 3, 3], [3.5, 3, 3], [3.5, 3.5, 3], [3, 3.5, 3]],
                     "triangles": [[0, 1, 2], [0, 2, 3]]}})");
}

json with_polygon(json polygon) {
  json j = scene_with_scenery();
  j["scenery"][1]["polygon"] = std::move(polygon);
  return j;
}

}  // namespace

TEST_CASE("scenery: polygons then mesh triangles, with derived planes", "[scene][scenery]") {
  const ccd::Scene s = ccd::scene_from_json(scene_with_scenery(), "s.json");
  REQUIRE(s.scenery.size() == 4);  // 2 polygons, then 2 triangles
  CHECK(s.scenery[0].normal == Vec3(0, 0, 1));
  CHECK(s.scenery[0].offset == 0.0);
  CHECK(s.scenery[2].vertices == std::vector<Vec3>{Vec3(3, 3, 3), Vec3(3.5, 3, 3), Vec3(3.5, 3.5, 3)});
  CHECK(s.scenery[3].vertices == std::vector<Vec3>{Vec3(3, 3, 3), Vec3(3.5, 3.5, 3), Vec3(3, 3.5, 3)});
  CHECK(s.scenery[3].offset == 3.0);
  REQUIRE(s.scenery_mesh);
  CHECK(s.scenery_mesh->triangles.size() == 2);
  // Ramp (0,0,1), (1,0,1.5), (0,1,1): normal (-1/2, 0, 1) normalised.
  CHECK(s.scenery[1].normal.isApprox(Vec3(-0.5, 0, 1).normalized(), 1e-15));
}

TEST_CASE("scenery: written back as read, digest only changes with scenery", "[scene][scenery]") {
  const ccd::Scene s = ccd::scene_from_json(scene_with_scenery(), "s.json");
  const json out = ccd::scene_to_json(s);
  CHECK(out["format"] == "ccdlab-scene/2");
  CHECK(out["scenery"].size() == 2);
  CHECK(out["scenery_mesh"]["triangles"] == json::parse("[[0, 1, 2], [0, 2, 3]]"));
  const ccd::Scene back = ccd::scene_from_json(out, "s.json");
  REQUIRE(back.scenery.size() == s.scenery.size());
  for (std::size_t i = 0; i < s.scenery.size(); ++i) CHECK(back.scenery[i].vertices == s.scenery[i].vertices);
  CHECK(ccd::scene_digest(back) == ccd::scene_digest(s));
  // Without scenery the scene is a version-1 sphere scene with its old digest.
  ccd::Scene plain = s;
  plain.scenery.clear();
  plain.scenery_mesh.reset();
  const json pj = ccd::scene_to_json(plain);
  CHECK(pj["format"] == "ccdlab-scene/1");
  CHECK_FALSE(pj.contains("scenery"));
  CHECK_FALSE(pj.contains("scenery_mesh"));
  CHECK(ccd::scene_digest(plain) != ccd::scene_digest(s));
  // One ulp of one scenery vertex changes the digest.
  json moved = scene_with_scenery();
  moved["scenery"][0]["polygon"][0][0] = std::nextafter(-2.0, 0.0);
  CHECK(ccd::scene_digest(ccd::scene_from_json(moved, "s.json")) != ccd::scene_digest(s));
}

TEST_CASE("scenery: bad polygons are rejected with the field, the index and the reason", "[scene][scenery]") {
  CHECK(error_of(with_polygon(json::parse("[[0, 0, 1], [1, 0, 1]]"))) ==
        "s.json: scenery[1].polygon: needs at least 3 vertices, has 2");
  CHECK(error_of(with_polygon(json::parse("[[0, 0, 1], [1, 0, 1], [1, 0, 1], [0, 1, 1]]"))) ==
        "s.json: scenery[1].polygon[2]: repeats vertex 1");
  CHECK(error_of(with_polygon(json::parse("[[0, 0, 1], [1, 0, 1], [2, 0, 1], [0, 1, 1]]"))) ==
        "s.json: scenery[1].polygon[1]: is collinear with its neighbours (vertices 0 and 2)");
  // Non-planar: the fourth vertex 1e-3 off the plane z = 1 of a unit square (the worst
  // vertex about the mean plane is named; here all four are 2.5e-4 from it).
  const std::string bent = error_of(with_polygon(json::parse("[[0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1.001]]")));
  CHECK(bent.rfind("s.json: scenery[1].polygon[", 0) == 0);
  CHECK(bent.find("from the polygon's plane: not planar (tolerance 1e-09 x size 1.41)") != std::string::npos);
  // Within the stated tolerance (1e-9 x size): accepted.
  CHECK(error_of(with_polygon(json::parse("[[0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1.0000000000001]]"))).empty());
  // Non-convex: a dart.
  CHECK(error_of(with_polygon(json::parse("[[0, 0, 1], [2, 0, 1], [1, 0.5, 1], [2, 2, 1], [0, 2, 1]]")))
            .find("not convex") != std::string::npos);
  // A pentagram winds twice: every turn has the same sign, still not convex.
  CHECK(error_of(with_polygon(json::parse(
                     "[[0, 1, 1], [0.588, -0.809, 1], [-0.951, 0.309, 1], [0.951, 0.309, 1], [-0.588, -0.809, 1]]")))
            .find("not convex") != std::string::npos);
  CHECK(error_of(with_polygon(json::parse("[[0, 0, 1], [1, 0, 1], [0, 1, \"x\"]]"))) ==
        "s.json: scenery[1].polygon[2][2]: must be a number");
  CHECK(error_of(with_polygon(json::parse("[[0, 0, 1], [1, 0, 1], [0, 1]]"))) ==
        "s.json: scenery[1].polygon[2]: must be an array of 3 numbers");
  CHECK(error_of(with_polygon(json::parse("[[0, 0, 1], [1, 0, 1], [0, 1, 1e31]]"))) ==
        "s.json: scenery[1].polygon[2][2]: magnitude above the limit 1e+30");
  json j = scene_with_scenery();
  j["scenery"][0] = json::parse(R"({"polygn": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]})");
  CHECK(error_of(j).rfind("s.json: scenery[0].polygn: unknown field", 0) == 0);
}

TEST_CASE("scenery: bad meshes, versions and unsupported combinations", "[scene][scenery]") {
  json j = scene_with_scenery();
  j["scenery_mesh"]["triangles"][1][2] = 4;
  CHECK(error_of(j) == "s.json: scenery_mesh.triangles[1][2]: vertex index 4 out of range (the mesh has 4 vertices)");
  j = scene_with_scenery();
  j["scenery_mesh"]["triangles"][1] = json::parse("[0, 2, 2]");
  CHECK(error_of(j) == "s.json: scenery_mesh.triangles[1][2]: repeats vertex 1");
  j = scene_with_scenery();
  j["scenery_mesh"]["triangles"][0] = json::parse("[0, 1]");
  CHECK(error_of(j) == "s.json: scenery_mesh.triangles[0]: must be an array of 3 vertex indices");
  j = scene_with_scenery();
  j["scenery_mesh"]["vertices"][0] = json::parse("[3, 3, 3.5]");
  j["scenery_mesh"]["triangles"][0] = json::parse("[0, 1, 2]");
  j["scenery_mesh"]["vertices"][1] = json::parse("[3.25, 3.25, 3.25]");
  j["scenery_mesh"]["vertices"][2] = json::parse("[3.5, 3.5, 3]");
  CHECK(error_of(j) == "s.json: scenery_mesh.triangles[0][0]: is collinear with its neighbours (vertices 2 and 1)");
  j = scene_with_scenery();
  j["format"] = "ccdlab-scene/1";
  CHECK(error_of(j) == "s.json: scenery: needs format \"ccdlab-scene/2\"");
  j = scene_with_scenery();
  j["box"]["boundary"] = {"wrap", "reflect", "reflect"};
  CHECK(error_of(j).rfind("s.json: scenery: static scenery in a box that wraps around", 0) == 0);
}

TEST_CASE("scenery with rigid bodies: accepted, and still validated", "[scene][scenery][rigid]") {
  json j = scene_with_scenery();
  j["shapes"] = json::parse(R"([{"name": "b", "kind": "box", "half_extents": [0.25, 0.25, 0.25]}])");
  j["bodies"][0].erase("radius");
  j["bodies"][0]["shape"] = "b";
  const ccd::Scene s = ccd::scene_from_json(j, "s.json");
  CHECK(s.has_non_spheres());
  CHECK_FALSE(s.scenery.empty());
  // A bad polygon is still refused with its index, next to a rigid body.
  j["scenery"][0]["polygon"][2] = j["scenery"][0]["polygon"][0];
  CHECK(error_of(j).rfind("s.json: scenery[0].polygon", 0) == 0);
  // Wrap-around stays refused with rigid bodies too.
  j = scene_with_scenery();
  j["shapes"] = json::parse(R"([{"name": "b", "kind": "box", "half_extents": [0.25, 0.25, 0.25]}])");
  j["bodies"][0].erase("radius");
  j["bodies"][0]["shape"] = "b";
  j["box"]["boundary"] = {"wrap", "reflect", "reflect"};
  CHECK(error_of(j).rfind("s.json: scenery: static scenery in a box that wraps around", 0) == 0);
}

TEST_CASE("polygon_from_vertices and polygon_defect", "[scene][scenery]") {
  const ccd::StaticPolygon p = ccd::polygon_from_vertices({Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)});
  CHECK(p.normal.isApprox(Vec3(1, 1, 1).normalized(), 1e-15));
  CHECK(p.offset == Approx(1.0 / std::sqrt(3.0)).epsilon(1e-15));
  CHECK_FALSE(ccd::polygon_defect(p.vertices));
  // Clockwise input: the normal flips, the polygon is still valid (two-sided).
  const ccd::StaticPolygon q = ccd::polygon_from_vertices({Vec3(0, 0, 1), Vec3(0, 1, 0), Vec3(1, 0, 0)});
  CHECK(q.normal.isApprox(-p.normal, 1e-15));
  CHECK_FALSE(ccd::polygon_defect(q.vertices));
  // Far from the origin (2^40), a unit square is still planar and convex.
  const double F = 1099511627776.0;
  CHECK_FALSE(ccd::polygon_defect({Vec3(F, F, F), Vec3(F + 1, F, F), Vec3(F + 1, F + 1, F), Vec3(F, F + 1, F)}));
  CHECK(ccd::polygon_defect({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0, 0)})->reason.find("collinear") !=
        std::string::npos);
}

}  // namespace ccd_scene_scenery_test
