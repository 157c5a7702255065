// `box.boundary` in scene files and the periodic box's images.
#include "scene_error.hpp"

#include <ccd/io/input_error.hpp>
#include <ccd/scene/periodic.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>

#include <catch2/catch.hpp>

#include <set>

namespace ccd_scene_periodic_test {

using nlohmann::json;

namespace {

using ccd::test::error_of;

json wrapped_scene() {
  return json::parse(R"({"format": "ccdlab-scene/1", "horizon": 2.0,
    "box": {"min": [0,0,0], "max": [8,8,8], "boundary": "wrap"},
    "bodies": [{"radius": 1, "position": [0,4,8], "velocity": [1,0,0]},
               {"radius": 0.5, "position": [7.5,5,5]}]})");
}

}  // namespace

TEST_CASE("box.boundary: one name, or one per axis, reflect by default", "[scene][periodic]") {
  const ccd::Scene s = ccd::scene_from_json(wrapped_scene(), "s.json");
  REQUIRE(s.wraps());
  for (int k = 0; k < 3; ++k) CHECK(s.box->wraps(k));
  json j = wrapped_scene();
  j["box"]["boundary"] = {"wrap", "reflect", "wrap"};
  j["bodies"][0]["position"] = {0, 4, 7};  // at least the radius from the walls on y
  const ccd::Scene m = ccd::scene_from_json(j, "s.json");
  CHECK(m.box->wraps(0));
  CHECK_FALSE(m.box->wraps(1));
  CHECK(m.box->wraps(2));
  // Round trip keeps the boundary; a reflecting scene is written without it (its digest
  // does not change).
  CHECK(ccd::scene_from_json(ccd::scene_to_json(m), "s.json").box->boundary == m.box->boundary);
  j["box"].erase("boundary");
  j["bodies"][0]["position"] = {1, 4, 7};
  j["bodies"][1]["position"] = {7, 5, 5};
  const ccd::Scene r = ccd::scene_from_json(j, "s.json");
  CHECK_FALSE(r.wraps());
  CHECK_FALSE(ccd::scene_to_json(r)["box"].contains("boundary"));
  j["box"]["boundary"] = "reflect";
  CHECK(ccd::scene_digest(ccd::scene_from_json(j, "s.json")) == ccd::scene_digest(r));
}

TEST_CASE("box.boundary: bad input names the field", "[scene][periodic]") {
  json j = wrapped_scene();
  SECTION("unknown name") {
    j["box"]["boundary"] = "loop";
    CHECK(error_of(j) == "s.json: box.boundary: must be \"reflect\" or \"wrap\"");
    j["box"]["boundary"] = {"wrap", "loop", "wrap"};
    CHECK(error_of(j) == "s.json: box.boundary[1]: must be \"reflect\" or \"wrap\"");
    j["box"]["boundary"] = {"wrap", "wrap"};
    CHECK(error_of(j).find("s.json: box.boundary: must be") == 0);
  }
  SECTION("edge below twice the largest diameter") {
    j["bodies"][0]["radius"] = 2.0 + 1e-9;  // 4 r > 8
    CHECK(error_of(j) ==
          "s.json: bodies[0].radius: box edge on wrapped axis 0 must be at least twice the body's diameter (4 x radius)");
    j["bodies"][0]["radius"] = 2.0;  // exactly twice: accepted
    CHECK(error_of(j).empty());
  }
  SECTION("centre outside [min, max] on a wrapped axis") {
    j["bodies"][1]["position"] = {8.25, 5, 5};
    CHECK(error_of(j) == "s.json: bodies[1].position[0]: centre must lie in [box.min, box.max] on a wrapped axis");
  }
  SECTION("a shaped body's enclosing radius decides the edge rule") {
    j["format"] = "ccdlab-scene/2";
    // A stick of enclosing radius 1.25 + 0.5 = 1.75 (rounded up by a few ulps): accepted.
    j["shapes"] = json::parse(R"([{"name": "s", "kind": "capsule", "half_length": 1.25, "radius": 0.5}])");
    j["bodies"][1].erase("radius");
    j["bodies"][1]["shape"] = "s";
    CHECK(error_of(j).empty());
    j["shapes"][0]["half_length"] = 1.5 + 1.0 / 1024;  // 4 x 2.0009765625 > 8
    CHECK(error_of(j) == "s.json: bodies[1].shape: box edge on wrapped axis 0 must be at least twice the shape's "
                         "enclosing diameter (4 x enclosing radius)");
  }
}

