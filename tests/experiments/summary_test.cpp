// The summary table: the contacts to detect (body-body and body-scenery), per method the
// zero-miss frontier and the cheapest zero-miss cost at or below it, the missed contacts
// per dt; worked out by hand on small results files.
#include "../../experiments/summary.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace experiments_summary_test {

using nlohmann::json;

namespace {

// A record of a scene with 400 body-body events (none in progress at t = 0) and no scenery.
json record(const std::string& method, double dt, double hz, std::uint64_t missed, double cost, bool conservative) {
  return {{"method", method}, {"dt", dt}, {"hz", hz}, {"events", 400}, {"initial_contacts", 0}, {"undecided", 0},
          {"missed", missed}, {"missed_fraction", double(missed) / 400.0}, {"seconds_per_simulated_second", cost},
          {"conservative", conservative}};
}

json results() {
  json r = {{"experiment", {{"name", "gas60"}, {"hz", {30, 60, 240, 480}}}},
            {"scene", {{"bodies", 5000}, {"horizon", 1.0}}},
            {"truth", {{"events", 400}}}};
  r["records"] = json::array({
      record("aabb/sap", 1.0 / 30, 30, 40, 0.01, false),
      record("aabb/sap", 1.0 / 60, 60, 4, 0.02, false),
      record("aabb/sap", 1.0 / 240, 240, 0, 0.08, false),
      record("aabb/sap", 1.0 / 480, 480, 0, 0.16, false),
      record("capsule/sap", 1.0 / 30, 30, 0, 0.005, true),
      record("capsule/sap", 1.0 / 60, 60, 0, 0.004, true),  // cheaper at the smaller dt
      record("capsule/sap", 1.0 / 240, 240, 0, 0.012, true),
      record("capsule/sap", 1.0 / 480, 480, 0, 0.02, true),
      record("sphere/brute", 1.0 / 30, 30, 40, 0.5, false),
  });
  return r;
}

using Row = std::vector<std::string>;

// The rows of the plain-text tables that start with `method` (the answer's row first, then
// the missed table's), each split into its cells (columns are apart by two spaces or more).
std::vector<Row> rows_of(const std::string& text, const std::string& method) {
  std::vector<Row> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(method + "  ", 0) != 0 && line.rfind(method + " *  ", 0) != 0) continue;
    Row row;
    for (std::size_t i = 0; i < line.size();) {
      const std::size_t gap = line.find("  ", i);
      row.push_back(line.substr(i, gap - i));
      if (gap == std::string::npos) break;
      i = line.find_first_not_of(' ', gap);
    }
    out.push_back(row);
  }
  return out;
}

// The widest line of `text`.
std::size_t widest(const std::string& text) {
  std::istringstream in(text);
  std::size_t w = 0;
  for (std::string line; std::getline(in, line);) w = std::max(w, line.size());
  return w;
}

}  // namespace

TEST_CASE("summary table: zero-miss frontier, cheapest zero-miss cost, missed per dt", "[summary]") {
  const std::string text = ccdlab::summary_text(results());
  INFO(text);
  CHECK(text.rfind("contacts to detect: 400\n", 0) == 0);  // no scenery: no split by kind
  // The answer: one unit per column, the frontier and the cheapest point in Hz, the cost in s/s.
  CHECK(text.find("\nmethod         largest dt, no miss (Hz)  cheapest zero-miss cost (s/s)  at dt (Hz)\n") !=
        std::string::npos);
  // aabb/sap: no miss from 240 Hz on, cheapest there (0.08 s/s).
  CHECK(rows_of(text, "aabb/sap") == std::vector<Row>{{"aabb/sap", "240", "0.08", "240"},
                                                      {"aabb/sap", "40 (10 %)", "4 (1 %)", "0", "0"}});
  // capsule/sap: conservative at every dt (*), no miss at the largest dt, cheapest at 60 Hz.
  CHECK(rows_of(text, "capsule/sap") == std::vector<Row>{{"capsule/sap *", "30", "0.004", "60"},
                                                         {"capsule/sap *", "0", "0", "0", "0"}});
  // sphere/brute missed at its only dt: no frontier, blank where it did not run.
  CHECK(rows_of(text, "sphere/brute") == std::vector<Row>{{"sphere/brute", "none", "-", "-"},
                                                          {"sphere/brute", "40 (10 %)"}});
  // The missed contacts per dt, largest dt first, as counts with the percentage of the 400;
  // numbers right-aligned under their heading.
  CHECK(text.find("\nmissed contacts (of 400) at each dt (Hz)\n"
                  "method         missed @ 30 Hz  missed @ 60 Hz  missed @ 240 Hz  missed @ 480 Hz\n"
                  "aabb/sap            40 (10 %)         4 (1 %)                0                0\n") !=
        std::string::npos);
  CHECK(widest(text) <= ccdlab::kSummaryWidth);

  const std::string md = ccdlab::summary_markdown(results());
  CHECK(md.rfind("# Summary: gas60\n", 0) == 0);
  CHECK(md.find("| method | largest dt, no miss (Hz) | cheapest zero-miss cost (s/s) | at dt (Hz) |") !=
        std::string::npos);
  CHECK(md.find("| capsule/sap \\* | 30 | 0.004 | 60 |") != std::string::npos);
  CHECK(md.find("| aabb/sap | 240 | 0.08 | 240 |") != std::string::npos);
  CHECK(md.find("| sphere/brute | none | - | - |") != std::string::npos);
  CHECK(md.find("| method | missed @ 30 Hz | missed @ 60 Hz | missed @ 240 Hz | missed @ 480 Hz |") !=
        std::string::npos);
  CHECK(md.find("| aabb/sap | 40 (10 %) | 4 (1 %) | 0 | 0 |") != std::string::npos);
  CHECK(md.find("| sphere/brute | 40 (10 %) |  |  |  |") != std::string::npos);
}

