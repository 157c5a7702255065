#pragma once
// What one results record counts as contacts, body-body and body-scenery together: the
// contacts to detect (the truth's events less those in progress at t = 0 and those the
// truth could not decide) and the missed ones. The summary, the missed list and the report
// (scripts/report.py, the same rule) read records through these, so a scene with a floor
// counts its floor contacts. A record without scenery (or a cloth record) reads its
// static_* fields as 0.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <tuple>

namespace ccdlab {

struct RecordContacts {
  std::uint64_t body_to_detect = 0;     ///< body-body (or cloth self-contact) events to detect
  std::uint64_t scenery_to_detect = 0;  ///< body-scenery events to detect
  std::uint64_t body_missed = 0;
  std::uint64_t scenery_missed = 0;
  std::uint64_t to_detect() const { return body_to_detect + scenery_to_detect; }
  std::uint64_t missed() const { return body_missed + scenery_missed; }
  /// missed / to_detect, 0 when there is nothing to detect.
  double missed_fraction() const { return to_detect() ? double(missed()) / double(to_detect()) : 0.0; }
};

inline RecordContacts record_contacts(const nlohmann::json& r) {
  auto count = [&](const char* key) { return r.value(key, std::uint64_t{0}); };
  auto apart = [](std::uint64_t all, std::uint64_t a, std::uint64_t b) { return all >= a + b ? all - a - b : 0; };
  RecordContacts c;
  // The body pairs' fields bare, the scenery's with "static_".
  struct Twin {
    const char* prefix;
    std::uint64_t* to_detect;
    std::uint64_t* missed;
  };
  for (const Twin& t : {Twin{"", &c.body_to_detect, &c.body_missed},
                        Twin{"static_", &c.scenery_to_detect, &c.scenery_missed}}) {
    auto field = [&](const char* name) { return count((std::string(t.prefix) + name).c_str()); };
    *t.to_detect = apart(field("events"), field("initial_contacts"), field("undecided"));
    *t.missed = field("missed");
  }
  return c;
}

}  // namespace ccdlab