TEST_CASE("box.boundary: shaped bodies wrap (every kind, prescribed and free spin)", "[scene][periodic][rigid]") {
  json j = json::parse(R"({"format": "ccdlab-scene/2", "horizon": 2.0,
    "box": {"min": [0,0,0], "max": [8,8,8], "boundary": ["wrap", "reflect", "wrap"]},
    "shapes": [{"name": "stick", "kind": "capsule", "half_length": 1.0, "radius": 0.125},
               {"name": "crate", "kind": "box", "half_extents": [0.5, 0.25, 0.125]},
               {"name": "rock", "kind": "hull", "points": [[0.5,0,0], [0,0.5,0], [0,0,0.5], [-0.25,-0.25,-0.25]]}],
    "bodies": [{"shape": "stick", "position": [0,4,8], "velocity": [1,0,0], "angular_velocity": [0,0,4]},
               {"shape": "crate", "position": [7.5,5,5], "angular_velocity": [1,2,3], "spin": "free"},
               {"shape": "rock", "position": [4,4,4]},
               {"radius": 0.5, "position": [2,2,2]}]})");
  const ccd::Scene s = ccd::scene_from_json(j, "s.json");
  REQUIRE(s.wraps());
  CHECK(s.has_non_spheres());
  CHECK(s.kind(0) == ccd::ShapeKind::Capsule);
  CHECK(s.kind(1) == ccd::ShapeKind::Box);
  CHECK(s.rigid_body(1).spin == ccd::SpinModel::Free);
  // Round trip keeps shapes, spin and boundary.
  const ccd::Scene back = ccd::scene_from_json(ccd::scene_to_json(s), "s.json");
  CHECK(back.box->boundary == s.box->boundary);
  CHECK(ccd::scene_digest(back) == ccd::scene_digest(s));
  // On the reflecting axis y the enclosing sphere must start inside the walls, as before.
  j["bodies"][0]["position"] = {0, 0.5, 8};  // stick's enclosing radius 1.125 > 0.5
  CHECK(error_of(j) == "s.json: bodies[0].position: body must start inside the box (centre at least radius from every wall)");
}

TEST_CASE("periodic box: images of a box meet the cell, nearest image", "[scene][periodic]") {
  ccd::Scene s;
  s.box = ccd::WallBox{};
  s.box->max = ccd::Vec3(8, 8, 8);
  s.box->boundary = {ccd::Boundary::Wrap, ccd::Boundary::Wrap, ccd::Boundary::Reflect};
  const ccd::PeriodicBox p = *ccd::PeriodicBox::of(s);
  auto images = [&](const ccd::Aabb& b) {
    std::set<ccd::ImageShift> out;
    p.for_each_image(b, [&](const ccd::ImageShift& x) { out.insert(x); });
    return out;
  };
  // Inside: only itself.
  CHECK(images({{1, 1, 1}, {2, 2, 2}}) == std::set<ccd::ImageShift>{{0, 0, 0}});
  // Over the max face on x: also one period back; over both x and y: the corner too.
  CHECK(images({{7, 1, 1}, {9, 2, 2}}) == std::set<ccd::ImageShift>{{0, 0, 0}, {-1, 0, 0}});
  CHECK(images({{7, -1, 1}, {9, 2, 2}}) ==
        std::set<ccd::ImageShift>{{0, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {-1, 1, 0}});
  // The reflecting axis z has no images, however wide the box.
  CHECK(images({{1, 1, -5}, {2, 2, 15}}) == std::set<ccd::ImageShift>{{0, 0, 0}});
  // Wider than a period: every shift that brings a part of it into the cell.
  CHECK(images({{-9, 1, 1}, {1, 2, 2}}).size() == 3);
  CHECK(p.nearest({0.5, 4, 4}, {7.5, 4, 4}) == ccd::ImageShift{-1, 0, 0});
  CHECK(p.nearest({7.5, 4, 4}, {0.5, 4, 4}) == ccd::ImageShift{1, 0, 0});
  CHECK(p.nearest({4, 4, 4}, {4, 4, 7.9}) == ccd::ImageShift{0, 0, 0});  // z reflects
  CHECK(p.shift(0, -3).value() == -24.0);
}

}  // namespace ccd_scene_periodic_test
