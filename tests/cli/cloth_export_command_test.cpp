// `ccdlab cloth frames` and `ccdlab cloth queries`: the motion and the CCD queries of a
// small cloth run, written as folders. The queries are checked against the frames (every
// row is the exact rational of the double position of the listed vertex at the listed
// step), `ccdlab ccd` on them has zero false negatives against the exact 7th column, and
// bad input exits 2 with one line and writes nothing.
#include "cli_support.hpp"

#include <cloth/io/query_file.hpp>

#include <catch2/catch.hpp>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace cli_cloth_export_command_test {

namespace fs = std::filesystem;
using nlohmann::json;

using ccdlab::test::Folder;
using ccdlab::test::run_ccdlab;

namespace {

json read_json(const std::string& path) {
  std::ifstream in(path);
  return json::parse(in);
}

std::vector<double> read_positions(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
  std::vector<double> v(bytes.size() / sizeof(double));
  std::memcpy(v.data(), bytes.data(), v.size() * sizeof(double));
  REQUIRE(bytes.size() == v.size() * sizeof(double));
  return v;
}

}  // namespace

TEST_CASE("ccdlab cloth frames writes every state, the mesh and the springs", "[cloth][cli]") {
  Folder dir;
  REQUIRE(run_ccdlab("cloth frames pile --n 6 --steps 7 -o " + (dir / "m"), dir) == 0);
  const json m = read_json(dir / "m/cloth.json");
  CHECK(m["format"] == "ccdlab-cloth-motion/1");
  CHECK(m["particles"] == 36);
  CHECK(m["steps"] == 7);
  CHECK(m["times"].size() == 8);
  CHECK(m["triangles"].size() == 2 * 5 * 5);
  // structural 2*6*5, shear 2*5*5, bend 2*6*4
  CHECK(m["springs"]["a"].size() == 60 + 50 + 48);
  CHECK(m["springs"]["rest"].size() == m["springs"]["kind"].size());
  const std::vector<double> x = read_positions(dir / "m/positions.f64");
  REQUIRE(x.size() == 8 * 36 * 3);
  // The sheet falls: the last state differs from the first, and the first is the grid.
  CHECK(x[1] != x[7 * 36 * 3 + 1]);
  CHECK_FALSE(fs::exists(dir / "m.tmp." + std::to_string(::getpid())));
  // The folder is replaced by a second run; the digest names the motion.
  const std::string digest = m["digest"];
  REQUIRE(run_ccdlab("cloth frames pile --n 6 --steps 7 -o " + (dir / "m"), dir) == 0);
  CHECK(read_json(dir / "m/cloth.json")["digest"] == digest);
  REQUIRE(run_ccdlab("cloth frames pile --n 6 --steps 8 -o " + (dir / "m"), dir) == 0);
  CHECK(read_json(dir / "m/cloth.json")["digest"] != digest);
  // The Python reader gives the same positions.
  std::string out;
  REQUIRE(std::system(("/usr/bin/python3 " CCDLAB_SOURCE_DIR "/scripts/cloth_frames.py " + (dir / "m") +
                       " --state 8 --particle 35 > " + (dir / "py.txt"))
                          .c_str()) == 0);
  const std::vector<double> y = read_positions(dir / "m/positions.f64");
  std::ifstream py(dir / "py.txt");
  double px = 0, pyv = 0, pz = 0;
  py >> px >> pyv >> pz;
  const std::size_t at = (8 * 36 + 35) * 3;
  CHECK(px == y[at]);
  CHECK(pyv == y[at + 1]);
  CHECK(pz == y[at + 2]);
}

