// `ccdlab merge` reads shards as strictly as experiments: every field with its type, job
// indices in range and owned by their shard, one experiment, one scene (by contents), one
// ground truth. Shards come from real runs; each case breaks one thing.
#include <experiments/results_file.hpp>

#include <ccd/io/input_error.hpp>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace experiments_merge_test {

namespace fs = std::filesystem;
using nlohmann::json;
using ccdlab::ResultsShard;

namespace {

struct Folder {
  fs::path path;
  Folder() {
    std::string tmpl = (fs::temp_directory_path() / "ccdlab-merge-test-XXXXXX").string();
    path = ::mkdtemp(tmpl.data());
  }
  ~Folder() { fs::remove_all(path); }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
};

int run_ccdlab(const std::string& args, std::string* err = nullptr, const Folder* dir = nullptr) {
  const std::string errfile = dir ? *dir / "stderr.txt" : "/dev/null";
  const int rc = std::system((std::string(CCDLAB_BINARY) + " " + args + " >/dev/null 2>" + errfile).c_str());
  if (err && dir) {
    std::ifstream in(errfile);
    err->assign(std::istreambuf_iterator<char>(in), {});
  }
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

json read(const std::string& path) {
  std::ifstream in(path);
  return json::parse(in);
}

json scene(double x) {
  return {{"format", "ccdlab-scene/1"},
          {"horizon", 1.0},
          {"bodies",
           {{{"radius", 0.5}, {"position", {0, 0, 0}}, {"velocity", {2, 0, 0}}},
            {{"radius", 0.5}, {"position", {x, 0, 0}}},
            {{"radius", 0.25}, {"position", {0, 3, 0}}, {"velocity", {0, -3, 0}}}}}};
}

// Three shards of a 2-method x 3-dt experiment over a scene file.
struct Shards {
  Folder dir;
  std::vector<ResultsShard> shards;
  explicit Shards(double x_of_shard_2 = 1.5) {
    const json e = {{"format", "ccdlab-experiment/1"}, {"name", "m"}, {"scene", "scene.json"},
                    {"dt", {0.1, 0.05, 0.02}}, {"methods", {"aabb/sap", "capsule/grid"}}};
    std::ofstream(dir / "e.json") << e.dump();
    for (int k = 1; k <= 3; ++k) {
      std::ofstream(dir / "scene.json") << scene(k == 2 ? x_of_shard_2 : 1.5).dump();
      const std::string out = dir / ("s" + std::to_string(k) + ".json");
      REQUIRE(run_ccdlab("run " + (dir / "e.json") + " --quiet --shard " + std::to_string(k) + "/3 -o " + out) == 0);
      shards.push_back({out, read(out)});
    }
  }
};

std::string merge_error(const std::vector<ResultsShard>& shards) {
  try {
    ccdlab::merge_results(shards);
  } catch (const ccd::InputError& e) {
    return e.what();
  }
  return "merged";
}

}  // namespace

TEST_CASE("merge validates every field of every shard and names file and field", "[merge][cli]") {
  Shards s;
  const std::string s1 = s.shards[0].file, s2 = s.shards[1].file;
  REQUIRE(merge_error(s.shards) == "merged");
  json& first = s.shards[0].results;
  SECTION("a missing field: once read as garbage (a peak memory of 7.5e18)") {
    first.erase("peak_memory_bytes");
    CHECK(merge_error(s.shards) == s1 + ": peak_memory_bytes: missing required field");
  }
  SECTION("a missing record field") {
    first["records"][1].erase("missed");
    CHECK(merge_error(s.shards) == s1 + ": records[1].missed: missing required field");
    first["records"][1]["missed"] = 0;
    first["records"][1]["self_check"].erase("ok");
    CHECK(merge_error(s.shards) == s1 + ": records[1].self_check.ok: missing required field");
  }
  SECTION("wrong types: once 'type must be number, but is number'") {
    first["truth"]["events"] = 1.5;
    CHECK(merge_error(s.shards) == s1 + ": truth.events: must be an integer in [0, 18446744073709551615]");
    first["truth"]["events"] = "3";
    CHECK(merge_error(s.shards) == s1 + ": truth.events: must be an integer in [0, 18446744073709551615]");
  }
  SECTION("a record of the wrong type") {
    first["records"][0]["candidates"] = -4;
    CHECK(merge_error(s.shards) == s1 + ": records[0].candidates: must be an integer in [0, 18446744073709551615]");
    first["records"][0]["candidates"] = 4;
    first["records"][0]["bound_seconds"] = "fast";
    CHECK(merge_error(s.shards) == s1 + ": records[0].bound_seconds: must be a number");
  }
  SECTION("job indices out of range, of another shard, twice") {
    first["records"][0]["job"] = 99;
    CHECK(merge_error(s.shards) == s1 + ": records[0].job: must be below shard.jobs = 6");
    first["records"][0]["job"] = 1;
    CHECK(merge_error(s.shards) == s1 + ": records[0].job: job 1 does not belong to shard 1/3");
    first["records"][0]["job"] = 0;
    first["records"][1]["job"] = 0;
    CHECK(merge_error(s.shards) == s1 + ": records[1].job: job 0 appears twice");
  }
  SECTION("counts: initial contacts + detected + missed = events") {
    json& rec = first["records"][0];
    const std::uint64_t events = rec["events"].get<std::uint64_t>();
    REQUIRE(events > 0);
    // Every event in progress at t = 0 (a scene whose bodies start overlapping): valid.
    rec["initial_contacts"] = events;
    rec["detected"] = 0;
    rec["missed"] = 0;
    CHECK(merge_error(s.shards) == "merged");
    rec["missed"] = 1;
    CHECK(merge_error(s.shards) == s1 + ": records[0].missed: undecided + initial_contacts + detected + missed must equal events");
    rec["missed"] = 0;
    rec["initial_contacts"] = events + 1;
    CHECK(merge_error(s.shards) == s1 + ": records[0].missed: undecided + initial_contacts + detected + missed must equal events");
  }
  SECTION("a record that is not its job's method or dt") {
    first["records"][0]["method"] = "capsule/grid";
    CHECK(merge_error(s.shards) == s1 + ": records[0].method: must be 'aabb/sap', the method of job 0");
  }
  SECTION("an experiment that is not one") {
    first["experiment"]["methods"] = {"aabb/octree", "capsule/grid"};
    CHECK(merge_error(s.shards).rfind(s1 + ": experiment.methods[0]: unknown broad phase", 0) == 0);
    // Once a JSON type error (exit 1, no field) from erasing a key of an array.
    first["experiment"] = {1, 2};
    CHECK(merge_error(s.shards) == s1 + ": experiment: must be an object");
  }
  SECTION("the shard itself") {
    first["shard"]["index"] = 4;
    CHECK(merge_error(s.shards) == s1 + ": shard.index: must be an integer in [1, 3]");
    first["shard"]["index"] = 1;
    first["shard"]["jobs"] = 7;
    CHECK(merge_error(s.shards) == s1 + ": shard.jobs: must be 6 (methods x dt of the experiment)");
  }
  SECTION("the same shard twice, a shard missing") {
    std::vector<ResultsShard> twice = {s.shards[0], s.shards[0], s.shards[2]};
    CHECK(merge_error(twice) == s1 + ": shard.index: shard 1 is also " + s1);
    std::vector<ResultsShard> missing = {s.shards[0], s.shards[2]};
    CHECK(merge_error(missing) == s1 + ": shard: the shards 2 of 3 are missing");
  }
}

TEST_CASE("merge refuses shards of different scene contents under the same file name", "[merge][cli]") {
  // Shard 2 ran after one body of scene.json moved by 1e-9 m: the same path, the same
  // number of bodies and events, another scene.
  Shards s(1.5 + 1e-9);
  const std::string here = s.shards[1].results["truth"]["scene_sha256"].get<std::string>();
  const std::string there = s.shards[0].results["truth"]["scene_sha256"].get<std::string>();
  REQUIRE(here != there);
  CHECK(merge_error(s.shards) == s.shards[1].file + ": truth.scene_sha256: a different scene than " + s.shards[0].file +
                                     " (\"" + here + "\" here, \"" + there + "\" there)");
  // On the command line: exit 2, one line, no file.
  std::string err;
  const std::string out = s.dir / "merged.json";
  CHECK(run_ccdlab("merge " + s.shards[0].file + " " + s.shards[1].file + " " + s.shards[2].file + " -o " + out, &err,
               &s.dir) == 2);
  CHECK(err.rfind("ccdlab merge: " + s.shards[1].file + ": truth.scene_sha256: a different scene", 0) == 0);
  CHECK(std::count(err.begin(), err.end(), '\n') == 1);
  CHECK_FALSE(fs::exists(out));
  // Nor over one of its inputs.
  CHECK(run_ccdlab("merge " + s.shards[0].file + " -o " + s.shards[0].file) == 2);
}

}  // namespace experiments_merge_test
