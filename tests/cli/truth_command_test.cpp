// Runs the built `ccdlab truth` binary (CCDLAB_BINARY) on good and bad scenes.
#include <ccd/scene/scene_io.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/truth/truth_io.hpp>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace cli_truth_command_test {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Run {
  int status;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class TempDir {
 public:
  TempDir() {
    dir_ = fs::temp_directory_path() / ("ccdlab_truth_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  ~TempDir() { fs::remove_all(dir_); }
  fs::path operator/(const std::string& s) const { return dir_ / s; }

 private:
  fs::path dir_;
};

Run run(const TempDir& tmp, const std::string& args) {
  const std::string cmd = std::string(CCDLAB_BINARY) + " truth " + args + " >" + (tmp / "out.txt").string() +
                          " 2>" + (tmp / "err.txt").string();
  const int raw = std::system(cmd.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(tmp / "out.txt"), slurp(tmp / "err.txt")};
}

json good_scene() {
  return json::parse(R"({"format": "ccdlab-scene/1", "horizon": 10.0,
    "box": {"min": [-20,-20,-20], "max": [20,20,20]},
    "bodies": [{"radius": 1, "position": [0,0,0], "velocity": [1,0,0]},
               {"radius": 1, "position": [10,0,0], "velocity": [-1,0,0]},
               {"radius": 1, "position": [0,10,0]}]})");
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

}  // namespace

TEST_CASE("ccdlab truth writes ccdlab-truth/2 with the scene digest, and a summary", "[experiments][truth]") {
  TempDir tmp;
  write(tmp / "s.json", good_scene().dump());
  const fs::path out = tmp / "t.json";
  const Run r = run(tmp, (tmp / "s.json").string() + " -o " + out.string());
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find("events       1 (0 tangent)") != std::string::npos);
  CHECK(r.out.find("written      " + out.string()) != std::string::npos);
  const ccd::TruthFile t = ccd::load_truth(out.string());
  CHECK(t.horizon == 10.0);
  REQUIRE(t.events.size() == 1);
  CHECK((t.events[0].a == 0 && t.events[0].b == 1));
  CHECK(t.events[0].enter == Approx(4.0).margin(1e-12));
  CHECK(t.events[0].exit == Approx(6.0).margin(1e-12));
  CHECK(t.version == 2);
  CHECK(t.scene_sha256 == ccd::scene_digest(ccd::load_scene((tmp / "s.json").string())));
  CHECK(t.errors.empty());  // the exact solver: no error fields

  const Run quiet = run(tmp, (tmp / "s.json").string() + " --quiet --threads 1 -o " + (tmp / "q.json").string());
  CHECK(quiet.status == 0);
  CHECK(quiet.out.empty());
  CHECK(slurp(tmp / "q.json") == slurp(out));  // same bytes whatever the thread count

  const Run summary = run(tmp, (tmp / "s.json").string());
  CHECK(summary.status == 0);
  CHECK(summary.out.find("bodies       3") != std::string::npos);
}

TEST_CASE("ccdlab truth rejects bad input with status 2 and writes nothing", "[experiments][truth]") {
  TempDir tmp;
  const fs::path scene = tmp / "bad.json";
  const fs::path out = tmp / "t.json";
  json j = good_scene();
  std::string text;
  std::string expected;  // the message after "ccdlab truth: "
  SECTION("malformed JSON") {
    text = "{\"format\": \"ccdlab-scene/1\", \"horizon\": ";
    expected = scene.string() + ": malformed JSON";
  }
  SECTION("missing field") {
    j["bodies"][2].erase("position");
    expected = scene.string() + ": bodies[2].position: missing required field";
  }
  SECTION("radius <= 0") {
    j["bodies"][1]["radius"] = -0.5;
    expected = scene.string() + ": bodies[1].radius: must be > 0";
  }
  SECTION("horizon <= 0") {
    j["horizon"] = 0;
    expected = scene.string() + ": horizon: must be > 0";
  }
  SECTION("body outside the box") {
    j["bodies"][2]["position"] = {0, 19.5, 0};
    expected = scene.string() + ": bodies[2].position: body must start inside the box";
  }
  SECTION("box min >= max") {
    j["box"]["max"][1] = -20;
    expected = scene.string() + ": box: min must be < max";
  }
  if (text.empty()) text = j.dump();
  write(scene, text);
  const Run r = run(tmp, scene.string() + " -o " + out.string());
  CHECK(r.status == 2);
  CHECK(r.err.rfind("ccdlab truth: " + expected, 0) == 0);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);  // one line
  CHECK(!fs::exists(out));
  for (const auto& e : fs::directory_iterator(tmp / ""))  // no temporary left either
    CHECK(e.path().filename().string().rfind("t.json", 0) != 0);
}

TEST_CASE("ccdlab truth usage errors exit with status 2", "[experiments][truth]") {
  TempDir tmp;
  CHECK(run(tmp, "").status == 2);
  CHECK(run(tmp, (tmp / "missing.json").string()).status == 2);
  CHECK(run(tmp, "x.json --threads zero").status == 2);
  CHECK(run(tmp, "x.json --bogus").status == 2);
  CHECK(run(tmp, "x.json -o").status == 2);
}

