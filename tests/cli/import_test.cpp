// `ccdlab import`: the round trip with `ccdlab poses` (poses of a linear-motion scene,
// imported back, give the same truth), its options, and bad input refused with exit 2,
// the line and the column named, and no file written.
#include "cli_support.hpp"

#include <ccd/scene/scene_io.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace cli_import_test {

using ccdlab::test::Folder;
using ccdlab::test::run_ccdlab;
using nlohmann::json;

namespace {

// Linear motion, no walls: eight bodies of radius 1/2 crossing, grazing, and one at rest;
// dyadic numbers, so the poses at 1/8-s frames are exact and the motion between them is
// the scene's own.
const char* kLinear = R"({"format": "ccdlab-scene/1", "horizon": 2.0,
  "bodies": [{"radius": 0.5, "position": [0, 0, 0], "velocity": [2, 0, 0]},
             {"radius": 0.5, "position": [4, 0.5, 0], "velocity": [-1, 0, 0]},
             {"radius": 0.5, "position": [0, 3, 0], "velocity": [1, 0, 0]},
             {"radius": 0.5, "position": [2, 4, 0]},
             {"radius": 0.5, "position": [0, 8, 0], "velocity": [0.5, 0.25, -1]},
             {"radius": 0.5, "position": [1, 8, -1.5], "velocity": [0, 0, 1]},
             {"radius": 0.5, "position": [-3, -3, -3], "velocity": [1.5, 1.5, 1.5]},
             {"radius": 0.5, "position": [0, -8, 0]}]})";

json events_of(const std::string& truth_file) { return json::parse(ccdlab::test::slurp(truth_file))["events"]; }

}  // namespace

TEST_CASE("ccdlab import: poses of a linear-motion scene come back with the same truth", "[cli][import]") {
  Folder dir;
  std::ofstream(dir / "scene.json") << kLinear;
  REQUIRE(run_ccdlab("poses " + dir / "scene.json" + " --times 0:2:0.125 -o " + dir / "poses.csv", dir) == 0);
  std::string out;
  REQUIRE(run_ccdlab("import " + dir / "poses.csv" + " --radius 0.5 -o " + dir / "back.json", dir, &out) == 0);
  CHECK(out.find("8 bodies, 136 frames, 0 velocity changes, horizon 2 s") != std::string::npos);
  const ccd::Scene back = ccd::load_scene(dir / "back.json");
  const ccd::Scene original = ccd::load_scene(dir / "scene.json");
  REQUIRE(back.bodies.size() == original.bodies.size());
  for (std::size_t i = 0; i < back.bodies.size(); ++i) {
    CHECK(back.bodies[i].position == original.bodies[i].position);
    CHECK(back.bodies[i].velocity == original.bodies[i].velocity);
  }
  REQUIRE(run_ccdlab("truth " + dir / "scene.json" + " -o " + dir / "truth.json", dir) == 0);
  REQUIRE(run_ccdlab("truth " + dir / "back.json" + " -o " + dir / "truth_back.json", dir) == 0);
  const json a = events_of(dir / "truth.json"), b = events_of(dir / "truth_back.json");
  CHECK(a.size() >= 3);
  CHECK(a == b);
}

TEST_CASE("ccdlab import: a scene with velocity changes, through poses at its change times, and back",
          "[cli][import]") {
  Folder dir;
  json s = json::parse(kLinear);
  s["bodies"][0]["velocity_changes"] = json::parse(R"([{"t": 0.5, "velocity": [-2, 0, 0]}, {"t": 1.25, "velocity": [0, 1, 0]}])");
  s["bodies"][3]["velocity_changes"] = json::parse(R"([{"t": 0.25, "velocity": [0, -4, 0]}])");
  std::ofstream(dir / "scene.json") << s.dump();
  REQUIRE(run_ccdlab("poses " + dir / "scene.json" + " --times 0:2:0.125 -o " + dir / "poses.csv", dir) == 0);
  std::string out;
  REQUIRE(run_ccdlab("import " + dir / "poses.csv" + " --radius 0.5 -o " + dir / "back.json", dir, &out) == 0);
  CHECK(out.find("3 velocity changes") != std::string::npos);
  REQUIRE(run_ccdlab("truth " + dir / "scene.json" + " -o " + dir / "truth.json", dir) == 0);
  REQUIRE(run_ccdlab("truth " + dir / "back.json" + " -o " + dir / "truth_back.json", dir) == 0);
  CHECK(events_of(dir / "truth.json") == events_of(dir / "truth_back.json"));
}

