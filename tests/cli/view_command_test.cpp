// `ccdlab view`: the data the page is given (experiments/view_data.hpp), the page assembly
// (experiments/view_page.hpp) and the command's input checks. The page itself is tested in a
// browser by tests/viewer/browser_test.py (CTest viewer.browser).
#include "cli_support.hpp"

#include "../../experiments/view_data.hpp"
#include "../../experiments/view_page.hpp"

#include <ccd/motion/rotation.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_io.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>

namespace cli_view_command_test {

using nlohmann::json;
using ccdlab::test::Folder;
using ccdlab::test::run_ccdlab;
using ccdlab::test::slurp;

namespace {

// Two balls through each other between the samples of dt = 0.5: contact over
// [0.2, 0.3] (centres 5 apart, closing at 20 m/s, radii 0.5 each); a third bounces on
// walls and falls under gravity (several pieces).
json tunnel_scene() {
  return json::parse(R"({"format": "ccdlab-scene/1", "horizon": 1.0, "gravity": [0, -2, 0],
    "box": {"min": [-10, -10, -10], "max": [10, 10, 10]},
    "bodies": [{"radius": 0.5, "position": [0, 0, 0], "velocity": [10, 1, 0]},
               {"radius": 0.5, "position": [5, 0, 0], "velocity": [-10, 1, 0]},
               {"radius": 0.25, "position": [8, 5, 0], "velocity": [40, 0, 3]}]})");
}

void write(const std::string& path, const json& j) { std::ofstream(path) << j.dump(1); }

// p + v s + a s^2 / 2 on the exported piece of `body` that holds t (as the page does).
ccd::Vec3 page_position(const json& data, std::size_t body, double t) {
  const json& arr = data["bodies"]["pieces"][body];
  std::size_t k = 0;
  while ((k + 1) * 11 < arr.size() && arr[(k + 1) * 11].get<double>() <= t) ++k;
  const std::size_t o = k * 11;
  const double s = t - arr[o].get<double>();
  ccd::Vec3 p;
  for (int d = 0; d < 3; ++d)
    p[d] = arr[o + 2 + d].get<double>() + arr[o + 5 + d].get<double>() * s + arr[o + 8 + d].get<double>() * 0.5 * s * s;
  return p;
}

}  // namespace

TEST_CASE("view data: the page's pieces reproduce the exact trajectories", "[view]") {
  const ccd::Scene scene = ccd::scene_from_json(tunnel_scene(), "scene.json");
  const ccd::Trajectories traj(scene);
  ccdlab::ViewInputs in;
  in.scene_file = "scene.json";
  const json data = ccdlab::body_view_data(scene, in);
  CHECK(data["format"] == "ccdlab-view/1");
  CHECK(data["bodies"]["count"] == 3);
  CHECK(data["bodies"]["rotations"].empty());  // spheres: no orientation to draw
  CHECK(data["truth"].is_null());
  CHECK(data["runs"].empty());
  // Body 2 reflects at the +x wall (x = 9.75 at t = 0.04375) and falls: several pieces.
  REQUIRE(traj.pieces(2).size() >= 2);
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(data["bodies"]["pieces"][i].size() == 11 * traj.pieces(i).size());
    for (double t : {0.0, 0.04375, 0.1, 0.25, 0.5, 0.75, 1.0}) {
      // 9 significant digits per number: within 1e-7 of the scene's size.
      const ccd::Vec3 d = page_position(data, i, t) - traj.position(i, t);
      CHECK(d.norm() < 1e-7 * 10.0);
    }
  }
}

TEST_CASE("view data: spinning shapes carry their rotation pieces", "[view]") {
  const ccd::Scene scene = ccd::load_scene(std::string(CCDLAB_SOURCE_DIR) + "/data/scenes/rigid-example.json");
  const ccd::Rotations rot(scene);
  ccdlab::ViewInputs in;
  in.scene_file = "rigid-example.json";
  const json data = ccdlab::body_view_data(scene, in);
  REQUIRE(data["shapes"].size() == scene.shapes.size());
  CHECK(data["shapes"][0]["kind"] == "capsule");
  CHECK(data["shapes"][2]["points"].size() == 4);
  REQUIRE(data["bodies"]["rotations"].size() == scene.bodies.size());
  // Body 0 changes its spin at t = 1: two rotation pieces of 9 numbers.
  CHECK(data["bodies"]["rotations"][0].size() == 9 * rot.pieces(0).size());
  CHECK(rot.pieces(0).size() == 2);
  CHECK(data["bodies"]["shape"][1] == -1);  // the plain ball
}