TEST_CASE("ccdlab truth: a bad ccdlab-scene/2 exits 2 with one line naming file, field and index", "[cli][truth][rigid]") {
  TempDir tmp;
  json s = json::parse(R"({"format": "ccdlab-scene/2", "horizon": 1.0,
    "shapes": [{"name": "crate", "kind": "box", "half_extents": [0.5, 0.25, -0.125]}],
    "bodies": [{"shape": "crate", "position": [0, 0, 0]}, {"radius": 1, "position": [5, 0, 0]}]})");
  const std::string path = (tmp / "bad.json").string();
  std::ofstream(path) << s.dump();
  const Run r = run(tmp, path + " -o " + (tmp / "t.json").string());
  CHECK(r.status == 2);
  CHECK(r.err == "ccdlab truth: " + path + ": shapes[0].half_extents[2]: must be > 0\n");
  CHECK_FALSE(fs::exists(tmp / "t.json"));
  s["shapes"][0]["kind"] = "hull";
  s["shapes"][0].erase("half_extents");
  s["shapes"][0]["points"] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  std::ofstream(path) << s.dump();
  const Run h = run(tmp, path);
  CHECK(h.status == 2);
  CHECK(h.err == "ccdlab truth: " + path + ": shapes[0].points: all points are coplanar (the hull has no volume)\n");
}

TEST_CASE("ccdlab truth on a rigid scene writes certified brackets that read back", "[cli][truth][rigid]") {
  TempDir tmp;
  const std::string scene = std::string(CCDLAB_SOURCE_DIR) + "/data/scenes/rigid-example.json";
  const Run r = run(tmp, scene + " -o " + (tmp / "t.json").string());
  REQUIRE(r.status == 0);
  const ccd::TruthFile t = ccd::load_truth((tmp / "t.json").string());
  CHECK(t.version == 2);
  CHECK(t.scene_sha256 == ccd::scene_digest(ccd::load_scene(scene)));
  REQUIRE(t.events.size() >= 5);
  REQUIRE(t.errors.size() == t.events.size());
  // Brackets: the time tolerance (2^-30 x 2 s, about 2e-9 s) plus the time the pair spends
  // within the distance band (L x tolerance) of touching, a few tolerances at these speeds.
  for (const ccd::EventError& e : t.errors) {
    CHECK(e.enter_error < 5e-8);
    CHECK(e.exit_error < 5e-8);
    CHECK_FALSE(e.grazing);
  }
}

TEST_CASE("ccdlab truth on a scene with scenery writes static events, bad scenery exits 2", "[experiments][truth][scenery]") {
  TempDir tmp;
  // Body 0 falls through the floor polygon (|z| <= 1 for t in [1, 3]); body 1 stays away;
  // body 2 grazes the polygon's edge x = 4 at t = 2 (distance sqrt(1 + (2 - t)^2) >= 1).
  json s = json::parse(R"({"format": "ccdlab-scene/2", "horizon": 4.0,
    "box": {"min": [-20,-20,-20], "max": [20,20,20]},
    "bodies": [{"radius": 1, "position": [0,0,2], "velocity": [0,0,-1]},
               {"radius": 1, "position": [10,10,10]},
               {"radius": 1, "position": [5,0,2], "velocity": [0,0,-1]}],
    "scenery": [{"polygon": [[-4,-4,0], [4,-4,0], [4,4,0], [-4,4,0]]}]})");
  write(tmp / "s.json", s.dump());
  const fs::path out = tmp / "t.json";
  const Run r = run(tmp, (tmp / "s.json").string() + " -o " + out.string());
  REQUIRE(r.status == 0);
  CHECK(r.out.find("static       2 events (1 tangent) against 1 polygons") != std::string::npos);
  const ccd::TruthFile t = ccd::load_truth(out.string());
  CHECK(t.has_scenery);
  REQUIRE(t.static_events.size() == 2);
  CHECK(t.static_events[0] == ccd::StaticEvent{0, 0, 1.0, 3.0});
  CHECK(t.static_events[1].body == 2);
  CHECK(t.static_events[1].enter == t.static_events[1].exit);
  CHECK(t.static_events[1].enter == Approx(2.0).margin(1e-7));
  CHECK(t.scene_sha256 == ccd::scene_digest(ccd::load_scene((tmp / "s.json").string())));

  s["scenery"][0]["polygon"][2] = {4, 4, 0.5};
  write(tmp / "bad.json", s.dump());
  const fs::path bad_out = tmp / "bad_t.json";
  const Run b = run(tmp, (tmp / "bad.json").string() + " -o " + bad_out.string());
  CHECK(b.status == 2);
  CHECK(b.err.find("bad.json: scenery[0].polygon[") != std::string::npos);
  CHECK(b.err.find("not planar") != std::string::npos);
  CHECK(std::count(b.err.begin(), b.err.end(), '\n') == 1);
  CHECK_FALSE(fs::exists(bad_out));
}

}  // namespace cli_truth_command_test
