// `ccdlab run` and `ccdlab merge` end to end: bad input, thread-count independence,
// shards that merge into the whole run.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/wait.h>

namespace cli_run_command_test {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct TempDir {
  fs::path path;
  TempDir() {
    std::string tmpl = (fs::temp_directory_path() / "ccdlab-run-test-XXXXXX").string();
    path = ::mkdtemp(tmpl.data());
  }
  ~TempDir() { fs::remove_all(path); }
  std::string write(const std::string& name, const json& j) const {
    const fs::path p = path / name;
    std::ofstream(p) << j.dump();
    return p.string();
  }
};

// Runs the ccdlab binary with `args`; returns the exit status, stderr in `err`.
int ccdlab(const std::string& args, std::string* err = nullptr, const TempDir* dir = nullptr) {
  const std::string errfile = dir ? (dir->path / "stderr.txt").string() : "/dev/null";
  const int rc = std::system((std::string(CCDLAB_BINARY) + " " + args + " >/dev/null 2>" + errfile).c_str());
  if (err && dir) {
    std::ifstream in(errfile);
    err->assign(std::istreambuf_iterator<char>(in), {});
  }
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

json small_experiment() {
  return {{"format", "ccdlab-experiment/1"},
          {"name", "small"},
          {"scene", {{"generator", "gas"}, {"bodies", 150}, {"seed", 3}, {"horizon", 0.5}}},
          {"dt", {0.1, 0.02, 0.005}},
          {"methods", {"aabb/sap", "sphere/grid", "capsule/sap", "horn:2/brute"}}};
}

json read(const std::string& path) {
  std::ifstream in(path);
  return json::parse(in);
}

}  // namespace

TEST_CASE("ccdlab run rejects bad experiments with exit 2 and writes nothing", "[run][cli]") {
  const TempDir dir;
  const std::string out = (dir.path / "out.json").string();
  json e = small_experiment();
  std::string err;
  SECTION("unknown method: the valid ones are listed") {
    e["methods"] = {"aabb/sap", "aabb/octree"};
    CHECK(ccdlab("run " + dir.write("e.json", e) + " -o " + out, &err, &dir) == 2);
    CHECK(err.find("methods[1]") != std::string::npos);
    CHECK(err.find("sap") != std::string::npos);  // the list of valid broad phases
  }
  SECTION("bad method option: the field and the option are named") {
    e["methods"] = {"aabb/sap", "aabb/grid:cell=-1"};
    CHECK(ccdlab("run " + dir.write("e.json", e) + " -o " + out, &err, &dir) == 2);
    CHECK(err.find("e.json: methods[1]") != std::string::npos);
    CHECK(err.find("parameter 'cell'") != std::string::npos);
  }
  SECTION("dt <= 0") {
    e["dt"] = {0.1, 0.0};
    CHECK(ccdlab("run " + dir.write("e.json", e) + " -o " + out, &err, &dir) == 2);
    CHECK(err.find("dt[1]") != std::string::npos);
  }
  SECTION("dt larger than the horizon") {
    e["dt"] = {1.0};
    CHECK(ccdlab("run " + dir.write("e.json", e) + " -o " + out, &err, &dir) == 2);
    CHECK(err.find("horizon") != std::string::npos);
  }
  SECTION("empty method list") {
    e["methods"] = json::array();
    CHECK(ccdlab("run " + dir.write("e.json", e) + " -o " + out, &err, &dir) == 2);
    CHECK(err.find("methods") != std::string::npos);
  }
  SECTION("unreadable scene file") {
    e["scene"] = "no-such-scene.json";
    CHECK(ccdlab("run " + dir.write("e.json", e) + " -o " + out, &err, &dir) == 2);
    CHECK(err.find("no-such-scene.json") != std::string::npos);
  }
  SECTION("unknown generator") {
    e["scene"] = {{"generator", "plasma"}};
    CHECK(ccdlab("run " + dir.write("e.json", e) + " -o " + out, &err, &dir) == 2);
    CHECK(err.find("gas") != std::string::npos);
  }
  SECTION("malformed JSON") {
    std::ofstream(dir.path / "bad.json") << "{\"format\": ";
    CHECK(ccdlab("run " + (dir.path / "bad.json").string() + " -o " + out, &err, &dir) == 2);
  }
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("counts do not depend on the thread count, shards merge into the whole run", "[run][cli]") {
  const TempDir dir;
  const std::string e = dir.write("e.json", small_experiment());
  const std::string one = (dir.path / "one.json").string(), two = (dir.path / "two.json").string();
  const std::string seven = (dir.path / "seven.json").string();
  REQUIRE(ccdlab("run " + e + " --quiet --threads 1 -o " + one) == 0);
  REQUIRE(ccdlab("run " + e + " --quiet --threads 2 -o " + two) == 0);
  REQUIRE(ccdlab("run " + e + " --quiet --threads 7 -o " + seven) == 0);  // more workers than most cores
  const json a = read(one), b = read(two), c = read(seven);
  REQUIRE(a["records"].size() == 12);
  REQUIRE(c["records"].size() == 12);
  const char* counts[] = {"steps", "events", "detected", "missed", "candidates", "bound_candidates",
                          "confirmed", "false_positives", "max_penetration", "mean_lag"};
  for (std::size_t i = 0; i < a["records"].size(); ++i) {
    CHECK(a["records"][i]["method"] == c["records"][i]["method"]);
    for (const char* k : counts) CHECK(a["records"][i][k] == b["records"][i][k]);
    for (const char* k : counts) CHECK(a["records"][i][k] == c["records"][i][k]);
    CHECK(a["records"][i]["self_check"]["ok"] == true);
    if (a["records"][i]["continuous"].get<bool>()) CHECK(a["records"][i]["missed"] == 0);
  }
  SECTION("three shards, merged") {
    std::string shards;
    for (int k = 1; k <= 3; ++k) {
      const std::string s = (dir.path / ("s" + std::to_string(k) + ".json")).string();
      REQUIRE(ccdlab("run " + e + " --quiet --threads 1 --shard " + std::to_string(k) + "/3 -o " + s) == 0);
      shards += " " + s;
    }
    const std::string merged = (dir.path / "merged.json").string();
    REQUIRE(ccdlab("merge" + shards + " -o " + merged) == 0);
    const json m = read(merged);
    REQUIRE(m["records"].size() == a["records"].size());
    for (std::size_t i = 0; i < a["records"].size(); ++i)
      for (const char* k : counts) CHECK(m["records"][i][k] == a["records"][i][k]);
    // A missing shard is an error.
    CHECK(ccdlab("merge " + (dir.path / "s1.json").string() + " -o " + (dir.path / "bad.json").string()) == 2);
    CHECK_FALSE(fs::exists(dir.path / "bad.json"));
    // A malformed shard: the message names its file and the field.
    json broken = read((dir.path / "s2.json").string());
    broken["shard"]["count"] = "three";
    const std::string broken_path = dir.write("broken.json", broken);
    std::string err;
    CHECK(ccdlab("merge " + (dir.path / "s1.json").string() + " " + broken_path + " " +
                     (dir.path / "s3.json").string() + " -o " + (dir.path / "bad.json").string(),
                 &err, &dir) == 2);
    CHECK(err.find(broken_path + ": shard.count: must be an integer in [1, 4096]") != std::string::npos);
    CHECK_FALSE(fs::exists(dir.path / "bad.json"));
  }
}

TEST_CASE("Ctrl-C leaves no results file and exits with 130", "[run][cli]") {
  const TempDir dir;
  const std::string out = (dir.path / "interrupted.json").string();
  // The default experiment runs for many seconds: interrupt it after half a second.
  const std::string cmd = "sh -c '" + std::string(CCDLAB_BINARY) + " run " + CCDLAB_SOURCE_DIR +
                          "/data/experiments/default.json --quiet -o " + out +
                          " 2>/dev/null & p=$!; sleep 0.5; kill -INT $p; wait $p'";
  const int rc = std::system(cmd.c_str());
  CHECK(WIFEXITED(rc));
  CHECK(WEXITSTATUS(rc) == 130);
  CHECK_FALSE(fs::exists(out));
  for (const auto& f : fs::directory_iterator(dir.path)) CHECK(f.path().filename().string().find(".tmp.") == std::string::npos);
}

TEST_CASE("ccdlab run --truth reuses a stored truth of the same scene only", "[run][cli][truth]") {
  const TempDir dir;
  const std::string scene = (dir.path / "scene.json").string();
  REQUIRE(ccdlab("scene gas bodies=150 seed=3 horizon=0.5 -o " + scene) == 0);
  json e = small_experiment();
  e["scene"] = scene;
  const std::string exp = dir.write("e.json", e);
  const std::string truth = (dir.path / "truth.json").string();
  REQUIRE(ccdlab("truth " + scene + " --quiet -o " + truth) == 0);
  const std::string computed = (dir.path / "computed.json").string(), reused = (dir.path / "reused.json").string();
  REQUIRE(ccdlab("run " + exp + " --quiet --threads 1 -o " + computed) == 0);
  std::string err;
  SECTION("the same scene: the same counts, the source recorded") {
    REQUIRE(ccdlab("run " + exp + " --quiet --threads 1 --truth " + truth + " -o " + reused, &err, &dir) == 0);
    const json a = read(computed), b = read(reused);
    CHECK(a["truth"]["source"] == "computed");
    CHECK(b["truth"]["source"] == truth);
    CHECK(a["truth"]["scene_sha256"] == b["truth"]["scene_sha256"]);
    CHECK(a["truth"]["events"] == b["truth"]["events"]);
    REQUIRE(a["records"].size() == b["records"].size());
    for (std::size_t i = 0; i < a["records"].size(); ++i)
      for (const char* k : {"events", "detected", "missed", "confirmed", "false_positives", "max_penetration"})
        CHECK(a["records"][i][k] == b["records"][i][k]);
  }
  SECTION("another scene's truth: exit 2 naming the file, nothing written") {
    const std::string other = (dir.path / "other.json").string(), other_truth = (dir.path / "other-truth.json").string();
    REQUIRE(ccdlab("scene gas bodies=150 seed=4 horizon=0.5 -o " + other) == 0);
    REQUIRE(ccdlab("truth " + other + " --quiet -o " + other_truth) == 0);
    CHECK(ccdlab("run " + exp + " --quiet --truth " + other_truth + " -o " + reused, &err, &dir) == 2);
    CHECK(err.find(other_truth + ": scene_sha256: this is the ground truth of another scene") != std::string::npos);
    CHECK_FALSE(fs::exists(reused));
  }
  SECTION("a version 1 file is read; its horizon is checked") {
    json v1 = read(truth);
    v1["format"] = "ccdlab-truth/1";
    v1.erase("scene_sha256");
    const std::string v1_path = dir.write("v1.json", v1);
    REQUIRE(ccdlab("run " + exp + " --threads 1 --truth " + v1_path + " -o " + reused, &err, &dir) == 0);
    CHECK(err.find("no scene digest") != std::string::npos);
    CHECK(read(reused)["truth"]["events"] == read(computed)["truth"]["events"]);
    v1["horizon"] = 0.75;  // still holds every event, but is not the scene's horizon
    const std::string short_path = dir.write("short.json", v1);
    CHECK(ccdlab("run " + exp + " --quiet --truth " + short_path + " -o " + (dir.path / "x.json").string(), &err,
                 &dir) == 2);
    CHECK(err.find(short_path + ": horizon") != std::string::npos);
  }
  SECTION("a missing or malformed truth file: exit 2 naming it") {
    CHECK(ccdlab("run " + exp + " --quiet --truth " + (dir.path / "none.json").string() + " -o " + reused, &err,
                 &dir) == 2);
    CHECK(err.find("none.json") != std::string::npos);
    CHECK_FALSE(fs::exists(reused));
  }
}

TEST_CASE("ccdlab run --list-missed lists every miss, the summary goes beside the results", "[run][cli]") {
  const TempDir dir;
  const std::string out = (dir.path / "r.json").string();
  json e = small_experiment();
  e.erase("dt");
  e["hz"] = {10, 50};
  e["scene"]["speed_max"] = 200;  // fast enough that the discrete methods miss at 10 and 50 Hz
  const std::string file = dir.write("e.json", e);
  REQUIRE(ccdlab("run " + file + " -o " + out + " --quiet --list-missed --threads 1", nullptr, &dir) == 0);
  const json r = read(out);
  std::uint64_t listed = 0;
  for (const json& rec : r["records"]) {
    REQUIRE(rec.contains("missed_events"));
    CHECK(rec["missed_events"].size() == rec["missed"].get<std::size_t>());
    CHECK(rec["hz"].get<double>() * rec["dt"].get<double>() == Approx(1.0).epsilon(1e-15));
    CHECK(rec["conservative"].get<bool>() == rec["continuous"].get<bool>());  // every bound here holds its claim
    double previous = -1.0;
    for (const json& m : rec["missed_events"]) {
      CHECK(m["a"].get<int>() < m["b"].get<int>());
      CHECK(m["enter"].get<double>() >= previous);
      previous = m["enter"].get<double>();
    }
    listed += rec["missed_events"].size();
  }
  CHECK(listed > 0);  // at 10 Hz the discrete methods miss
  std::ifstream md(dir.path / "r.summary.md");
  REQUIRE(md.good());
  const std::string summary((std::istreambuf_iterator<char>(md)), {});
  CHECK(summary.find("| aabb/sap |") != std::string::npos);
  CHECK(summary.find("| capsule/sap \\* |") != std::string::npos);
  CHECK(summary.find("missed @ 10 Hz") != std::string::npos);
}

}  // namespace cli_run_command_test
