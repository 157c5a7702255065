// The cloth experiment format (ccdlab-cloth-experiment/1) and `ccdlab run` on it: defaults
// filled in, one error line per bad field, results and summary written, the mesh truth
// stored once and read back.
#include "../../experiments/cloth_experiment.hpp"
#include "../cli/cli_support.hpp"

#include <ccd/io/input_error.hpp>
#include <cloth/cull/cullers.hpp>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

namespace experiments_cloth_experiment_test {

namespace fs = std::filesystem;
using nlohmann::json;
using ccdlab::test::Folder;

namespace {

json small() {
  return {{"format", "ccdlab-cloth-experiment/1"}, {"name", "small"}, {"scene", "pile"}, {"n", 5},
          {"steps", 40},                            {"k", {8, 1, 4}}};
}

std::string refused(const json& j) {
  try {
    ccdlab::cloth_experiment_from_json(j, "e.json");
  } catch (const ccd::InputError& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace

TEST_CASE("cloth experiment: defaults, and every bad field named", "[cloth][experiments]") {
  const ccdlab::ClothExperiment e = ccdlab::cloth_experiment_from_json(small(), "e.json");
  CHECK(e.k == std::vector<int>{1, 4, 8});
  CHECK(e.cullers.size() == ccd::cloth::cullers().size());  // every registered culler
  CHECK(e.modes == std::vector<std::string>{"discrete", "continuous"});
  const json back = ccdlab::cloth_experiment_to_json(e);
  CHECK(back["cullers"].size() == e.cullers.size());
  CHECK(back["repeats"] == 1);
  CHECK(ccdlab::cloth_experiment_from_json(back, "e.json").k == e.k);  // what the results record parses again
  {  // without steps (the scene's own), the record writes "steps": null: it parses again
    json no_steps = small();
    no_steps.erase("steps");
    const ccdlab::ClothExperiment d = ccdlab::cloth_experiment_from_json(no_steps, "e.json");
    const json written = ccdlab::cloth_experiment_to_json(d);
    CHECK(written["steps"].is_null());
    CHECK(ccdlab::cloth_experiment_from_json(written, "e.json").steps == d.steps);
  }

  auto with = [](const char* key, const json& v) {
    json j = small();
    j[key] = v;
    return j;
  };
  CHECK(refused(with("k", json::array())) ==
        "e.json: k: must be a non-empty array of check intervals (integrator steps)");
  CHECK(refused(with("k", {2, 2})) == "e.json: k: check intervals must be distinct");
  CHECK(refused(with("k", {0})) == "e.json: k[0]: must be an integer in [1, 1000000]");
  CHECK(refused(with("cullers", {"bvh", "bhv_cones"})) ==
        "e.json: cullers[1]: unknown culler 'bhv_cones' (did you mean \"bvh_cones\"?)");
  CHECK(refused(with("cullers", {"bvh", "bvh"})) == "e.json: cullers[1]: culler 'bvh' is listed twice");
  CHECK(refused(with("modes", {"sampled"})) == "e.json: modes[0]: must be \"discrete\" or \"continuous\"");
  CHECK(refused(with("n", 3)) == "e.json: n: must be an integer in [4, 1000]");
  CHECK(refused(with("scene", "s.json")) == "e.json: n: applies to a built-in scene only (a scene file sets its grid)");
  CHECK(refused(with("dt", 1)).rfind("e.json: dt: unknown field", 0) == 0);
  json no_k = small();
  no_k.erase("k");
  CHECK(refused(no_k) == "e.json: k: missing required field");
  // k longer than the run: found with the scene.
  const ccdlab::ClothExperiment long_k = ccdlab::cloth_experiment_from_json(with("k", {41}), "e.json");
  CHECK_THROWS_WITH(ccdlab::load_cloth_experiment_scene(long_k, "e.json"),
                    "e.json: k[0]: check interval 41 is longer than the run (40 steps)");
}

TEST_CASE("ccdlab run on a cloth experiment: records, summary, and the truth computed once", "[cloth][cli]") {
  Folder dir;
  std::ofstream(dir / "e.json") << small().dump();
  std::string out, err;
  REQUIRE(ccdlab::test::run_ccdlab("run " + (dir / "e.json") + " -o " + (dir / "r.json") + " --threads 2", dir, &out,
                                   &err) == 0);
  const json r = json::parse(ccdlab::test::slurp(dir / "r.json"));
  CHECK(r["format"] == "ccdlab-cloth-results/1");
  CHECK(r["records"].size() == ccd::cloth::cullers().size() * 2 * 3);
  CHECK(r["truth"]["reused"] == false);
  CHECK(r["scene"]["triangles"] == 2 * 4 * 4);
  for (const json& rec : r["records"]) {
    CHECK(rec["detected"].get<int>() + rec["missed"].get<int>() == rec["events"].get<int>());
    if (rec["conservative"].get<bool>()) CHECK(rec["missed"] == 0);
    CHECK(rec["dt"].get<double>() == Approx(rec["k"].get<int>() * 0.005));
  }
  CHECK(out.find("bvh/continuous *") != std::string::npos);  // the summary table
  CHECK(fs::exists(dir / "r.summary.md"));
  const std::string truth_file = r["truth"]["file"].get<std::string>();
  CHECK(fs::path(truth_file).parent_path() == fs::path(dir / "cloth-truth"));
  CHECK(fs::exists(truth_file));
  // Again: the truth is read back and the counts are the same.
  REQUIRE(ccdlab::test::run_ccdlab("run " + (dir / "e.json") + " -o " + (dir / "r2.json") + " --quiet", dir) == 0);
  const json r2 = json::parse(ccdlab::test::slurp(dir / "r2.json"));
  CHECK(r2["truth"]["reused"] == true);
  CHECK(r2["truth"]["events"] == r["truth"]["events"]);
  for (std::size_t i = 0; i < r["records"].size(); ++i)
    for (const char* key : {"method", "k", "detected", "missed", "candidates", "confirmed", "false_positives"})
      CHECK(r2["records"][i][key] == r["records"][i][key]);
  // A damaged truth file is bad input: one line, exit 2, no results.
  std::ofstream(truth_file) << R"({"format": "ccdlab-cloth-truth/1"})";
  REQUIRE(ccdlab::test::run_ccdlab("run " + (dir / "e.json") + " -o " + (dir / "r3.json"), dir, nullptr, &err) == 2);
  CHECK(err == "ccdlab run: " + truth_file + ": digest: missing required field\n");
  CHECK_FALSE(fs::exists(dir / "r3.json"));
  // Bad experiments and options.
  json bad = small();
  bad["k"] = {1, 100};
  std::ofstream(dir / "bad.json") << bad.dump();
  REQUIRE(ccdlab::test::run_ccdlab("run " + (dir / "bad.json") + " -o " + (dir / "r4.json"), dir, nullptr, &err) == 2);
  CHECK(err == "ccdlab run: " + (dir / "bad.json") + ": k[1]: check interval 100 is longer than the run (40 steps)\n");
  CHECK_FALSE(fs::exists(dir / "r4.json"));
  REQUIRE(ccdlab::test::run_ccdlab("run " + (dir / "e.json") + " --shard 1/2", dir, nullptr, &err) == 2);
  CHECK(err.find("apply to sphere and rigid experiments only") != std::string::npos);
}

}  // namespace experiments_cloth_experiment_test
