// Sharding: for any shard count N and any order of the shard files, `merge_results`
// gives back the whole run, count for count (docs/experiments.md, "Running on a cluster").
#include "../../experiments/results_file.hpp"
#include "../../experiments/run_experiment.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

namespace experiments_shard_merge_test {

using nlohmann::json;

namespace {

json small_experiment() {
  return {{"format", "ccdlab-experiment/1"},
          {"name", "small"},
          {"scene", {{"generator", "gas"}, {"bodies", 120}, {"seed", 5}, {"horizon", 0.5}}},
          {"dt", {0.1, 0.02, 0.005}},
          {"methods", {"aabb/sap", "sphere/grid", "capsule/sap", "horn:2/brute"}}};
}

// The results without what differs between two runs of one experiment: timings (fields
// whose name contains "seconds"), the environment, the shard and the peak memory.
json comparable(const json& j) {
  if (j.is_object()) {
    json out = json::object();
    for (const auto& [k, v] : j.items()) {
      const bool timing = k.find("seconds") != std::string::npos;
      if (!timing && k != "environment" && k != "shard" && k != "peak_memory_bytes") out[k] = comparable(v);
    }
    return out;
  }
  if (j.is_array()) {
    json out = json::array();
    for (const json& v : j) out.push_back(comparable(v));
    return out;
  }
  return j;
}

}  // namespace

TEST_CASE("shards merged in any order equal the whole run, for any shard count", "[run][shard]") {
  const ccdlab::Experiment e = ccdlab::experiment_from_json(small_experiment(), "small.json");
  const ccd::Scene scene = ccdlab::load_experiment_scene(e, "small.json");
  ccdlab::RunOptions options;
  options.threads = 2;
  options.quiet = true;
  const json whole = ccdlab::run_experiment(e, scene, options);
  const std::size_t jobs = whole["records"].size();
  REQUIRE(jobs == 12);

  options.threads = 1;
  std::mt19937 rng(19);
  for (const int n : {1, 2, 3, 5, 7, 12, 13}) {
    CAPTURE(n);
    std::vector<json> shards;
    std::size_t records = 0;
    for (int k = 1; k <= n; ++k) {
      options.shard = {k, n};
      shards.push_back(ccdlab::run_experiment(e, scene, options));
      records += shards.back()["records"].size();
      for (const json& r : shards.back()["records"]) CHECK(r["job"].get<int>() % n == k - 1);
    }
    CHECK(records == jobs);  // every job in exactly one shard; with n > jobs some are empty
    std::vector<std::string> names;
    for (int k = 1; k <= n; ++k) names.push_back("shard" + std::to_string(k) + ".json");
    std::vector<std::size_t> order(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    for (int permutation = 0; permutation < 3; ++permutation) {
      CAPTURE(permutation);
      if (permutation == 1) std::reverse(order.begin(), order.end());
      if (permutation == 2) std::shuffle(order.begin(), order.end(), rng);
      std::vector<ccdlab::ResultsShard> given;
      for (const std::size_t i : order) given.push_back({names[i], shards[i]});
      const json merged = ccdlab::merge_results(given);
      CHECK(merged["shard"]["merged_from"] == n);
      CHECK(comparable(merged) == comparable(whole));
      if (n > 1 && n <= static_cast<int>(jobs)) {  // a missing shard is an error, whichever it is
        given.pop_back();
        CHECK_THROWS(ccdlab::merge_results(given));
      }
    }
  }
}

}  // namespace experiments_shard_merge_test