TEST_CASE("ccdlab cloth queries round trip: ccdlab ccd has no false negative against column 7", "[cloth][cli]") {
  Folder dir;
  // A 4 x 4 sheet pinned along z = 0 whose far row turns about the x axis through
  // z = 0.375 at 31.25 rad/s: within 12 steps it sweeps through the sheet, so the steps
  // hold contacts (12 at separation 0) and the round trip can fail.
  std::ofstream(dir / "spin.json") << R"({"format": "ccdlab-cloth/1",
    "grid": {"nx": 4, "ny": 4, "origin": [0, 0, 0], "du": [0.25, 0, 0], "dv": [0, 0, 0.25]},
    "particle_mass": 0.05, "springs": {"structural": {"stiffness": 50, "damping": 0.1},
    "shear": {"stiffness": 5, "damping": 0}, "bend": {"stiffness": 1, "damping": 0}},
    "pinned": [0, 1, 2, 3],
    "spin": {"particles": [12, 13, 14, 15], "center": [0, 0, 0.375], "axis": [1, 0, 0], "rate": 31.25},
    "thickness": 0.001, "step": 0.01, "steps": 12})";
  const std::string scene = (dir / "spin.json") + " --culler bvh --threads 2";
  REQUIRE(run_ccdlab("cloth queries " + scene + " --steps 0:12 -o " + (dir / "q"), dir) == 0);
  REQUIRE(run_ccdlab("cloth frames " + (dir / "spin.json") + " -o " + (dir / "m"), dir) == 0);
  const json index = read_json(dir / "q/index.json");
  const json motion = read_json(dir / "m/cloth.json");
  CHECK(index["format"] == "ccdlab-cloth-queries/1");
  CHECK(index["digest"] == motion["digest"]);
  CHECK(index["steps"] == json::array({0, 12}));
  const std::vector<double> x = read_positions(dir / "m/positions.f64");
  std::size_t total_hits = 0;
  for (const std::string kind : {"vf", "ee"}) {
    const json& k = index[kind];
    const auto file = ccd::cloth::read_query_file(dir / ("q/" + kind + ".csv"));
    REQUIRE(file.queries.size() == k["queries"].get<std::size_t>());
    REQUIRE(k["step"].size() == file.queries.size());
    REQUIRE(k["vertices"].size() == 4 * file.queries.size());
    CHECK(file.inexact_coordinates == 0);  // every coordinate is a double, written exactly
    std::size_t hits = 0;
    for (std::size_t q = 0; q < file.queries.size(); ++q) {
      const std::size_t s = k["step"][q];
      CHECK(s < 12);
      for (std::size_t row = 0; row < 8; ++row) {
        const std::size_t v = k["vertices"][4 * q + row % 4];
        const std::size_t state = s + (row < 4 ? 0 : 1);
        for (int c = 0; c < 3; ++c)
          REQUIRE(file.queries[q].x[row][c] == x[(state * 16 + v) * 3 + static_cast<std::size_t>(c)]);
      }
      hits += file.expected[q] ? 1 : 0;
    }
    CHECK(hits == k["hits"].get<std::size_t>());
    total_hits += hits;
    REQUIRE(run_ccdlab("ccd " + (dir / ("q/" + kind + ".csv")) + " --kind " + kind + " -o " +
                           (dir / (kind + ".json")),
                       dir) == 0);
    const json r = read_json(dir / (kind + ".json"));
    CHECK(r["false_negatives"] == 0);
    std::size_t misses = 0, false_positives = 0;
    for (std::size_t q = 0; q < file.queries.size(); ++q) {
      misses += file.expected[q] && r["results"][q] == 0 ? 1 : 0;
      false_positives += !file.expected[q] && r["results"][q] == 1 ? 1 : 0;
    }
    CHECK(misses == 0);
    CHECK(false_positives == r["false_positives"].get<std::size_t>());
    INFO(kind << ": " << file.queries.size() << " queries, " << hits << " hits, " << false_positives
              << " false positives");
    CHECK(file.queries.size() > 0);
  }
  CHECK(total_hits == 12);

  // --hard-below: a subset that keeps every contact (distance 0 is below any threshold).
  REQUIRE(run_ccdlab("cloth queries " + scene + " --steps 0:12 --hard-below 0.01 -o " + (dir / "h"), dir) ==
          0);
  const json hard = read_json(dir / "h/index.json");
  CHECK(hard["hard_below"] == 0.01);
  for (const std::string kind : {"vf", "ee"}) {
    CHECK(hard[kind]["queries"].get<std::size_t>() <= index[kind]["queries"].get<std::size_t>());
    CHECK(hard[kind]["hits"] == index[kind]["hits"]);
  }
  CHECK(hard["vf"]["queries"].get<std::size_t>() + hard["ee"]["queries"].get<std::size_t>() <
        index["vf"]["queries"].get<std::size_t>() + index["ee"]["queries"].get<std::size_t>());
}

