// `ccdlab ccd` on the shipped hard query files: zero false negatives, results equal to the
// file's expected column (decided exactly), JSON written atomically, bad input exit 2.
#include "cli_support.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace cli_ccd_command_test {

namespace fs = std::filesystem;
using nlohmann::json;

using ccdlab::test::Folder;

namespace {

int run_ccd(const std::string& args, const Folder& dir, std::string* out = nullptr, std::string* err = nullptr) {
  return ccdlab::test::run_ccdlab("ccd " + args, dir, out, err);
}

std::string data(const std::string& name) { return std::string(CCDLAB_SOURCE_DIR) + "/data/ccd/" + name; }

}  // namespace

TEST_CASE("ccdlab ccd runs the shipped hard query files without a miss", "[cloth][cli]") {
  Folder dir;
  for (const std::string kind : {"vf", "ee"}) {
    INFO(kind);
    const std::string file = data("hard_" + kind + ".csv");
    std::string out;
    REQUIRE(run_ccd(file + " --kind " + kind + " -o " + (dir / "r.json"), dir, &out) == 0);
    CHECK(out.find("false negatives: 0\n") != std::string::npos);
    std::ifstream in(dir / "r.json");
    const json r = json::parse(in);
    CHECK(r["format"] == "ccdlab-ccd/1");
    CHECK(r["false_negatives"] == 0);
    const auto n = r["queries"].get<std::size_t>();
    CHECK(n >= 40);
    CHECK(r["results"].size() == n);
    CHECK(r["seconds"].size() == n);
    // The exact reference reproduces the expected column: zero misses and zero false positives.
    REQUIRE(run_ccd(file + " --kind " + kind + " --exact -o " + (dir / "x.json"), dir, &out) == 0);
    std::ifstream xin(dir / "x.json");
    const json x = json::parse(xin);
    CHECK(x["false_negatives"] == 0);
    CHECK(x["false_positives"] == 0);
    // The files are what --write-hard writes today.
    REQUIRE(run_ccd("--write-hard --kind " + kind + " -o " + (dir / "h.csv"), dir) == 0);
    std::ifstream a(file), b(dir / "h.csv");
    CHECK(std::string(std::istreambuf_iterator<char>(a), {}) == std::string(std::istreambuf_iterator<char>(b), {}));
  }
}

TEST_CASE("ccdlab ccd runs the shipped near-miss query files and reports why it reported contacts", "[cloth][cli]") {
  Folder dir;
  // Counts as measured (docs/cloth.md, Figures): without and with --keep-tolerance-stops.
  struct Expected {
    std::string kind;
    int false_positives, proved, exact, tolerance, budget, keep_false_positives, keep_tolerance, keep_budget;
  };
  for (const Expected& e : {Expected{"vf", 0, 81, 69, 0, 0, 16, 159, 7}, Expected{"ee", 5, 67, 78, 0, 10, 93, 194, 49}}) {
    INFO(e.kind);
    const std::string file = data("near_miss_" + e.kind + ".csv");
    std::string out;
    REQUIRE(run_ccd(file + " --kind " + e.kind + " -o " + (dir / "r.json"), dir, &out) == 0);
    CHECK(out.find("false negatives: 0\n") != std::string::npos);
    CHECK(out.find("contacts reported: " + std::to_string(e.proved) + " proved, " + std::to_string(e.exact) +
                   " decided exactly, 0 tolerance stops, " + std::to_string(e.budget) + " budget spent") !=
          std::string::npos);
    std::ifstream in(dir / "r.json");
    const json r = json::parse(in);
    CHECK(r["queries"] == 300);
    CHECK(r["false_negatives"] == 0);
    CHECK(r["false_positives"] == e.false_positives);
    CHECK(r["hits"]["proved"] == e.proved);
    CHECK(r["hits"]["exact"] == e.exact);
    CHECK(r["hits"]["tolerance"] == e.tolerance);
    CHECK(r["hits"]["budget"] == e.budget);
    CHECK(r["decided_exactly"] == e.exact);  // here every exactly decided query is a contact
    CHECK(r["options"]["keep_tolerance_stops"] == false);
    // The flag restores the kernel without its decisions: every tolerance stop a contact.
    REQUIRE(run_ccd(file + " --kind " + e.kind + " --keep-tolerance-stops -o " + (dir / "k.json"), dir, &out) == 0);
    std::ifstream kin(dir / "k.json");
    const json k = json::parse(kin);
    CHECK(k["false_negatives"] == 0);
    CHECK(k["false_positives"] == e.keep_false_positives);
    CHECK(k["hits"]["proved"] == 0);
    CHECK(k["hits"]["exact"] == 0);
    CHECK(k["hits"]["tolerance"] == e.keep_tolerance);
    CHECK(k["hits"]["budget"] == e.keep_budget);
    CHECK(k["options"]["keep_tolerance_stops"] == true);
    // The exact reference reproduces the expected column, and the files are what
    // --write-near-miss writes today.
    REQUIRE(run_ccd(file + " --kind " + e.kind + " --exact -o " + (dir / "x.json"), dir, &out) == 0);
    std::ifstream xin(dir / "x.json");
    const json x = json::parse(xin);
    CHECK(x["false_negatives"] == 0);
    CHECK(x["false_positives"] == 0);
    CHECK_FALSE(x.contains("hits"));
    REQUIRE(run_ccd("--write-near-miss --kind " + e.kind + " -o " + (dir / "n.csv"), dir) == 0);
    std::ifstream a(file), b(dir / "n.csv");
    CHECK(std::string(std::istreambuf_iterator<char>(a), {}) == std::string(std::istreambuf_iterator<char>(b), {}));
  }
  std::string err;
  CHECK(run_ccd("--write-near-miss --write-hard --kind vf -o " + (dir / "n.csv"), dir, nullptr, &err) == 2);
}

TEST_CASE("ccdlab ccd rejects bad input with exit 2 and one line", "[cloth][cli]") {
  Folder dir;
  std::string err;
  {
    std::ofstream(dir / "bad.csv") << "1,1,0,1,0,1,1\n1,1,0,1,x,1,1\n";
  }
  CHECK(run_ccd((dir / "bad.csv") + " --kind vf -o " + (dir / "r.json"), dir, nullptr, &err) == 2);
  CHECK(err == "ccdlab ccd: " + (dir / "bad.csv") + ": line 2, column 5: not a decimal integer: 'x'\n");
  CHECK_FALSE(fs::exists(dir / "r.json"));
  CHECK(run_ccd(data("hard_vf.csv") + " --kind xx", dir, nullptr, &err) == 2);
  CHECK(run_ccd(data("hard_vf.csv"), dir, nullptr, &err) == 2);
  CHECK(run_ccd(data("hard_vf.csv") + " --kind vf --separation -1", dir, nullptr, &err) == 2);
  CHECK(run_ccd((dir / "missing.csv") + " --kind vf", dir, nullptr, &err) == 2);
  CHECK(run_ccd(data("hard_vf.csv") + " --kind vf -o " + data("hard_vf.csv"), dir, nullptr, &err) == 2);
}

}  // namespace cli_ccd_command_test
