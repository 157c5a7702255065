// Hostile input, round two, end to end: work that every command refuses up front with its
// estimate (and --force overrides), outputs that are never lost or half written (side-files
// with their results, file names that are not UTF-8, a full disk), and signals. Each
// reproducer of the issue is the first SECTION of its TEST_CASE. Faults (SIGKILL at random
// points, a full disk for every command, concurrent writers) are in hostile_faults_test.cpp.
#include "cli_support.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <csignal>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace cli_hostile_outputs_test {

namespace fs = std::filesystem;
using nlohmann::json;
using ccdlab::test::Folder;
using ccdlab::test::slurp;

namespace {

struct Run {
  int status;
  std::string out, err;
};

// `ccdlab ARGS`, after the shell commands `prefix` (e.g. a ulimit).
Run cli(const Folder& dir, const std::string& args, const std::string& prefix = "") {
  Run r{};
  if (prefix.empty()) {
    r.status = ccdlab::test::run_ccdlab(args, dir, &r.out, &r.err);
    return r;
  }
  const std::string cmd = prefix + std::string(CCDLAB_BINARY) + " " + args + " >" + (dir / "stdout.txt") + " 2>" +
                          (dir / "stderr.txt");
  const int raw = std::system(("sh -c '" + cmd + "'").c_str());
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(dir / "stdout.txt");
  r.err = slurp(dir / "stderr.txt");
  return r;
}

std::string write(const Folder& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name, std::ios::binary) << text;
  return dir / name;
}

bool one_line(const std::string& s) { return !s.empty() && s.find('\n') == s.size() - 1; }

int temporaries(const fs::path& folder) {
  int n = 0;
  for (const auto& f : fs::recursive_directory_iterator(folder))
    n += f.path().filename().string().find(".tmp.") != std::string::npos;
  return n;
}

const json kBox = {{"name", "crate"}, {"kind", "box"}, {"half_extents", {0.5, 0.3, 0.2}}};

// n boxes at one point, each spinning about its own axis (fixed seed).
json spinning_pile(int n) {
  json bodies = json::array();
  for (int i = 0; i < n; ++i)
    bodies.push_back({{"shape", "crate"},
                      {"position", {0, 0, 0}},
                      {"angular_velocity", {std::sin(i) * 5, std::cos(i * 1.7) * 5, std::sin(i * 0.3 + 1) * 5}}});
  return {{"format", "ccdlab-scene/2"}, {"horizon", 1.0}, {"shapes", {kBox}}, {"bodies", bodies}};
}

json two_spheres() {
  return {{"format", "ccdlab-scene/1"},
          {"horizon", 1.0},
          {"bodies",
           {{{"radius", 0.5}, {"position", {0, 0, 0}}, {"velocity", {1, 0, 0}}},
            {{"radius", 0.5}, {"position", {5, 0, 0}}, {"velocity", {-1, 0, 0}}}}}};
}

json experiment(const std::string& scene, const json& methods = {"aabb/grid"}) {
  return {{"format", "ccdlab-experiment/1"}, {"scene", scene}, {"dt", {0.1}}, {"methods", methods}};
}

}  // namespace

TEST_CASE("every command estimates its work up front and refuses absurd work without --force",
          "[hostile][cli][estimate]") {
  Folder dir;
  const std::string out = dir / "out.json";
  SECTION("view: a free spin at 1e30 rad/s with 200 angular-velocity changes") {
    json changes = json::array();
    for (int k = 0; k < 200; ++k)
      changes.push_back({{"t", (k + 1) / 202.0}, {"angular_velocity", {k % 2 ? 1e30 : -1e30, 1e29, 0}}});
    const json s = {{"format", "ccdlab-scene/2"},
                    {"horizon", 1.0},
                    {"shapes", {kBox}},
                    {"bodies",
                     {{{"shape", "crate"},
                       {"position", {0, 0, 0}},
                       {"spin", "free"},
                       {"angular_velocity", {1e30, 1e29, 0}},
                       {"angular_velocity_changes", changes}}}}};
    const std::string scene = write(dir, "spin.json", s.dump());
    const auto start = std::chrono::steady_clock::now();
    const Run r = cli(dir, "view " + scene + " -o " + (dir / "v.html"));
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(20));
    CHECK(r.status == 2);
    CHECK(one_line(r.err));
    CHECK(r.err.find("ccdlab view: " + scene + ": bodies: needs 2.01e+07 page entries") == 0);
    CHECK(r.err.find("above the limit 5e+06 without --force") != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "v.html"));
