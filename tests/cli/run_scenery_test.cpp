// `ccdlab run` on a scene with a floor (floor_ramp): the printed summary, the Markdown
// summary and the missed list after it count the body-scenery contacts with the
// body-body ones. At 60 Hz aabb/grid misses no body-body contact but floor contacts, so
// its zero-miss frontier is 120 Hz, not 60 Hz.
#include "cli_support.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace cli_run_scenery_test {

using ccdlab::test::Folder;
using ccdlab::test::run_ccdlab;
using ccdlab::test::slurp;
using nlohmann::json;

namespace {

// The cells of the first line of `text` that starts with `method` and two spaces.
std::vector<std::string> row(const std::string& text, const std::string& method) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(method + "  ", 0) != 0) continue;
    std::vector<std::string> cells;  // apart by two spaces or more
    for (std::size_t i = 0; i < line.size();) {
      const std::size_t gap = line.find("  ", i);
      cells.push_back(line.substr(i, gap - i));
      if (gap == std::string::npos) break;
      i = line.find_first_not_of(' ', gap);
    }
    return cells;
  }
  return {};
}

}  // namespace

TEST_CASE("ccdlab run: floor contacts count in the summary and the missed list", "[run][cli][scenery]") {
  const Folder dir;
  std::ofstream(dir / "e.json") << json{{"format", "ccdlab-experiment/1"},
                                        {"name", "floor"},
                                        {"scene", {{"generator", "floor_ramp"}}},
                                        {"hz", {60, 120}},
                                        {"methods", {"aabb/grid", "swept_aabb/grid"}}}
                                       .dump();
  std::string out;
  REQUIRE(run_ccdlab("run " + dir / "e.json" + " -o " + dir / "r.json" + " --quiet --list-missed --threads 2", dir,
                     &out) == 0);
  const json results = json::parse(slurp(dir / "r.json"));
  const json& at60 = results["records"][0];
  REQUIRE(at60["method"] == "aabb/grid");
  REQUIRE(at60["hz"] == 60.0);
  // The case this test is about: no body-body miss at 60 Hz, floor contacts missed there.
  REQUIRE(at60["missed"] == 0);
  const std::uint64_t floor_missed = at60["static_missed"].get<std::uint64_t>();
  REQUIRE(floor_missed > 0);
  INFO(out);
  // The terminal summary: aabb/grid's frontier is 120 Hz; the contacts of each kind said.
  CHECK(out.find("contacts to detect: 1535 (1023 body-body, 512 body-scenery); 1000 in progress at t = 0 apart\n") !=
        std::string::npos);
  const std::vector<std::string> answer = row(out, "aabb/grid");
  REQUIRE(answer.size() == 4);
  CHECK(answer[1] == "120");
  CHECK(row(out, "swept_aabb/grid *").at(1) == "60");
  const std::string md = slurp(dir / "r.summary.md");
  CHECK(md.find("| aabb/grid | 120 | ") != std::string::npos);
  // The missed list: aabb/grid at 60 Hz, all its misses body-scenery, each named.
  CHECK(out.find("aabb/grid at 60 Hz: missed " + std::to_string(floor_missed) + " of 1535 (") != std::string::npos);
  CHECK(out.find("): 0 body-body, " + std::to_string(floor_missed) + " body-scenery\n") != std::string::npos);
  CHECK(out.find(", scenery polygon ") != std::string::npos);
  CHECK(out.find("swept_aabb/grid: missed none at any dt\n") != std::string::npos);
  // Every record lists its body-scenery misses: as many as it counts, in order of entry.
  for (const json& r : results["records"]) {
    REQUIRE(r.contains("static_missed_events"));
    CHECK(r["static_missed_events"].size() == r["static_missed"].get<std::size_t>());
    double previous = 0.0;
    for (const json& m : r["static_missed_events"]) {
      CHECK(m["body"].get<std::uint32_t>() < 1000);
      CHECK(m["polygon"].get<std::uint32_t>() < 5);
      CHECK(m["enter"].get<double>() >= previous);
      CHECK(m["exit"].get<double>() >= m["enter"].get<double>());
      previous = m["enter"].get<double>();
    }
  }
}

}  // namespace cli_run_scenery_test
