// `ccdlab cloth`: built-in scenes and scene files simulate and write their frames; bad
// input exits 2 with one line and writes nothing.
#include "cli_support.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace cli_cloth_command_test {

namespace fs = std::filesystem;
using nlohmann::json;

using ccdlab::test::Folder;

namespace {

int run_cloth(const std::string& args, const Folder& dir, std::string* err = nullptr) {
  return ccdlab::test::run_ccdlab("cloth " + args, dir, nullptr, err);
}

}  // namespace

TEST_CASE("ccdlab cloth writes the frames of a built-in scene and of a scene file", "[cloth][cli]") {
  Folder dir;
  REQUIRE(run_cloth("pile --n 6 --steps 7 --every 3 -o " + (dir / "f.json"), dir) == 0);
  std::ifstream in(dir / "f.json");
  const json f = json::parse(in);
  CHECK(f["format"] == "ccdlab-cloth-frames/1");
  CHECK(f["triangles"].size() == 2 * 5 * 5);
  REQUIRE(f["frames"].size() == 4);  // t = 0, 3h, 6h, 7h
  CHECK(f["frames"][3]["t"].get<double>() == Approx(7 * 0.005));
  CHECK(f["frames"][0]["x"].size() == 3 * 36);
  {
    std::ofstream(dir / "s.json") << R"({"format": "ccdlab-cloth/1",
      "grid": {"nx": 3, "ny": 3, "origin": [0, 0, 0], "du": [0.5, 0, 0], "dv": [0, 0, 0.5]},
      "particle_mass": 0.1, "springs": {"structural": {"stiffness": 10, "damping": 0},
      "shear": {"stiffness": 1, "damping": 0}, "bend": {"stiffness": 1, "damping": 0}},
      "thickness": 0, "step": 0.01, "steps": 2})";
  }
  CHECK(run_cloth((dir / "s.json") + " -o " + (dir / "g.json"), dir) == 0);
  std::string err;
  {
    std::ofstream(dir / "bad.json") << R"({"format": "ccdlab-cloth/1", "grid": {}})";
  }
  CHECK(run_cloth((dir / "bad.json") + " -o " + (dir / "h.json"), dir, &err) == 2);
  CHECK(err == "ccdlab cloth: " + (dir / "bad.json") + ": grid.nx: missing required field\n");
  CHECK_FALSE(fs::exists(dir / "h.json"));
  CHECK(run_cloth("drape --n 3 -o " + (dir / "h.json"), dir) == 2);
  CHECK(run_cloth("drape", dir) == 2);
}

}  // namespace cli_cloth_command_test