#ifndef CCDLAB_SANITIZED  // the sanitizers' allocator aborts instead of throwing std::bad_alloc
    // Forced under a 1 GB address space: one line, exit 1, not an abort.
    const Run f = cli(dir, "view " + scene + " --force -o " + (dir / "v.html"), "ulimit -v 1000000; ");
    CHECK(f.status == 1);
    CHECK(f.err == "ccdlab view: out of memory building the page of " + scene + "\n");
    CHECK_FALSE(fs::exists(dir / "v.html"));
#endif
  }
  SECTION("truth and run of 1,000 spinning boxes piled at one point") {
    const std::string scene = write(dir, "pile.json", spinning_pile(1000).dump());
    Run r = cli(dir, "truth " + scene + " -o " + out);
    CHECK(r.status == 2);
    CHECK(one_line(r.err));
    CHECK(r.err.find("ccdlab truth: " + scene + ": bodies: needs ") == 0);
    CHECK(r.err.find("certified pair tests (1000 bodies with shapes") != std::string::npos);
    CHECK(r.err.find("above the limit 1e+09 without --force") != std::string::npos);
    // aabb/brute on the same pile, the truth given or not.
    const std::string e = write(dir, "e.json", experiment(scene, {"aabb/brute"}).dump());
    r = cli(dir, "run " + e + " -o " + out);
    CHECK(r.status == 2);
    CHECK(r.err.find("ccdlab run: " + e + ": scene: needs ") == 0);
    CHECK(r.err.find("certified pair tests") != std::string::npos);
    // Two of the boxes, apart, pass. (Two at one point pass the estimate too, but their truth
    // certifies the overlap instant by instant until its evaluation budget runs out: a second
    // in Release, minutes under the sanitizers.)
    json two = spinning_pile(2);
    two["bodies"][1]["position"] = {4, 0, 0};
    r = cli(dir, "truth " + write(dir, "pile2.json", two.dump()) + " --quiet -o " + out);
    CHECK(r.status == 0);
    fs::remove(out);
  }
  SECTION("two 20,000-point hulls spinning against each other") {
    json points = json::array();
    for (int i = 0; i < 20000; ++i) {  // a Fibonacci sphere
      const double z = 1.0 - 2.0 * (i + 0.5) / 20000, r = std::sqrt(1.0 - z * z), a = 2.399963229728653 * i;
      points.push_back({r * std::cos(a), r * std::sin(a), z});
    }
    const json s = {{"format", "ccdlab-scene/2"},
                    {"horizon", 1.0},
                    {"shapes", {{{"name", "h"}, {"kind", "hull"}, {"points", points}}}},
                    {"bodies",
                     {{{"shape", "h"}, {"position", {0, 0, 0}}, {"angular_velocity", {0, 0, 5}}},
                      {{"shape", "h"}, {"position", {1.5, 0, 0}}, {"angular_velocity", {5, 0, 0}}}}}};
    const std::string scene = write(dir, "hulls.json", s.dump());
    const Run r = cli(dir, "truth " + scene + " -o " + out);
    CHECK(r.status == 2);
    CHECK(r.err.find("certified pair tests (2 bodies with shapes") != std::string::npos);
  }
  SECTION("cloth, cloth frames and cloth queries of a 1000 x 1000 grid for 10^6 steps") {
    const std::string scene = write(dir, "big.json", R"({"format": "ccdlab-cloth/1",
      "grid": {"nx": 1000, "ny": 1000, "origin": [0, 0, 0], "du": [0.01, 0, 0], "dv": [0, 0, 0.01]},
      "particle_mass": 0.1, "springs": {"structural": {"stiffness": 10, "damping": 0},
      "shear": {"stiffness": 1, "damping": 0}, "bend": {"stiffness": 1, "damping": 0}},
      "thickness": 0, "step": 0.01, "steps": 1000000})");
    for (const std::string& cmd : {"cloth " + scene + " -o " + out, "cloth frames " + scene + " -o " + (dir / "F"),
                                   "cloth queries " + scene + " --steps 0:1 -o " + (dir / "Q"),
                                   std::string("cloth drape --n 1000 --steps 1000000 -o ") + out}) {
      INFO(cmd);
#ifdef CCDLAB_SANITIZED  // AddressSanitizer reserves terabytes of shadow: no address-space limit there
      const Run r = cli(dir, cmd);
#else  // the refusal comes before any allocation for the grid: 4 GB is far below what it would take
      const Run r = cli(dir, cmd, "ulimit -v 4000000; ");
#endif
      CHECK(r.status == 2);
      CHECK(one_line(r.err));
      CHECK(r.err.find("needs 1e+12 particle-steps (1000 x 1000 particles, 1000000 steps), above the limit 1e+09 "
                       "without --force") != std::string::npos);
    }
    CHECK_FALSE(fs::exists(dir / "F"));
    CHECK_FALSE(fs::exists(dir / "Q"));
  }
  SECTION("run of a cloth experiment of a 1000 x 1000 grid for 10^6 steps, and of too many jobs") {
    const std::string e = write(dir, "big.json", R"({"format": "ccdlab-cloth-experiment/1", "name": "big",
      "scene": "drape", "n": 1000, "steps": 1000000, "k": [1]})");
