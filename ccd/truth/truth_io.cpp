#include <ccd/truth/truth_io.hpp>

#include <ccd/io/atomic_file.hpp>
#include <ccd/io/json_reader.hpp>
#include <ccd/scene/input_error.hpp>
#include <ccd/scene/scene_io.hpp>

#include <cmath>
#include <limits>

namespace ccd {
namespace {

using nlohmann::json;

json event_json(const ContactEvent& e) { return {{"a", e.a}, {"b", e.b}, {"enter", e.enter}, {"exit", e.exit}}; }

using Reader = JsonReader;

}  // namespace

json truth_to_json(const TruthFile& t) {
  json events = json::array();
  for (const ContactEvent& e : t.events) events.push_back(event_json(e));
  return {{"format", kTruthFormat}, {"horizon", t.horizon}, {"events", std::move(events)}};
}

std::string truth_to_text(const TruthFile& t) {
  std::string s = "{\"format\": \"" + std::string(kTruthFormat) + "\", \"horizon\": " + json(t.horizon).dump() +
                  ",\n \"events\": [";
  for (std::size_t i = 0; i < t.events.size(); ++i) {
    s += i == 0 ? "\n  " : ",\n  ";
    s += event_json(t.events[i]).dump();
  }
  s += t.events.empty() ? "]}\n" : "\n ]}\n";
  return s;
}

TruthFile truth_from_json(const json& j, const std::string& file) {
  Reader r{file};
  if (!j.is_object()) r.fail("", "a truth file must be a JSON object");
  const json& format = r.require(j, "format", "");
  if (!format.is_string() || format.get<std::string>() != kTruthFormat)
    r.fail("format", std::string("must be \"") + kTruthFormat + "\"");
  TruthFile t;
  t.horizon = r.number(r.require(j, "horizon", ""), "horizon");
  if (t.horizon <= 0.0) r.fail("horizon", "must be > 0");
  const json& events = r.require(j, "events", "");
  if (!events.is_array()) r.fail("events", "must be an array");
  t.events.reserve(events.size());
  for (std::size_t i = 0; i < events.size(); ++i) {
    const std::string p = "events[" + std::to_string(i) + "]";
    const json& e = events[i];
    if (!e.is_object()) r.fail(p, "must be an object with a, b, enter and exit");
    ContactEvent ev;
    ev.a = r.index(r.require(e, "a", p), p + ".a");
    ev.b = r.index(r.require(e, "b", p), p + ".b");
    ev.enter = r.number(r.require(e, "enter", p), p + ".enter");
    ev.exit = r.number(r.require(e, "exit", p), p + ".exit");
    if (ev.a >= ev.b) r.fail(p + ".b", "must be greater than a");
    if (ev.enter < 0.0 || ev.enter > t.horizon) r.fail(p + ".enter", "must lie in [0, horizon]");
    if (ev.exit < ev.enter || ev.exit > t.horizon) r.fail(p + ".exit", "must lie in [enter, horizon]");
    if (!t.events.empty() && !event_order(t.events.back(), ev))
      r.fail(p, "events must be sorted by (enter, a, b) without duplicates");
    t.events.push_back(ev);
  }
  return t;
}

TruthFile load_truth(const std::string& path) { return truth_from_json(read_json_file(path), path); }

void save_truth(const TruthFile& t, const std::string& path) { write_file_atomically(path, truth_to_text(t)); }

}  // namespace ccd
