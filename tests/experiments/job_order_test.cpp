// The runner starts its jobs smallest dt first (experiments/job_order.hpp) and still
// writes each job's record at its own place.
#include "../../experiments/job_order.hpp"
#include "../../experiments/run_experiment.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <vector>

namespace experiments_job_order_test {

using nlohmann::json;

TEST_CASE("job order: smallest dt first, equal dt in index order", "[run][job_order]") {
  CHECK(ccdlab::job_order(std::vector<double>{}).empty());
  CHECK(ccdlab::job_order(std::vector<double>{0.5}) == std::vector<std::size_t>{0});
  // The runner's layout: per method, dt descending (two methods, three dt).
  const std::vector<double> dt{0.1, 0.02, 0.005, 0.1, 0.02, 0.005};
  CHECK(ccdlab::job_order(dt) == std::vector<std::size_t>{2, 5, 1, 4, 0, 3});
  // Not sorted in any way, with ties that are not adjacent, and dyadic neighbours.
  const std::vector<double> mixed{0.25, 0x1p-10, 0.25, 0x1.0000000000001p-10, 0x1p-10, 1.0};
  CHECK(ccdlab::job_order(mixed) == std::vector<std::size_t>{1, 4, 3, 0, 2, 5});
}

TEST_CASE("records keep the job order whatever order the jobs ran in", "[run][job_order]") {
  const json spec = {{"format", "ccdlab-experiment/1"},
                     {"name", "order"},
                     {"scene", {{"generator", "gas"}, {"bodies", 80}, {"seed", 3}, {"horizon", 0.5}}},
                     {"dt", {0.1, 0.02, 0.005}},
                     {"methods", {"aabb/sap", "horn:2/grid"}}};
  const ccdlab::Experiment e = ccdlab::experiment_from_json(spec, "order.json");
  const ccd::Scene scene = ccdlab::load_experiment_scene(e, "order.json");
  ccdlab::RunOptions options;
  options.quiet = true;
  std::vector<json> runs;
  for (const int threads : {1, 2}) {
    options.threads = threads;
    runs.push_back(ccdlab::run_experiment(e, scene, options));
  }
  for (const json& run : runs) {
    const json& records = run["records"];
    REQUIRE(records.size() == 6);
    for (std::size_t i = 0; i < records.size(); ++i) {
      CHECK(records[i]["job"] == i);
      CHECK(records[i]["method"] == spec["methods"][i / 3]);
      CHECK(records[i]["dt"] == spec["dt"][i % 3]);
    }
  }
  for (std::size_t i = 0; i < 6; ++i) {
    CHECK(runs[0]["records"][i]["detected"] == runs[1]["records"][i]["detected"]);
    CHECK(runs[0]["records"][i]["missed"] == runs[1]["records"][i]["missed"]);
  }
}

}  // namespace experiments_job_order_test