#ifdef CCDLAB_SANITIZED  // AddressSanitizer reserves terabytes of shadow: no address-space limit there
    Run r = cli(dir, "run " + e + " -o " + out);
#else  // refused before the grid is simulated: 4 GB is far below what it would take
    Run r = cli(dir, "run " + e + " -o " + out, "ulimit -v 4000000; ");
#endif
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab run: " + e + ": steps: needs 1e+12 particle-steps (1000 x 1000 particles, 1000000 "
                   "steps), above the limit 1e+09 without --force\n");
    // A small run repeated 1000 times over 2 cullers x 2 modes x 5 k: 4.1e+10 particle-steps of checks.
    const std::string jobs = write(dir, "jobs.json", R"({"format": "ccdlab-cloth-experiment/1", "name": "jobs",
      "scene": "drape", "n": 64, "steps": 500, "k": [1, 2, 4, 8, 16], "cullers": ["bvh", "bvh_cones"],
      "repeats": 1000})");
    r = cli(dir, "run " + jobs + " -o " + out);
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab run: " + jobs + ": repeats: needs 4.1e+10 particle-steps of checks (64 x 64 particles, "
                   "500 steps, 20 jobs x 1000 repeats), above the limit 1e+10 without --force\n");
    CHECK_FALSE(fs::exists(out));
    CHECK_FALSE(fs::exists(dir / "cloth-truth"));
  }
  SECTION("mesh-frames of a 1000 x 1000 run at step 10^6, and of 5e7 generated faces") {
    Run r = cli(dir, "mesh-frames drape --n 1000 --step 1000000 -o " + (dir / "F"));
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab mesh-frames: drape: --step: needs 1e+12 particle-steps (1000 x 1000 particles, 1000001 "
                   "steps), above the limit 1e+09 without --force\n");
    r = cli(dir, "mesh-frames tori --faces 50000000 -o " + (dir / "F"));
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab mesh-frames: tori: --faces: needs 5e+07 faces (--faces 50000000), above the limit 1e+07 "
                   "without --force\n");
    CHECK_FALSE(fs::exists(dir / "F"));
  }
  SECTION("view of a huge cloth frames file, and of frames past the page's entries") {
    // 2e8 bytes (sparse: no disk is used): refused by its size before a byte is read.
    const std::string huge = write(dir, "huge.json", "");
    fs::resize_file(huge, 200000000);
    Run r = cli(dir, "view " + huge + " -o " + (dir / "v.html"));
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab view: " + huge + ": needs 2e+08 bytes of input (the file's size), above the limit 1e+08 "
                   "without --force\n");
    // 6 frames of 1000 x 1000 particles: 6e6 positions, refused before any is read.
    json frames = {{"format", "ccdlab-cloth-frames/1"}, {"nx", 1000}, {"ny", 1000}, {"triangles", json::array()},
                   {"frames", json::array()}};
    for (int k = 0; k < 6; ++k) frames["frames"].push_back({{"t", k}, {"x", json::array()}});
    const std::string many = write(dir, "many.json", frames.dump());
    r = cli(dir, "view " + many + " -o " + (dir / "v.html"));
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab view: " + many + ": frames: needs 6e+06 page entries (6 frames of 1000 x 1000 particles), "
                   "above the limit 5e+06 without --force\n");
    // Forced, the frames are read (and these are bad: their positions are missing).
    r = cli(dir, "view " + many + " --force -o " + (dir / "v.html"));
    CHECK(r.status == 2);
    CHECK(r.err.find("frames[0].x: must hold 3 nx ny = 3000000 coordinates") != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "v.html"));
  }
  SECTION("ccd of /dev/zero and of a folder; import of a folder") {
    Run r = cli(dir, "ccd /dev/zero --kind vf -o " + out);
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab ccd: /dev/zero: is not a regular file (a device or a pipe); give a file\n");
    r = cli(dir, "ccd " + dir.path.string() + " --kind vf");
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab ccd: " + dir.path.string() + ": is a folder; give a file\n");
    r = cli(dir, "import " + dir.path.string() + " --radius 1 -o " + out);
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab import: " + dir.path.string() + ": is a folder; give a file\n");
  }
  SECTION("import --shapes {\"shapes\": 5}") {
    const std::string csv = write(dir, "f.csv", "body,t,x,y,z,shape\n0,0,0,0,0,box:1,1,1\n0,1,1,0,0,box:1,1,1\n");
    const std::string shapes = write(dir, "shapes.json", R"({"shapes": 5})");
    const Run r = cli(dir, "import " + csv + " --shapes " + shapes + " -o " + out);
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab import: " + shapes + ": shapes: must be an array of shape objects (docs/formats.md)\n");
  }
  SECTION("import of 100,000 bodies with distinct inline shapes is linear") {
    std::string csv = "body,t,x,y,z,shape\n";
    char line[128];
    for (int i = 0; i < 100000; ++i)
      for (int t = 0; t < 2; ++t) {
        std::snprintf(line, sizeof line, "%d,%d,%d,0,0,sphere:%.6f\n", i, t, 3 * i + t, 0.5 + i * 1e-6);
        csv += line;
      }
    const std::string file = write(dir, "many.csv", csv);
    const auto start = std::chrono::steady_clock::now();
    const Run r = cli(dir, "import " + file + " -o " + out);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(r.status == 0);
    // Quadratic look-ups took minutes; linear ones take about a second (more under sanitizers).
    CHECK(seconds < 60.0);
    CHECK(json::parse(slurp(out))["shapes"].size() == 100000);
    fs::remove(out);
  }
  SECTION("poses past 1e7 rows: refused with the estimate, --force writes them") {
    const std::string scene = write(dir, "s.json", two_spheres().dump());
    Run r = cli(dir, "poses " + scene + " --times 0:1:1e-7 -o " + out);
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab poses: " + scene +
                       ": --times: needs 2e+07 rows (1e+07 times x 2 bodies), above the limit 1e+07 without --force\n");
  }
  CHECK_FALSE(fs::exists(out));
  CHECK(temporaries(dir.path) == 0);
}

