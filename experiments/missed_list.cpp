#include "missed_list.hpp"

#include "record_contacts.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace ccdlab {
namespace {

using nlohmann::json;

std::string number(double x, const char* format) {
  char text[48];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

// "2 of 940 (0.213 %)".
std::string rate(std::uint64_t missed, std::uint64_t of) {
  return std::to_string(missed) + " of " + std::to_string(of) + " (" +
         number(of ? 100.0 * double(missed) / double(of) : 0.0, "%.3g") + " %)";
}

struct Missed {
  double enter = 0.0, exit = 0.0;
  std::string who;  // "bodies 3 and 7" or "body 3, scenery polygon 1"
};

// The missed contacts a record lists, body-body and body-scenery, in order of entry.
std::vector<Missed> listed(const json& r) {
  std::vector<Missed> out;
  if (const auto m = r.find("missed_events"); m != r.end() && m->is_array())
    for (const json& e : *m)
      out.push_back({e.value("enter", 0.0), e.value("exit", 0.0),
                     "bodies " + std::to_string(e.value("a", 0)) + " and " + std::to_string(e.value("b", 0))});
  if (const auto m = r.find("static_missed_events"); m != r.end() && m->is_array())
    for (const json& e : *m)
      out.push_back({e.value("enter", 0.0), e.value("exit", 0.0),
                     "body " + std::to_string(e.value("body", 0)) + ", scenery polygon " +
                         std::to_string(e.value("polygon", 0))});
  std::stable_sort(out.begin(), out.end(), [](const Missed& x, const Missed& y) { return x.enter < y.enter; });
  return out;
}

// The dt as the experiment gave it: "60 Hz" or "0.1 s".
std::string dt_text(const json& results, const json& r) {
  const double hz = r.value("hz", 0.0);
  if (const auto e = results.find("experiment"); hz > 0.0 && e != results.end() && e->contains("hz"))
    for (const json& h : (*e)["hz"])
      if (h.get<double>() == hz) return number(hz, "%g") + " Hz";
  return number(r.at("dt").get<double>(), "%.3g") + " s";
}

}  // namespace

std::string missed_list_text(const json& results, std::size_t max_lines) {
  // Per method (in order of first record), its record at the largest dt with a miss.
  std::vector<std::string> methods;
  std::vector<const json*> worst;
  for (const json& r : results.at("records")) {
    const std::string m = r.at("method").get<std::string>();
    auto it = std::find(methods.begin(), methods.end(), m);
    if (it == methods.end()) {
      methods.push_back(m);
      worst.push_back(nullptr);
      it = methods.end() - 1;
    }
    const json*& w = worst[static_cast<std::size_t>(it - methods.begin())];
    if (record_contacts(r).missed() > 0 && (!w || r.at("dt").get<double>() > w->at("dt").get<double>())) w = &r;
  }
  const auto failing = static_cast<std::size_t>(std::count_if(worst.begin(), worst.end(), [](const json* w) { return w; }));
  const std::size_t share = failing ? std::max<std::size_t>(1, max_lines / failing) : 0;
  std::string out = "Missed contacts, per method at the largest dt at which it missed one:\n";
  for (std::size_t i = 0; i < methods.size(); ++i) {
    if (!worst[i]) {
      out += methods[i] + ": missed none at any dt\n";
      continue;
    }
    const json& r = *worst[i];
    const RecordContacts c = record_contacts(r);
    out += methods[i] + " at " + dt_text(results, r) + ": missed " + rate(c.missed(), c.to_detect());
    if (c.scenery_to_detect) out += ": " + std::to_string(c.body_missed) + " body-body, " + std::to_string(c.scenery_missed) + " body-scenery";
    out += "\n";
    const std::vector<Missed> list = listed(r);
    if (list.empty()) {
      out += "  (the record lists none: run with --list-missed)\n";
      continue;
    }
    const std::size_t shown = std::min(list.size(), share);
    for (std::size_t k = 0; k < shown; ++k)
      out += "  " + list[k].who + ": enter " + number(list[k].enter, "%.6g") + " s, exit " +
             number(list[k].exit, "%.6g") + " s, duration " + number(list[k].exit - list[k].enter, "%.3g") + " s\n";
    if (shown < list.size())
      out += "  ... and " + std::to_string(list.size() - shown) +
             " more (all in the results file: the record's missed_events and static_missed_events)\n";
  }
  return out;
}

}  // namespace ccdlab