TEST_CASE("view page: one file, every marker filled, no early end of a script", "[view]") {
  json data{{"format", "ccdlab-view/1"}, {"scene_file", "odd</script><b>name"}};
  const std::string page = ccdlab::view_page(data);
  CHECK(page.find("@CCDLAB_") == std::string::npos);
  CHECK(page.find("REVISION") != std::string::npos);        // three.js itself
  CHECK(page.find("OrbitControls") != std::string::npos);
  CHECK(page.find("data-missed") != std::string::npos);     // the page's script
  CHECK(page.find("odd\\u003c/script\\u003e\\u003cb\\u003ename") != std::string::npos);
  CHECK(page.find("odd</script>") == std::string::npos);
}

TEST_CASE("view page: JSON in the script element escapes what the HTML parser or JavaScript reads", "[view]") {
  // "<!--<script>" alone (no "</script>") sends the HTML parser into its script-data escape
  // states, where the element's real end tag no longer ends it: the page stays 'loading'.
  CHECK(ccdlab::json_for_script(json("a</b")) == "\"a\\u003c/b\"");
  CHECK(ccdlab::json_for_script(json("<!--<script>")) == "\"\\u003c!--\\u003cscript\\u003e\"");
  CHECK(ccdlab::json_for_script(json("<img src=x onerror=f()>&amp;")) ==
        "\"\\u003cimg src=x onerror=f()\\u003e\\u0026amp;\"");
  // U+2028 and U+2029 (line terminators in older JavaScript), as escapes; other UTF-8 as is.
  CHECK(ccdlab::json_for_script(json("x\u2028y\u2029z\u00e9\u20ac")) == "\"x\\u2028y\\u2029z\u00e9\u20ac\"");
  // The same value: the escapes parse back to the original strings, keys included.
  const json nested{{"k<>&\u2028", {"</script>", "<!--", 1.5, nullptr}}};
  const std::string text = ccdlab::json_for_script(nested);
  CHECK(text.find_first_of("<>&") == std::string::npos);
  CHECK(text.find("\u2028") == std::string::npos);
  CHECK(json::parse(text) == nested);
}

TEST_CASE("ccdlab view: writes the page with the results' missed contacts", "[view][cli]") {
  Folder dir;
  write(dir / "scene.json", tunnel_scene());
  write(dir / "exp.json", json::parse(R"({"format": "ccdlab-experiment/1", "scene": "scene.json",
    "dt": [0.5, 0.01], "methods": ["aabb/sap"], "list_missed": true})"));
  REQUIRE(run_ccdlab("truth " + dir / "scene.json" + " -o " + dir / "truth.json --quiet", dir) == 0);
  REQUIRE(run_ccdlab("run " + dir / "exp.json" + " -o " + dir / "results.json --quiet", dir) == 0);
  std::string out, err;
  REQUIRE(run_ccdlab("view " + dir / "scene.json" + " --results " + dir / "results.json" + " --truth " +
                         dir / "truth.json" + " -o " + dir / "view.html",
                     dir, &out, &err) == 0);
  const std::string page = slurp(dir / "view.html");
  const std::size_t start = page.find("id=\"ccdlab-data\">");
  REQUIRE(start != std::string::npos);
  const std::size_t from = start + std::string("id=\"ccdlab-data\">").size();
  const json data = json::parse(page.substr(from, page.find("</script>", from) - from));
  REQUIRE(data["runs"].size() == 2);
  // dt = 0.5 misses the one contact; dt = 0.01 sees it.
  const json& coarse = data["runs"][0]["dt"] == 0.5 ? data["runs"][0] : data["runs"][1];
  REQUIRE(coarse["missed_events"].size() == 1);
  CHECK(coarse["missed_events"][0]["a"] == 0);
  CHECK(coarse["missed_events"][0]["b"] == 1);
  CHECK(std::abs(coarse["missed_events"][0]["enter"].get<double>() - 0.2) < 1e-12);
  CHECK(std::abs(coarse["missed_events"][0]["exit"].get<double>() - 0.3) < 1e-12);
  REQUIRE(data["truth"].size() == 1);
  CHECK(data["truth"][0][0] == 0);
  CHECK(data["truth"][0][1] == 1);
}