TEST_CASE("ccdlab cloth queries and frames: bad input exits 2 naming the option, nothing written", "[cloth][cli]") {
  Folder dir;
  std::string err;
  const std::string out = " -o " + (dir / "q");
  CHECK(run_ccdlab("cloth queries pile --n 6 --steps 5:5" + out, dir, nullptr, &err) == 2);
  CHECK(err == "ccdlab cloth queries: --steps '5:5': needs A:B, integers with 0 <= A < B (see ccdlab cloth --help)\n");
  CHECK(run_ccdlab("cloth queries pile --n 6 --steps 3" + out, dir, nullptr, &err) == 2);
  CHECK(err.find("--steps '3'") != std::string::npos);
  CHECK(run_ccdlab("cloth queries pile --n 6 --steps -1:4" + out, dir, nullptr, &err) == 2);
  CHECK(run_ccdlab("cloth queries pile --n 6 --steps 0:301" + out, dir, nullptr, &err) == 2);
  CHECK(err ==
        "ccdlab cloth queries: --steps '0:301': B must be <= the scene's 300 steps (see ccdlab cloth --help)\n");
  CHECK(run_ccdlab("cloth queries pile --n 6 --steps 0:2 --culler nope" + out, dir, nullptr, &err) == 2);
  CHECK(err.find("--culler: unknown culler 'nope'") != std::string::npos);
  CHECK(run_ccdlab("cloth queries pile --n 6 --steps 0:2 --culler boxes:nope" + out, dir, nullptr, &err) == 2);
  CHECK(run_ccdlab("cloth queries pile --n 6 --steps 0:2 --hard-below -1" + out, dir, nullptr, &err) == 2);
  CHECK(err.find("--hard-below") != std::string::npos);
  CHECK(run_ccdlab("cloth queries pile --n 6 --steps 0:2 --hard-below nan" + out, dir, nullptr, &err) == 2);
  CHECK(run_ccdlab("cloth queries pile --n 6 --steps 0:2", dir, nullptr, &err) == 2);
  CHECK(run_ccdlab("cloth queries pile --n 3 --steps 0:2" + out, dir, nullptr, &err) == 2);
  CHECK_FALSE(fs::exists(dir / "q"));
  {
    std::ofstream(dir / "bad.json") << R"({"format": "ccdlab-cloth/1", "grid": {}})";
  }
  CHECK(run_ccdlab("cloth queries " + (dir / "bad.json") + " --steps 0:1" + out, dir, nullptr, &err) == 2);
  CHECK(err == "ccdlab cloth queries: " + (dir / "bad.json") + ": grid.nx: missing required field\n");
  CHECK(run_ccdlab("cloth frames " + (dir / "bad.json") + out, dir, nullptr, &err) == 2);
  CHECK(err == "ccdlab cloth frames: " + (dir / "bad.json") + ": grid.nx: missing required field\n");
  CHECK_FALSE(fs::exists(dir / "q"));
  // A folder the command did not write is never replaced.
  fs::create_directory(dir / "mine");
  std::ofstream(dir / "mine/keep.txt") << "mine";
  CHECK(run_ccdlab("cloth frames pile --n 6 --steps 2 -o " + (dir / "mine"), dir, nullptr, &err) == 2);
  CHECK(err.find("was not written by this command") != std::string::npos);
  CHECK(run_ccdlab("cloth queries pile --n 6 --steps 0:2 -o " + (dir / "mine"), dir, nullptr, &err) == 2);
  CHECK(fs::exists(dir / "mine/keep.txt"));
  CHECK_FALSE(fs::exists(dir / "mine/cloth.json"));
  CHECK(run_ccdlab("cloth frames pile --n 6 --steps 2 -o " + (dir / "nofolder/m"), dir, nullptr, &err) == 2);
  CHECK(run_ccdlab("cloth frames pile --n 6 --bogus -o " + (dir / "m"), dir, nullptr, &err) == 2);
  CHECK(err.find("unknown option '--bogus'") != std::string::npos);
  // Existing usage keeps working.
  CHECK(run_ccdlab("cloth pile --n 6 --steps 2 -o " + (dir / "f.json"), dir) == 0);
}

}  // namespace cli_cloth_export_command_test