TEST_CASE("the summary side-file is checked against every input before the work and written with the results",
          "[hostile][cli][outputs]") {
  Folder dir;
  const std::string scene = write(dir, "r.summary.md", two_spheres().dump());  // the scene has the side-file's name
  const std::string scene_text = slurp(scene);
  SECTION("run -o r.json where r.summary.md is the scene, the experiment or the --truth file") {
    const std::string e = write(dir, "e.json", experiment("r.summary.md").dump());
    Run r = cli(dir, "run " + e + " -o " + (dir / "r.json"));
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab run: " + (dir / "r.summary.md") + ": is an input of this command (" + scene +
                       "); choose another output file\n");
    CHECK(slurp(scene) == scene_text);
    CHECK_FALSE(fs::exists(dir / "r.json"));
    // The experiment itself: e.json's side-file is e.summary.md.
    const std::string s2 = write(dir, "s.json", two_spheres().dump());
    const std::string e2 = write(dir, "x.summary.md", experiment(s2).dump());
    r = cli(dir, "run " + e2 + " -o " + (dir / "x.json"));
    CHECK(r.status == 2);
    CHECK(r.err.find("is an input of this command") != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "x.json"));
    // The --truth file.
    REQUIRE(cli(dir, "truth " + s2 + " -o " + (dir / "t.summary.md")).status == 0);
    const std::string truth_text = slurp(dir / "t.summary.md");
    r = cli(dir, "run " + write(dir, "e3.json", experiment(s2).dump()) + " --truth " + (dir / "t.summary.md") +
                        " -o " + (dir / "t.json"));
    CHECK(r.status == 2);
    CHECK(r.err.find("is an input of this command") != std::string::npos);
    CHECK(slurp(dir / "t.summary.md") == truth_text);
    CHECK_FALSE(fs::exists(dir / "t.json"));
  }
  SECTION("merge with a shard named m.summary.md") {
    const std::string s2 = write(dir, "s.json", two_spheres().dump());
    const std::string e = write(dir, "e.json", experiment(s2).dump());
    REQUIRE(cli(dir, "run " + e + " --quiet -o " + (dir / "m.summary.md")).status == 0);
    const std::string shard = slurp(dir / "m.summary.md");
    const Run r = cli(dir, "merge " + (dir / "m.summary.md") + " -o " + (dir / "m.json"));
    CHECK(r.status == 2);
    CHECK(r.err.find("is an input of this command") != std::string::npos);
    CHECK(slurp(dir / "m.summary.md") == shard);
    CHECK_FALSE(fs::exists(dir / "m.json"));
  }
  SECTION("a folder named like the side-file: refused before the run, no results left behind") {
    const std::string s2 = write(dir, "s.json", two_spheres().dump());
    fs::create_directory(dir / "f.summary.md");
    const Run r = cli(dir, "run " + write(dir, "e.json", experiment(s2).dump()) + " -o " + (dir / "f.json"));
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab run: " + (dir / "f.summary.md") + ": is a folder; the output must be a file\n");
    CHECK_FALSE(fs::exists(dir / "f.json"));
  }
  CHECK(temporaries(dir.path) == 0);
}

