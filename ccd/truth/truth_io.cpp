#include <ccd/truth/truth_io.hpp>

#include <ccd/io/atomic_file.hpp>
#include <ccd/io/json_reader.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_io.hpp>

#include <cmath>
#include <limits>

namespace ccd {
namespace {

using nlohmann::json;

// The error fields of one event, as for body-body events (absent when zero).
void add_error_fields(json& j, const EventError& err) {
  if (err.enter_error != 0.0) j["enter_error"] = err.enter_error;
  if (err.exit_error != 0.0) j["exit_error"] = err.exit_error;
  if (err.grazing) j["grazing"] = true;
  // Read as `grazing` when absent: written whenever that would read back wrong.
  if (err.undecided || err.grazing) j["undecided"] = err.undecided;
}

json event_json(const TruthFile& t, std::size_t i) {
  const ContactEvent& e = t.events[i];
  json j = {{"a", e.a}, {"b", e.b}, {"enter", e.enter}, {"exit", e.exit}};
  if (!t.errors.empty()) add_error_fields(j, t.errors[i]);
  return j;
}

json static_event_json(const TruthFile& t, std::size_t i) {
  const StaticEvent& e = t.static_events[i];
  json j = {{"body", e.body}, {"polygon", e.polygon}, {"enter", e.enter}, {"exit", e.exit}};
  if (!t.static_errors.empty()) add_error_fields(j, t.static_errors[i]);
  return j;
}

EventError read_error_fields(const JsonReader& r, const json& e, const std::string& p) {
  EventError err;
  err.enter_error = r.optional_number(e, "enter_error", p, 0.0);
  err.exit_error = r.optional_number(e, "exit_error", p, 0.0);
  if (err.enter_error < 0.0) r.fail(p + ".enter_error", "must be >= 0");
  if (err.exit_error < 0.0) r.fail(p + ".exit_error", "must be >= 0");
  err.grazing = r.optional_bool(e, "grazing", p, false);
  err.undecided = r.optional_bool(e, "undecided", p, err.grazing);
  return err;
}

bool is_digest(const std::string& s) {
  if (s.size() != 64) return false;
  for (char c : s)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

}  // namespace

json truth_to_json(const TruthFile& t) {
  json events = json::array();
  for (std::size_t i = 0; i < t.events.size(); ++i) events.push_back(event_json(t, i));
  json j = {{"format", kTruthFormat}, {"horizon", t.horizon}, {"scene_sha256", t.scene_sha256},
            {"events", std::move(events)}};
  if (t.has_scenery) {
    json st = json::array();
    for (std::size_t i = 0; i < t.static_events.size(); ++i) st.push_back(static_event_json(t, i));
    j["static_events"] = std::move(st);
  }
  return j;
}

std::string truth_to_text(const TruthFile& t) {
  // Without a scene digest (a truth read from a version 1 file) the file is version 1:
  // version 2 requires the digest, so writing it empty would give an unreadable file.
  const bool digest = !t.scene_sha256.empty();
  std::string s = "{\"format\": \"" + std::string(digest ? kTruthFormat : kTruthFormatV1) +
                  "\", \"horizon\": " + json(t.horizon).dump() +
                  (digest ? ", \"scene_sha256\": " + json(t.scene_sha256).dump() : std::string()) + ",\n \"events\": [";
  for (std::size_t i = 0; i < t.events.size(); ++i) {
    s += i == 0 ? "\n  " : ",\n  ";
    s += event_json(t, i).dump();
  }
  s += t.events.empty() ? "]" : "\n ]";
  if (t.has_scenery) {
    s += ",\n \"static_events\": [";
    for (std::size_t i = 0; i < t.static_events.size(); ++i) {
      s += i == 0 ? "\n  " : ",\n  ";
      s += static_event_json(t, i).dump();
    }
    s += t.static_events.empty() ? "]" : "\n ]";
  }
  s += "}\n";
  return s;
}

TruthFile truth_from_json(const json& j, const std::string& file) {
  const JsonReader r{file};
  if (!j.is_object()) r.fail("", "a truth file must be a JSON object");
  const std::string format = r.string(r.require(j, "format", ""), "format");
  TruthFile t;
  if (format == kTruthFormat) {
    t.version = 2;
  } else if (format == kTruthFormatV1) {
    t.version = 1;
  } else {
    r.fail("format", std::string("must be \"") + kTruthFormat + "\" or \"" + kTruthFormatV1 + "\"");
  }
  t.horizon = r.number(r.require(j, "horizon", ""), "horizon");
  if (t.horizon <= 0.0) r.fail("horizon", "must be > 0");
  if (t.version == 2) {
    t.scene_sha256 = r.string(r.require(j, "scene_sha256", ""), "scene_sha256");
    if (!is_digest(t.scene_sha256)) r.fail("scene_sha256", "must be 64 lowercase hexadecimal digits");
  }
  const json& events = r.require(j, "events", "");
  if (!events.is_array()) r.fail("events", "must be an array");
  t.events.reserve(events.size());
  std::vector<EventError> errors;
  bool any_error = false;
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
    const EventError err = t.version == 2 ? read_error_fields(r, e, p) : EventError{};
    any_error = any_error || err != EventError{};
    errors.push_back(err);
  }
  if (any_error) t.errors = std::move(errors);
  if (j.contains("static_events")) {
    const json& st = j.at("static_events");
    if (!st.is_array()) r.fail("static_events", "must be an array");
    t.has_scenery = true;
    t.static_events.reserve(st.size());
    std::vector<EventError> static_errors;
    bool any_static_error = false;
    for (std::size_t i = 0; i < st.size(); ++i) {
      const std::string p = "static_events[" + std::to_string(i) + "]";
      const json& e = st[i];
      if (!e.is_object()) r.fail(p, "must be an object with body, polygon, enter and exit");
      StaticEvent ev;
      ev.body = r.index(r.require(e, "body", p), p + ".body");
      ev.polygon = r.index(r.require(e, "polygon", p), p + ".polygon");
      ev.enter = r.number(r.require(e, "enter", p), p + ".enter");
      ev.exit = r.number(r.require(e, "exit", p), p + ".exit");
      if (ev.enter < 0.0 || ev.enter > t.horizon) r.fail(p + ".enter", "must lie in [0, horizon]");
      if (ev.exit < ev.enter || ev.exit > t.horizon) r.fail(p + ".exit", "must lie in [enter, horizon]");
      if (!t.static_events.empty() && !static_event_order(t.static_events.back(), ev))
        r.fail(p, "static events must be sorted by (enter, body, polygon) without duplicates");
      t.static_events.push_back(ev);
      const EventError err = read_error_fields(r, e, p);
      any_static_error = any_static_error || err != EventError{};
      static_errors.push_back(err);
    }
    if (any_static_error) t.static_errors = std::move(static_errors);
  }
  return t;
}

TruthFile load_truth(const std::string& path) { return truth_from_json(read_json_file(path), path); }

void save_truth(const TruthFile& t, const std::string& path) { write_file_atomically(path, truth_to_text(t)); }

}  // namespace ccd
