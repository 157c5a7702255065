// The summary table: per method the largest zero-miss dt, the cost at the cheapest
// zero-miss point, the missed fraction per dt; worked out by hand on a small results file.
#include "../../experiments/summary.hpp"

#include <catch2/catch.hpp>
#include <string>

using nlohmann::json;

namespace {

json record(const std::string& method, double dt, double hz, std::uint64_t missed, double fraction, double cost,
            bool conservative) {
  return {{"method", method}, {"dt", dt}, {"hz", hz}, {"missed", missed}, {"missed_fraction", fraction},
          {"seconds_per_simulated_second", cost}, {"conservative", conservative}};
}

json results() {
  json r = {{"experiment", {{"name", "gas60"}, {"hz", {30, 60, 240, 480}}}},
            {"scene", {{"bodies", 5000}, {"horizon", 1.0}}},
            {"truth", {{"events", 400}}}};
  r["records"] = json::array({
      record("aabb/sap", 1.0 / 30, 30, 40, 0.1, 0.01, false),
      record("aabb/sap", 1.0 / 60, 60, 4, 0.01, 0.02, false),
      record("aabb/sap", 1.0 / 240, 240, 0, 0.0, 0.08, false),
      record("aabb/sap", 1.0 / 480, 480, 0, 0.0, 0.16, false),
      record("capsule/sap", 1.0 / 30, 30, 0, 0.0, 0.005, true),
      record("capsule/sap", 1.0 / 60, 60, 0, 0.0, 0.004, true),  // cheaper at the smaller dt
      record("capsule/sap", 1.0 / 240, 240, 0, 0.0, 0.012, true),
      record("capsule/sap", 1.0 / 480, 480, 0, 0.0, 0.02, true),
      record("sphere/brute", 1.0 / 30, 30, 40, 0.1, 0.5, false),
  });
  return r;
}

}  // namespace

TEST_CASE("summary table: largest zero-miss dt, cheapest zero-miss cost, missed per dt", "[summary]") {
  const std::string text = ccdlab::summary_text(results());
  INFO(text);
  // Header: the timesteps as frequencies, largest dt first.
  CHECK(text.find("missed @ 30 Hz  missed @ 60 Hz  missed @ 240 Hz  missed @ 480 Hz") != std::string::npos);
  // aabb/sap: no miss from 240 Hz on, cheapest there (0.08 s/s).
  CHECK(text.find("aabb/sap") != std::string::npos);
  CHECK(text.find("240 Hz") != std::string::npos);
  CHECK(text.find("0.08 (dt 240 Hz)") != std::string::npos);
  CHECK(text.find("10%") != std::string::npos);
  // capsule/sap: conservative (*), no miss at the largest dt, cheapest at 60 Hz.
  CHECK(text.find("capsule/sap *") != std::string::npos);
  CHECK(text.find("0.004 (dt 60 Hz)") != std::string::npos);
  // sphere/brute missed at its only dt and has no entry at the others.
  CHECK(text.find("none") != std::string::npos);

  const std::string md = ccdlab::summary_markdown(results());
  CHECK(md.rfind("# Summary: gas60\n", 0) == 0);
  CHECK(md.find("| method | largest dt, no miss | cost at zero misses (s/s) | missed @ 30 Hz |") != std::string::npos);
  CHECK(md.find("| capsule/sap \\* | 30 Hz | 0.004 (dt 60 Hz) | 0 | 0 | 0 | 0 |") != std::string::npos);
  CHECK(md.find("| aabb/sap | 240 Hz | 0.08 (dt 240 Hz) | 10% | 1% | 0 | 0 |") != std::string::npos);
  CHECK(md.find("| sphere/brute | none | - | 10% |  |  |  |") != std::string::npos);
}

TEST_CASE("summary: timesteps given in seconds are labelled in seconds", "[summary]") {
  json r = results();
  r["experiment"].erase("hz");
  const std::string text = ccdlab::summary_text(r);
  INFO(text);
  CHECK(text.find("missed @ 0.0333  missed @ 0.0167  missed @ 0.00417  missed @ 0.00208") != std::string::npos);
  CHECK(text.find("Hz") == std::string::npos);
}

TEST_CASE("summary path: beside the results file", "[summary]") {
  CHECK(ccdlab::summary_path("results/default.json") == "results/default.summary.md");
  CHECK(ccdlab::summary_path("out") == "out.summary.md");
}
