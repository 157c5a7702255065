// `ccdlab pack`: a generated scene packed to the binary format gives the same truth file
// (digest included) as its JSON file through every command that reads scenes, unpacks to
// the same JSON text, and damaged or unsupported input exits 2 with one line naming the
// file and the field, writing nothing.
#include "cli_support.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

namespace cli_pack_test {

using ccdlab::test::Folder;
using ccdlab::test::run_ccdlab;
using ccdlab::test::slurp;

TEST_CASE("ccdlab pack: the binary scene stands in for its JSON file", "[cli][pack]") {
  Folder dir;
  const std::string json = dir / "gas.json", bin = dir / "gas.ccds";
  REQUIRE(run_ccdlab("scene swarm bodies=60 seed=3 horizon=0.5 -o " + json, dir) == 0);
  REQUIRE(run_ccdlab("pack " + json + " -o " + bin, dir) == 0);
  CHECK(slurp(bin).rfind("\x89" "CCDS\r\n\x1a", 0) == 0);
  CHECK(std::filesystem::file_size(bin) < std::filesystem::file_size(json));

  SECTION("truth: the same file, digest included") {
    REQUIRE(run_ccdlab("truth " + json + " -o " + dir / "t-json.json", dir) == 0);
    REQUIRE(run_ccdlab("truth " + bin + " -o " + dir / "t-bin.json", dir) == 0);
    CHECK(slurp(dir / "t-json.json") == slurp(dir / "t-bin.json"));
    CHECK(slurp(dir / "t-bin.json").find("\"scene_sha256\"") != std::string::npos);
    // The truth of the JSON file is accepted for a run on the binary file.
    std::ofstream(dir / "exp.json") << R"({"format": "ccdlab-experiment/1", "scene": "gas.ccds", "dt": [0.125],
      "methods": ["capsule/grid"]})";
    CHECK(run_ccdlab("run " + dir / "exp.json" + " --truth " + dir / "t-json.json" + " -o " + dir / "r.json", dir) == 0);
  }
  SECTION("poses and view read it too") {
    REQUIRE(run_ccdlab("poses " + json + " --times 0:0.5:0.25 -o " + dir / "p-json.csv", dir) == 0);
    REQUIRE(run_ccdlab("poses " + bin + " --times 0:0.5:0.25 -o " + dir / "p-bin.csv", dir) == 0);
    CHECK(slurp(dir / "p-json.csv") == slurp(dir / "p-bin.csv"));
    CHECK(run_ccdlab("view " + bin + " -o " + dir / "v.html", dir) == 0);
  }
  SECTION("--json unpacks to the text ccdlab scene wrote") {
    REQUIRE(run_ccdlab("pack " + bin + " -o " + dir / "back.json --json", dir) == 0);
    CHECK(slurp(dir / "back.json") == slurp(json));
  }
  SECTION("a truncated file: exit 2, one line naming file and section") {
    const std::string bytes = slurp(bin);
    std::ofstream(dir / "cut.ccds", std::ios::binary) << bytes.substr(0, 192 + 8 * 60 + 10);
    std::string err;
    CHECK(run_ccdlab("truth " + dir / "cut.ccds" + " -o " + dir / "t.json", dir, nullptr, &err) == 2);
    CHECK(err.rfind("ccdlab truth: " + dir / "cut.ccds" + ": position: truncated", 0) == 0);
    CHECK(err.find('\n') == err.size() - 1);
    CHECK_FALSE(std::filesystem::exists(dir / "t.json"));
  }
  SECTION("a stored digest that is not the scene's: pack refuses it") {
    std::string bytes = slurp(bin);
    bytes[40] = bytes[40] == 'a' ? 'b' : 'a';
    std::ofstream(dir / "bad.ccds", std::ios::binary) << bytes;
    std::string err;
    CHECK(run_ccdlab("pack " + dir / "bad.ccds" + " -o " + dir / "x.json --json", dir, nullptr, &err) == 2);
    CHECK(err.find(": digest: the stored digest") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir / "x.json"));
  }
}

TEST_CASE("ccdlab pack refuses what the binary format does not carry, and bad usage", "[cli][pack]") {
  Folder dir;
  REQUIRE(run_ccdlab("scene crates bodies=10 -o " + dir / "c.json", dir) == 0);
  std::string err;
  CHECK(run_ccdlab("pack " + dir / "c.json" + " -o " + dir / "c.ccds", dir, nullptr, &err) == 2);
  CHECK(err == "ccdlab pack: " + dir / "c.json" +
                   ": shapes: the binary scene format carries sphere scenes only (no shapes, spin or scenery): keep "
                   "this scene as JSON\n");
  CHECK_FALSE(std::filesystem::exists(dir / "c.ccds"));
  CHECK(run_ccdlab("pack " + dir / "c.json", dir) == 2);                                 // no -o
  CHECK(run_ccdlab("pack " + dir / "c.json" + " -o " + dir / "c.json", dir) == 2);      // its own input
  CHECK(run_ccdlab("pack " + dir / "missing.json" + " -o " + dir / "m.ccds", dir) == 2);
  CHECK(run_ccdlab("pack --frobnicate", dir) == 2);
}

}  // namespace cli_pack_test