TEST_CASE("file names that are not UTF-8 are stored escaped", "[hostile][cli][outputs]") {
  Folder dir;
  fs::create_directory(dir / "d\xff");
  const std::string scene = write(dir, "d\xff/t\xff.json", two_spheres().dump());
  SECTION("run: an experiment in folder d\\xff/ with its scene beside it") {
    write(dir, "d\xff/t.json", two_spheres().dump());
    const std::string e = write(dir, "d\xff/e.json", experiment("t.json").dump());  // JSON itself is UTF-8
    const Run r = cli(dir, "run " + e + " --quiet -o " + (dir / "d\xff/r\xff.json"));
    REQUIRE(r.status == 0);
    const json results = json::parse(slurp(dir / "d\xff/r\xff.json"));
    CHECK(results["experiment"]["scene"] == dir / "d\\xFF/t.json");
    CHECK(results["scene"]["source"] == dir / "d\\xFF/t.json");
    CHECK(fs::exists(dir / "d\xff/r\xff.summary.md"));
  }
  SECTION("view of t\\xff.json") {
    const Run r = cli(dir, "view " + scene + " -o " + (dir / "d\xff/v.html"));
    REQUIRE(r.status == 0);
    CHECK(slurp(dir / "d\xff/v.html").find("t\\\\xFF.json") != std::string::npos);
  }
  SECTION("ccd of q\\xff.csv") {
    REQUIRE(cli(dir, "ccd --write-hard --kind vf -o " + (dir / "d\xff/q\xff.csv")).status == 0);
    const Run r = cli(dir, "ccd " + (dir / "d\xff/q\xff.csv") + " --kind vf -o " + (dir / "c.json"));
    REQUIRE(r.status == 0);
    CHECK(json::parse(slurp(dir / "c.json"))["file"] == dir / "d\\xFF/q\\xFF.csv");
  }
  SECTION("cloth and cloth frames of c\\xff.json") {
    const std::string cloth = write(dir, "d\xff/c\xff.json", R"({"format": "ccdlab-cloth/1",
      "grid": {"nx": 3, "ny": 3, "origin": [0, 0, 0], "du": [0.5, 0, 0], "dv": [0, 0, 0.5]},
      "particle_mass": 0.1, "springs": {"structural": {"stiffness": 10, "damping": 0},
      "shear": {"stiffness": 1, "damping": 0}, "bend": {"stiffness": 1, "damping": 0}},
      "thickness": 0, "step": 0.01, "steps": 2})");
    REQUIRE(cli(dir, "cloth " + cloth + " -o " + (dir / "d\xff/f.json")).status == 0);
    CHECK(json::parse(slurp(dir / "d\xff/f.json"))["scene"] == dir / "d\\xFF/c\\xFF.json");
    REQUIRE(cli(dir, "cloth frames " + cloth + " -o " + (dir / "d\xff/F")).status == 0);
    CHECK(json::parse(slurp(dir / "d\xff/F/cloth.json"))["scene"] == dir / "d\\xFF/c\\xFF.json");
  }
  CHECK(temporaries(dir.path) == 0);
}