TEST_CASE("summary: body-scenery contacts are counted with the body-body ones", "[summary]") {
  // floor_ramp's shape: no body-body miss at 60 Hz, but floor contacts missed there.
  json r = results();
  r["records"] = json::array();
  for (auto [hz, missed, static_missed] : {std::tuple{30.0, 7, 304}, {60.0, 0, 107}, {240.0, 0, 0}, {480.0, 0, 0}}) {
    json rec = record("aabb/grid", 1.0 / hz, hz, static_cast<std::uint64_t>(missed), 0.1 * hz / 30, false);
    rec["events"] = 1023;
    rec["static_events"] = 1512;
    rec["static_initial_contacts"] = 1000;
    rec["static_undecided"] = 0;
    rec["static_missed"] = static_missed;
    r["records"].push_back(rec);
  }
  const std::string text = ccdlab::summary_text(r);
  INFO(text);
  CHECK(text.rfind("contacts to detect: 1535 (1023 body-body, 512 body-scenery); 1000 in progress at t = 0 apart\n",
                   0) == 0);
  // The frontier is 240 Hz, not 60 Hz: 107 floor contacts are missed at 60 Hz.
  CHECK(rows_of(text, "aabb/grid") ==
        std::vector<Row>{{"aabb/grid", "240", "0.8", "240"}, {"aabb/grid", "311 (20.3 %)", "107 (6.97 %)", "0", "0"}});
  CHECK(text.find("311 (20.3 %)") != std::string::npos);
  CHECK(text.find("107 (6.97 %)") != std::string::npos);
  const std::string md = ccdlab::summary_markdown(r);
  CHECK(md.find("| aabb/grid | 240 | 0.8 | 240 |") != std::string::npos);
  CHECK(md.find("| aabb/grid | 311 (20.3 %) | 107 (6.97 %) | 0 | 0 |") != std::string::npos);
}

TEST_CASE("summary: the star needs every record of the method conservative", "[summary]") {
  json r = results();
  r["records"][5]["conservative"] = false;  // capsule/sap at 60 Hz (velocity changes off step starts)
  r["records"][5]["missed"] = 2;
  const std::string text = ccdlab::summary_text(r);
  INFO(text);
  CHECK(text.find("capsule/sap *") == std::string::npos);
  CHECK(text.find("\ncapsule/sap: no star: conservative as it ran at dt (Hz) 30, 240, 480, not at 60\n") !=
        std::string::npos);
  // The frontier stops above the miss at 60 Hz: 240 Hz, cheapest there.
  CHECK(rows_of(text, "capsule/sap").front() == Row{"capsule/sap", "240", "0.012", "240"});
  CHECK(ccdlab::summary_markdown(r).find("| capsule/sap | 240 | 0.012 | 240 |") != std::string::npos);
}

TEST_CASE("summary: no line is wider than 100 columns, however many timesteps", "[summary]") {
  json r = results();
  r["experiment"]["hz"] = json::array();
  r["records"] = json::array();
  for (int k = 0; k < 12; ++k) {
    const double hz = 30.0 * (k + 1);
    r["experiment"]["hz"].push_back(hz);
    r["records"].push_back(record("swept_aabb:pieces=4/hgrid", 1.0 / hz, hz, 390 - static_cast<std::uint64_t>(k), 1.5, false));
    r["records"].back()["undecided"] = 3;  // a long note, wrapped
  }
  r["records"][1]["conservative"] = true;  // conservative at one dt only: a note naming it
  const std::string text = ccdlab::summary_text(r);
  INFO(text);
  CHECK(widest(text) <= ccdlab::kSummaryWidth);
  CHECK(widest(text) > 60);
  CHECK(text.find("swept_aabb:pieces=4/hgrid: no star: conservative as it ran at dt (Hz) 60, not at 30, 90,") !=
        std::string::npos);
  CHECK(text.find("3 undecided events") != std::string::npos);  // the blocks are filled, not one column each
  for (int k = 0; k < 12; ++k) CHECK(text.find("missed @ " + std::to_string(30 * (k + 1)) + " Hz") != std::string::npos);
  CHECK(text.find("missed contacts (of 397) at each dt (Hz)") != std::string::npos);
  CHECK(text.find("379 (95.5 %)") != std::string::npos);  // the last column, in a later block
}

TEST_CASE("summary: timesteps given in seconds are labelled in seconds", "[summary]") {
  json r = results();
  r["experiment"].erase("hz");
  const std::string text = ccdlab::summary_text(r);
  INFO(text);
  CHECK(text.find("missed @ 0.0333  missed @ 0.0167  missed @ 0.00417  missed @ 0.00208") != std::string::npos);
  CHECK(text.find("largest dt, no miss (s)") != std::string::npos);
  CHECK(rows_of(text, "aabb/sap").front() == Row{"aabb/sap", "0.00417", "0.08", "0.00417"});
  CHECK(text.find("Hz") == std::string::npos);
}

TEST_CASE("summary path: beside the results file", "[summary]") {
  CHECK(ccdlab::summary_path("results/default.json") == "results/default.summary.md");
  CHECK(ccdlab::summary_path("out") == "out.summary.md");
}

}  // namespace experiments_summary_test
