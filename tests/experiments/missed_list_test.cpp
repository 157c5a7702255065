// The missed list after the summary (`ccdlab run --list-missed`): per method the largest dt
// at which it missed a contact, the rate as "N of M (P %)" split by kind, the contacts in
// order of entry, at most the given number of lines with a count of the rest.
#include "../../experiments/missed_list.hpp"

#include <catch2/catch.hpp>
#include <string>

namespace experiments_missed_list_test {

using nlohmann::json;

namespace {

json record(const std::string& method, double hz, json missed, json static_missed) {
  return {{"method", method}, {"dt", 1.0 / hz}, {"hz", hz}, {"events", 942}, {"initial_contacts", 2},
          {"undecided", 0}, {"missed", missed.size()}, {"static_events", 10}, {"static_initial_contacts", 10},
          {"static_undecided", 0}, {"static_missed", static_missed.size()}, {"missed_events", missed},
          {"static_missed_events", static_missed}};
}

json event(int a, int b, double enter, double exit) { return {{"a", a}, {"b", b}, {"enter", enter}, {"exit", exit}}; }
json floor_event(int body, int polygon, double enter, double exit) {
  return {{"body", body}, {"polygon", polygon}, {"enter", enter}, {"exit", exit}};
}

}  // namespace

TEST_CASE("missed list: the largest dt with a miss, per method, both kinds in order of entry", "[summary]") {
  json r = {{"experiment", {{"hz", {30, 60}}}}};
  r["records"] = json::array({
      record("aabb/grid", 30, json::array({event(3, 7, 0.5, 0.625)}), json::array({floor_event(4, 1, 0.25, 0.5)})),
      record("aabb/grid", 60, json::array({event(1, 2, 0.125, 0.25)}), json::array()),
      record("horn/grid", 30, json::array(), json::array()),
      record("horn/grid", 60, json::array(), json::array()),
  });
  r["records"][0]["static_events"] = 12;  // two body-scenery contacts to detect
  const std::string text = ccdlab::missed_list_text(r);
  INFO(text);
  CHECK(text.find("aabb/grid at 30 Hz: missed 2 of 942 (0.212 %): 1 body-body, 1 body-scenery\n"
                  "  body 4, scenery polygon 1: enter 0.25 s, exit 0.5 s, duration 0.25 s\n"
                  "  bodies 3 and 7: enter 0.5 s, exit 0.625 s, duration 0.125 s\n") != std::string::npos);
  CHECK(text.find("at 60 Hz") == std::string::npos);  // the largest failing dt only
  CHECK(text.find("horn/grid: missed none at any dt\n") != std::string::npos);
}

TEST_CASE("missed list: at most a screenful, then a count of the rest", "[summary]") {
  json missed = json::array();
  for (int k = 0; k < 50; ++k) missed.push_back(event(k, k + 1, k / 64.0, k / 64.0 + 0.125));
  json r = {{"experiment", json::object()}, {"records", json::array({record("aabb/sap", 10, missed, json::array())})}};
  r["records"][0]["hz"] = 0;  // the dt given in seconds
  const std::string text = ccdlab::missed_list_text(r, 20);
  INFO(text);
  CHECK(text.find("aabb/sap at 0.1 s: missed 50 of 940 (5.32 %)\n") != std::string::npos);
  CHECK(text.find("bodies 19 and 20:") != std::string::npos);
  CHECK(text.find("bodies 20 and 21:") == std::string::npos);
  CHECK(text.find("  ... and 30 more (all in the results file") != std::string::npos);
  r["records"][0].erase("missed_events");
  CHECK(ccdlab::missed_list_text(r).find("(the record lists none: run with --list-missed)") != std::string::npos);
}

}  // namespace experiments_missed_list_test