TEST_CASE("run --truth checks every index of the truth's events against the scene", "[hostile][cli]") {
  Folder dir;
  json s = two_spheres();
  s["format"] = "ccdlab-scene/2";
  s["scenery"] = {{{"polygon", {{-10, -2, -10}, {10, -2, -10}, {10, -2, 10}}}}};
  const std::string scene = write(dir, "s.json", s.dump());
  REQUIRE(cli(dir, "truth " + scene + " -o " + (dir / "t.json")).status == 0);
  json truth = json::parse(slurp(dir / "t.json"));
  REQUIRE(truth.contains("static_events"));
  const std::string e = write(dir, "e.json", experiment(scene).dump());
  for (const char* field : {"body", "polygon"}) {
    json bad = truth;
    bad["static_events"] = {{{"body", 0}, {"polygon", 0}, {"enter", 0.25}, {"exit", 0.5}}};
    bad["static_events"][0][field] = 999;
    const std::string file = write(dir, "bad.json", bad.dump());
    const Run r = cli(dir, "run " + e + " --truth " + file + " -o " + (dir / "r.json"));
    INFO(field);
    CHECK(r.status == 2);
    CHECK(r.err.find(file + ": static_events[0]." + field + ": " + field + " 999 does not exist") !=
          std::string::npos);
    CHECK_FALSE(fs::exists(dir / "r.json"));
  }
}

TEST_CASE("SIGTERM and SIGINT stop a command within a second, writing nothing", "[hostile][cli][signals]") {
  Folder dir;
  // A rigid truth of minutes: 40 spinning boxes piled at one point, forced.
  const std::string scene = write(dir, "pile.json", spinning_pile(40).dump());
  const std::string e = write(dir, "e.json", experiment(scene, {"aabb/grid"}).dump());
  struct Case {
    std::string args, output;
  };
  for (const Case& c : {Case{"run " + e + " --force --quiet --threads 1 -o " + (dir / "r.json"), dir / "r.json"},
                        Case{"truth " + scene + " --force --threads 1 -o " + (dir / "t.json"), dir / "t.json"}}) {
    for (const int sig : {SIGTERM, SIGINT}) {
      INFO(c.args << " signal " << sig);
      // Started as a foreground child (a shell's background job would ignore SIGINT).
      const std::string cmd = "exec " + std::string(CCDLAB_BINARY) + " " + c.args + " 2>/dev/null";
      const pid_t pid = ::fork();
      REQUIRE(pid >= 0);
      if (pid == 0) {
        ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
      }
      // Once its temporary output exists it is working; 0.3 s later the signal.
      auto working = [&] {
        for (const auto& f : fs::directory_iterator(dir.path))
          if (f.path().string().rfind(c.output + ".tmp.", 0) == 0) return true;
        return false;
      };
      for (int k = 0; k < 3000 && !working(); ++k) ::usleep(10000);
      ::usleep(300000);
      const auto start = std::chrono::steady_clock::now();
      ::kill(pid, sig);
      int raw = 0;
      ::waitpid(pid, &raw, 0);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      CHECK(seconds < 1.5);
      // run: its own message and status 130; truth: ended by the signal itself.
      CHECK(((WIFEXITED(raw) && WEXITSTATUS(raw) == 130) || (WIFSIGNALED(raw) && WTERMSIG(raw) == sig)));
      CHECK_FALSE(fs::exists(c.output));
      CHECK(temporaries(dir.path) == 0);
    }
  }
}

}  // namespace cli_hostile_outputs_test