TEST_CASE("ccdlab import: shapes from --shapes, rigid bodies, stdout", "[cli][import]") {
  Folder dir;
  std::ofstream(dir / "shapes.json") << R"([{"name": "crate", "kind": "box", "half_extents": [0.5, 0.25, 0.25]}])";
  std::ofstream(dir / "frames.csv") << "body,t,x,y,z,shape,qw,qx,qy,qz\n"
                                       "0,0,0,0,0,crate,1,0,0,0\n"
                                       "0,1,1,0,0,crate,0.70710678118654757,0,0,0.70710678118654757\n"
                                       "1,0,3,0,0,\"box:0.5,0.5,0.5\",1,0,0,0\n"
                                       "1,1,3,0,0,\"box:0.5,0.5,0.5\",1,0,0,0\n";
  std::string out, err;
  REQUIRE(run_ccdlab("import " + dir / "frames.csv" + " --shapes " + dir / "shapes.json" + " -o -", dir, &out, &err) == 0);
  const ccd::Scene s = ccd::scene_from_json(json::parse(out), "stdout");
  REQUIRE(s.shapes.size() == 2);
  CHECK(s.kind(0) == ccd::ShapeKind::Box);
  CHECK(s.rigid[0].angular_velocity.z() == Approx(M_PI / 2).epsilon(1e-14));
  CHECK(err.find("2 bodies, 4 frames") != std::string::npos);
}

TEST_CASE("ccdlab import: bad input exits 2 naming the line and column, writes nothing", "[cli][import]") {
  Folder dir;
  struct Bad {
    const char* csv;
    const char* message;
  };
  const Bad cases[] = {
      {"body,t,x,y,z,radius\n0,0,0,0,0,1\n0,1,zero,0,0,1\n", "line 3: x: must be a finite number, got \"zero\""},
      {"body,t,x,y,radius\n0,0,0,0,1\n", "line 1: header: missing column \"z\""},
      {"body,t,x,y,z,radius\n0,1,0,0,0,1\n0,1,1,0,0,1\n0,0,0,0,0,1\n", "line 3: t: body \"0\" has two frames at t = 1"},
      {"body,t,x,y,z,radius\n0,0,0,0,0,-1\n0,1,0,0,0,-1\n", "line 2: radius: must be > 0"},
      {"body,t,x,y,z,radius\n0,0,0,0,0,1\n0,1,0,0,0,0.5\n", "line 3: radius: body \"0\" has radius 1.000000 on line 2"},
      {"body,t,x,y,z,shape,qw,qx,qy,qz\n0,0,0,0,0,sphere:1,0.9,0,0,0\n", "line 2: qw,qx,qy,qz: must be a unit quaternion"},
      {"body,t,x,y,z,radius\n0,0,0,0,0,1\n0,1,0,0,0\n", "line 3: has 5 cells, the header 6"},
  };
  for (const Bad& c : cases) {
    INFO(c.csv);
    std::ofstream(dir / "bad.csv") << c.csv;
    std::string err;
    CHECK(run_ccdlab("import " + dir / "bad.csv" + " -o " + dir / "out.json", dir, nullptr, &err) == 2);
    CHECK(err.find("ccdlab import: " + dir / "bad.csv" + ": " + c.message) == 0);
    CHECK(err.find('\n') == err.size() - 1);  // one line
    CHECK_FALSE(std::filesystem::exists(dir / "out.json"));
  }
  std::string err;
  CHECK(run_ccdlab("import " + dir / "missing.csv" + " -o " + dir / "out.json", dir, nullptr, &err) == 2);
  CHECK(run_ccdlab("import " + dir / "bad.csv", dir, nullptr, &err) == 2);
  CHECK(err.find("missing -o SCENE.json") != std::string::npos);
  CHECK(run_ccdlab("import " + dir / "bad.csv" + " --radius -1 -o " + dir / "out.json", dir, nullptr, &err) == 2);
  CHECK(err.find("--radius must be a number > 0") != std::string::npos);
  std::string out;
  CHECK(run_ccdlab("import --help", dir, &out) == 0);
  CHECK(out.find("usage: ccdlab import FRAMES.csv -o SCENE.json") != std::string::npos);
}

}  // namespace cli_import_test