TEST_CASE("ccdlab view: bad input exits 2 naming the file and the field, writes nothing", "[view][cli]") {
  Folder dir;
  write(dir / "scene.json", tunnel_scene());
  json other = tunnel_scene();
  other["bodies"][2]["radius"] = 0.3;
  write(dir / "other.json", other);
  write(dir / "exp.json", json::parse(R"({"format": "ccdlab-experiment/1", "scene": "other.json",
    "dt": [0.5], "methods": ["aabb/sap"], "list_missed": true})"));
  REQUIRE(run_ccdlab("run " + dir / "exp.json" + " -o " + dir / "other-results.json --quiet", dir) == 0);
  REQUIRE(run_ccdlab("truth " + dir / "other.json" + " -o " + dir / "other-truth.json --quiet", dir) == 0);
  const std::string page = dir / "view.html";
  std::string err;
  auto view = [&](const std::string& args) {
    err.clear();
    return run_ccdlab("view " + args + " -o " + page, dir, nullptr, &err);
  };

  SECTION("results of another scene") {
    CHECK(view(dir / "scene.json" + " --results " + dir / "other-results.json") == 2);
    CHECK(err.find("other-results.json: truth.scene_sha256") != std::string::npos);
  }
  SECTION("truth of another scene") {
    CHECK(view(dir / "scene.json" + " --truth " + dir / "other-truth.json") == 2);
    CHECK(err.find("other-truth.json: scene_sha256") != std::string::npos);
  }
  SECTION("a missed contact naming a body the scene does not have") {
    json r = json::parse(slurp(dir / "other-results.json"));
    r["records"][0]["missed_events"] = json::array({{{"a", 1}, {"b", 3}, {"enter", 0.2}, {"exit", 0.3}}});
    write(dir / "bad-results.json", r);
    CHECK(view(dir / "other.json" + " --results " + dir / "bad-results.json") == 2);
    CHECK(err.find("bad-results.json: records[0].missed_events[0].b: must be a body of the scene") != std::string::npos);
  }
  SECTION("a missed contact with a > b") {
    json r = json::parse(slurp(dir / "other-results.json"));
    r["records"][0]["missed_events"] = json::array({{{"a", 2}, {"b", 1}, {"enter", 0.2}, {"exit", 0.3}}});
    write(dir / "bad-results.json", r);
    CHECK(view(dir / "other.json" + " --results " + dir / "bad-results.json") == 2);
    CHECK(err.find("records[0].missed_events[0].b: must be greater than a") != std::string::npos);
  }
  SECTION("a results file that is not one") {
    write(dir / "bad-results.json", json{{"format", "ccdlab-results/2"}});
    CHECK(view(dir / "scene.json" + " --results " + dir / "bad-results.json") == 2);
    CHECK(err.find("bad-results.json: experiment: missing required field") != std::string::npos);
  }
  SECTION("a bad scene") {
    json s = tunnel_scene();
    s["bodies"][1]["radius"] = -1;
    write(dir / "bad.json", s);
    CHECK(view(dir / "bad.json") == 2);
    CHECK(err.find("bad.json: bodies[1].radius") != std::string::npos);
  }
  SECTION("a cloth scene: its frames are what the page shows") {
    write(dir / "cloth.json", json{{"format", "ccdlab-cloth/1"}});
    CHECK(view(dir / "cloth.json") == 2);
    CHECK(err.find("cloth.json: format: a cloth scene is shown from its frames") != std::string::npos);
  }
  SECTION("cloth frames with a triangle out of range") {
    write(dir / "frames.json", json::parse(R"({"format": "ccdlab-cloth-frames/1", "nx": 2, "ny": 2,
      "triangles": [[0, 1, 4]], "frames": [{"t": 0, "x": [0,0,0, 1,0,0, 0,1,0, 1,1,0]}]})"));
    CHECK(view(dir / "frames.json") == 2);
    CHECK(err.find("frames.json: triangles[0][2]: must be below nx * ny = 4") != std::string::npos);
  }
  SECTION("usage") {
    CHECK(run_ccdlab("view " + dir / "scene.json", dir, nullptr, &err) == 2);
    CHECK(err.find("missing -o") != std::string::npos);
    CHECK(view(dir / "scene.json --colour red") == 2);
    CHECK(view(dir / "scene.json" + " -o " + dir / "scene.json") == 2);  // -o given twice
  }
  CHECK_FALSE(std::filesystem::exists(page));
  CHECK_FALSE(std::filesystem::exists(dir / "scene.json.tmp"));
}

TEST_CASE("ccdlab view: cloth frames become the page's mesh", "[view][cli]") {
  Folder dir;
  REQUIRE(run_ccdlab("cloth drape --n 4 --steps 4 --every 2 -o " + dir / "frames.json", dir) == 0);
  REQUIRE(run_ccdlab("view " + dir / "frames.json" + " -o " + dir / "view.html", dir) == 0);
  const std::string page = slurp(dir / "view.html");
  CHECK(page.find("\"kind\":\"cloth\"") != std::string::npos);
  CHECK(page.find("\"nx\":4") != std::string::npos);
}

}  // namespace cli_view_command_test
