// The runner and undecided truth events (docs/experiments.md, `undecided`): a plate
// spinning 2^-50 from two resting balls, a gap the truth cannot certify, gives two
// undecided events; every method's record counts them apart (never detected, never
// missed, conservative or not), the results say how many there were, and so does the
// summary. The same plate 5e-7 away has no event at all.
#include "../../experiments/experiment.hpp"
#include "../../experiments/method.hpp"
#include "../../experiments/results_file.hpp"
#include "../../experiments/run_experiment.hpp"
#include "../../experiments/summary.hpp"
#include "../ccd/scene/plate_scenes.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

namespace experiments_undecided_runner_test {

using nlohmann::json;

namespace {

ccdlab::Experiment plate_experiment(const std::vector<std::string>& methods) {
  return ccdlab::experiment_from_json({{"format", "ccdlab-experiment/1"},
                                       {"name", "plate"},
                                       {"scene", "plate.json"},
                                       {"dt", {0.25, 0.0625}},
                                       {"methods", methods}},
                                      "plate.json");
}

ccdlab::RunOptions quiet() {
  ccdlab::RunOptions o;
  o.threads = 2;
  o.quiet = true;
  return o;
}

}  // namespace

TEST_CASE("undecided events are counted apart by every method, never as misses", "[runner][undecided]") {
  const ccd::Scene scene = ccd::test::dyadic_plate_scene(10.0, std::ldexp(1.0, -50));
  std::vector<std::string> methods = {"swept_aabb/brute", "capsule/grid", "horn:4/sap@earliest", "sphere/grid",
                                      "aabb/sap"};
  const json results = ccdlab::run_experiment(plate_experiment(methods), scene, quiet());
  REQUIRE(results["truth"]["events"] == 2);
  CHECK(results["truth"]["undecided_events"] == 2);
  REQUIRE(results["records"].size() == 2 * methods.size());
  bool conservative_seen = false;
  for (const json& r : results["records"]) {
    INFO(r["method"] << " dt " << r["dt"]);
    CHECK(r["events"] == 2);
    CHECK(r["undecided"] == 2);
    CHECK(r["detected"] == 0);
    CHECK(r["missed"] == 0);
    CHECK(r["initial_contacts"] == 0);
    CHECK(r["missed_fraction"] == 0.0);
    CHECK(r["self_check"]["ok"] == true);
    conservative_seen = conservative_seen || r["conservative"].get<bool>();
  }
  CHECK(conservative_seen);
  // The records pass the results reader's count check (undecided + initial + detected + missed = events).
  CHECK_NOTHROW(ccdlab::validate_results(results, "plate.json"));
  const std::string text = ccdlab::summary_text(results);
  CHECK(text.find("2 undecided events") != std::string::npos);
  CHECK(ccdlab::summary_markdown(results).find("2 undecided events") != std::string::npos);
}

TEST_CASE("the plate 5e-7 from two resting balls: no event, nothing undecided", "[runner][undecided]") {
  const ccd::Scene scene =
      ccd::test::spinning_plate_scene(ccd::Vec3(0.5, 0.5, 0.01), 10.0, 0.1, {0.1100005, -0.1100005});
  const json results = ccdlab::run_experiment(plate_experiment({"swept_aabb/brute", "sphere/grid"}), scene, quiet());
  CHECK(results["truth"]["events"] == 0);
  CHECK_FALSE(results["truth"].contains("undecided_events"));
  for (const json& r : results["records"]) {
    CHECK(r["events"] == 0);
    CHECK(r["undecided"] == 0);
    CHECK(r["missed"] == 0);
  }
  CHECK(ccdlab::summary_text(results).find("undecided") == std::string::npos);
}

}  // namespace experiments_undecided_runner_test
