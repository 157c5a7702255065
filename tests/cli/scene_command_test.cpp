// The `ccdlab scene` command, run as the built binary (CCDLAB_BINARY).
#include <ccd/scene/scene_io.hpp>
#include <generators/registry.hpp>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace cli_scene_command_test {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A folder of its own per test process (ctest may run test cases in parallel), removed
// when the process ends.
struct ScratchFolder {
  fs::path path = fs::temp_directory_path() / ("ccdlab_scene_test_" + std::to_string(::getpid()));
  ScratchFolder() { fs::create_directories(path); }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

const fs::path& scratch() {
  static const ScratchFolder folder;
  return folder.path;
}

struct Run {
  int status = -1;
  std::string out;
  std::string err;
};

// Runs `ccdlab scene ARGS` with stdout and stderr captured in files.
Run run_scene(const std::string& args) {
  const fs::path out = scratch() / "stdout.txt";
  const fs::path err = scratch() / "stderr.txt";
  const std::string cmd =
      std::string("'") + CCDLAB_BINARY + "' scene " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int raw = std::system(cmd.c_str());
  Run r;
  REQUIRE(WIFEXITED(raw));
  r.status = WEXITSTATUS(raw);
  auto slurp = [](const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  };
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

}  // namespace

TEST_CASE("ccdlab scene writes the scene that generate_scene makes", "[generators][cli]") {
  const fs::path file = scratch() / "gas.json";
  fs::remove(file);
  const Run r = run_scene("gas bodies=40 seed=3 offset=1e6,0,-5 -o '" + file.string() + "'");
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  REQUIRE(fs::exists(file));
  const ccd::Scene written = ccd::load_scene(file.string());
  const ccd::Scene expected =
      ccdlab::generate_scene("gas", json{{"bodies", 40}, {"seed", 3}, {"offset", {1e6, 0, -5}}});
  CHECK(ccd::scene_to_json(written) == ccd::scene_to_json(expected));
  fs::remove(file);
}

TEST_CASE("ccdlab scene --help lists every generator with its parameters and defaults", "[generators][cli]") {
  const Run r = run_scene("--help");
  CHECK(r.status == 0);
  for (const ccdlab::Generator& g : ccdlab::generators()) {
    CHECK(r.out.find("  " + std::string(g.name) + ": ") != std::string::npos);
    for (const ccdlab::ParameterSpec& s : g.parameters)
      CHECK(r.out.find(std::string(s.name) + "=" + ccdlab::format_number(s.default_value)) != std::string::npos);
  }
}

TEST_CASE("ccdlab scene refuses bad input with one line naming it, exit 2, no file", "[generators][cli]") {
  struct Case {
    const char* args;
    const char* named;  // the part the message must name
  };
  const Case c = GENERATE(Case{"plasma", "unknown generator 'plasma'; valid generators: gas, rain"},
                          Case{"gas radius=1", "gas: unknown parameter 'radius'; valid parameters: seed, bodies"},
                          Case{"gas bodies=2.5", "parameter 'bodies': must be an integer"},
                          Case{"gas bodies=-1", "parameter 'bodies': must be an integer"},
                          Case{"gas bodies=ten", "parameter 'bodies': 'ten' is not a number"},
                          Case{"gas fraction=0.5", "parameter 'fraction': must be a number in (0, 0.5)"},
                          Case{"gas r_min=2", "r_min (2) must be <= r_max (1.5)"},
                          Case{"lattice radius=0.3", "power of two"},
                          Case{"gas offset=1,2", "parameter 'offset': expects one number or three"},
                          Case{"gas bodies", "expected NAME=VALUE, got 'bodies'"},
                          Case{"gas --fast", "unknown option '--fast'"},
                          Case{"", "missing GENERATOR"});
  CAPTURE(c.args);
  const fs::path file = scratch() / "bad.json";
  fs::remove(file);
  const Run r = run_scene(std::string(c.args) + " -o '" + file.string() + "'");
  CHECK(r.status == 2);
  CHECK(!fs::exists(file));
  CHECK(r.err.rfind("ccdlab scene: ", 0) == 0);
  CHECK(r.err.find(c.named) != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(r.out.empty());
}

TEST_CASE("ccdlab scene without -o writes nothing", "[generators][cli]") {
  SECTION("no -o at all") {
    const Run r = run_scene("gas bodies=10");
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab scene: missing -o SCENE.json\n");
    CHECK(r.out.empty());
  }
  SECTION("-o without a name") {
    const Run r = run_scene("gas bodies=10 -o");
    CHECK(r.status == 2);
    CHECK(r.err == "ccdlab scene: -o needs a file name\n");
  }
}

TEST_CASE("ccdlab scene refuses an unwritable output before generating, with exit 2", "[generators][cli]") {
  const fs::path file = scratch() / "no-such-folder" / "x.json";
  const Run r = run_scene("gas bodies=10 -o '" + file.string() + "'");
  CHECK(r.status == 2);
  CHECK(!fs::exists(file));
  CHECK(r.err.find("no-such-folder") != std::string::npos);
}

TEST_CASE("data/scenes/default.json is the gas scene of 2000 bodies, seed 7, horizon 1, speeds up to 40", "[generators]") {
  const ccd::Scene stored = ccd::load_scene(std::string(CCDLAB_SOURCE_DIR) + "/data/scenes/default.json");
  const ccd::Scene expected = ccdlab::generate_scene("gas", json{{"bodies", 2000}, {"seed", 7}, {"horizon", 1}, {"speed_max", 40}});
  CHECK(ccd::scene_to_json(stored) == ccd::scene_to_json(expected));
}

}  // namespace cli_scene_command_test
