// `box.boundary` in scene files and the periodic box's images.
#include <ccd/scene/input_error.hpp>
#include <ccd/scene/periodic.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>

#include <catch2/catch.hpp>

#include <set>

using nlohmann::json;

namespace {

json wrapped_scene() {
  return json::parse(R"({"format": "ccdlab-scene/1", "horizon": 2.0,
    "box": {"min": [0,0,0], "max": [8,8,8], "boundary": "wrap"},
    "bodies": [{"radius": 1, "position": [0,4,8], "velocity": [1,0,0]},
               {"radius": 0.5, "position": [7.5,5,5]}]})");
}

std::string error_of(const json& j) {
  try {
    ccd::scene_from_json(j, "s.json");
  } catch (const ccd::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("box.boundary: one name, or one per axis; reflect by default", "[scene][periodic]") {
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
  SECTION("rigid shapes are refused") {
    j["format"] = "ccdlab-scene/2";
    j["shapes"] = json::parse(R"([{"name": "c", "kind": "box", "half_extents": [0.5, 0.25, 0.25]}])");
    j["bodies"][1].erase("radius");
    j["bodies"][1]["shape"] = "c";
    CHECK(error_of(j) == "s.json: bodies[1].shape: a wrapped box (box.boundary) takes plain spheres only");
  }
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
