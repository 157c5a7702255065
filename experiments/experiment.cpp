#include "experiment.hpp"

#include "method.hpp"
#include "../generators/registry.hpp"

#include <ccd/io/utf8_text.hpp>
#include <ccd/io/json_reader.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_io.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <functional>
#include <stdexcept>

namespace ccdlab {
namespace {

using nlohmann::json;
using ccd::JsonReader;

double positive_number(const JsonReader& r, const json& v, const std::string& field) {
  const double x = r.number(v, field);
  if (x <= 0.0) r.fail(field, "must be a finite number > 0");
  return x;
}

// A list of positive numbers, or {"from", "to", "count", "spacing"} (field: "dt" or "hz").
std::vector<double> parse_values(const JsonReader& r, const json& j, const std::string& field) {
  std::vector<double> values;
  if (j.is_array()) {
    if (j.empty()) r.fail(field, "must not be empty");
    for (std::size_t i = 0; i < j.size(); ++i)
      values.push_back(positive_number(r, j[i], field + "[" + std::to_string(i) + "]"));
  } else if (j.is_object()) {
    r.only_fields(j, field, {"from", "to", "count", "spacing"});
    const double from = positive_number(r, r.require(j, "from", field), field + ".from");
    const double to = positive_number(r, r.require(j, "to", field), field + ".to");
    const auto count = static_cast<int>(r.integer(r.require(j, "count", field), field + ".count", 1, 100000));
    std::string spacing = "log";
    if (j.contains("spacing")) {
      spacing = r.string(j["spacing"], field + ".spacing");
      if (spacing != "log" && spacing != "linear") r.fail(field + ".spacing", "must be \"log\" or \"linear\"");
    }
    if (count == 1) {
      values.push_back(from);
    } else {
      for (int i = 0; i < count; ++i) {
        const double f = double(i) / double(count - 1);
        double x = spacing == "log" ? std::exp(std::log(from) + f * (std::log(to) - std::log(from)))
                                    : from + f * (to - from);
        if (i == 0) x = from;
        if (i == count - 1) x = to;  // endpoints exactly as written
        values.push_back(x);
      }
    }
  } else {
    r.fail(field, "must be an array of numbers or {\"from\", \"to\", \"count\", \"spacing\"}");
  }
  return values;
}

// The timesteps of "dt" (seconds) and "hz" (frequencies, dt = 1 / hz), sorted by dt
// descending, each dt once; a dt given both ways keeps its frequency as written.
void parse_timesteps(const JsonReader& r, const json& j, Experiment& e) {
  struct Step {
    double dt, hz;
    bool from_hz;
  };
  std::vector<Step> steps;
  if (j.contains("dt"))
    for (double dt : parse_values(r, j["dt"], "dt")) steps.push_back({dt, 1.0 / dt, false});
  if (j.contains("hz"))
    for (double hz : parse_values(r, j["hz"], "hz")) {
      if (!(1.0 / hz > 0.0)) r.fail("hz", "frequency " + json(hz).dump() + " is too high (1 / hz is 0)");
      steps.push_back({1.0 / hz, hz, true});
    }
  if (steps.empty()) r.fail("dt", "missing required field (or give frequencies as \"hz\")");
  std::stable_sort(steps.begin(), steps.end(), [](const Step& x, const Step& y) {
    return x.dt != y.dt ? x.dt > y.dt : x.from_hz > y.from_hz;
  });
  for (const Step& s : steps) {
    if (!e.dt.empty() && e.dt.back() == s.dt) continue;  // the first of equal dts: from hz if any
    e.dt.push_back(s.dt);
    e.hz.push_back(s.hz);
    e.hz_given.push_back(s.from_hz);
  }
}

}  // namespace

std::string experiment_name(const json& j, const std::string& file, const std::string& fallback) {
  const JsonReader r{file};
  const auto plain = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-'; };
  std::string name;
  if (j.contains("name")) {
    name = r.string(j["name"], "name");
    // The name becomes a file name (results/NAME.json): never a path.
    if (name.empty() || name.size() > 200 || name.front() == '.' || name.front() == '-' ||
        !std::all_of(name.begin(), name.end(), plain))
      r.fail("name", "'" + name + "' is not a plain file name: 1 to 200 letters, digits, '.', '_' or '-', not "
                     "starting with '.' or '-' (the default results file is results/NAME.json)");
  } else {
    // The file's stem, with anything but letters, digits, '.', '_' and '-' made '_'.
    name = std::filesystem::path(file).stem().string().substr(0, 200);
    for (char& c : name)
      if (!plain(c)) c = '_';
    if (name.empty()) name = fallback;
    if (name.front() == '.' || name.front() == '-') name.front() = '_';
  }
  return name;
}

Experiment experiment_from_json(const json& j, const std::string& file) {
  const JsonReader r{file};
  if (!j.is_object()) r.fail("", "an experiment must be a JSON object");
  if (r.string(r.require(j, "format", ""), "format") != "ccdlab-experiment/1")
    r.fail("format", "must be \"ccdlab-experiment/1\"");
  r.only_fields(j, "", {"format", "name", "description", "scene", "dt", "hz", "methods", "acceleration_bound",
                        "repeats", "list_missed"});
  Experiment e;
  e.name = experiment_name(j, file, "experiment");
  const json& scene = r.require(j, "scene", "");
  if (scene.is_string()) {
    e.scene_path = scene.get<std::string>();
    if (e.scene_path.empty()) r.fail("scene", "must not be empty");
  } else if (scene.is_object()) {
    if (!scene.contains("generator") || !scene["generator"].is_string())
      r.fail("scene.generator", "missing required field (a generator name)");
    const Generator* gen = nullptr;
    try {
      gen = &generator_named(scene["generator"].get<std::string>());
    } catch (const std::invalid_argument& err) {
      r.fail("scene.generator", err.what());
    }
    std::vector<std::string_view> known{"generator"};
    for (const ParameterSpec& p : gen->parameters) known.push_back(p.name);
    r.only_fields(scene, "scene", known);
    e.scene_generator = scene;
    e.scene_generator.erase("comment");
  } else {
    r.fail("scene", "must be a scene file path or {\"generator\": NAME, ...}");
  }
  parse_timesteps(r, j, e);
  const json& methods = r.require(j, "methods", "");
  if (!methods.is_array() || methods.empty()) r.fail("methods", "must be a non-empty array of method names");
  std::vector<json> identities;  // each method resolved, parallel to e.methods
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const std::string field = "methods[" + std::to_string(i) + "]";
    if (!methods[i].is_string()) r.fail(field, "must be a string BOUND/BROADPHASE[@SCHEDULER]");
    MethodSpec m;
    try {
      m = parse_method(methods[i].get<std::string>());
    } catch (const std::invalid_argument& err) {
      r.fail(field, err.what());
    }
    // Compared as resolved, every option filled in: "horn/grid", "horn:4/grid" and
    // "horn:04/grid" are one method, spelled three ways.
    json resolved = {std::string(m.bound.info->name), m.bound.options.to_json(), std::string(m.broad_phase.info->name),
                     m.broad_phase.options.to_json(), std::string(m.scheduler.info->name),
                     m.scheduler.options.to_json()};
    const auto first = std::find(identities.begin(), identities.end(), resolved);
    if (first != identities.end())
      r.fail(field, "method '" + m.name + "' is the same method as methods[" +
                        std::to_string(first - identities.begin()) + "] ('" +
                        e.methods[static_cast<std::size_t>(first - identities.begin())].name + "')");
    identities.push_back(std::move(resolved));
    e.methods.push_back(std::move(m));
  }
  if (j.contains("acceleration_bound") && !j["acceleration_bound"].is_null()) {
    e.acceleration_bound = r.number(j["acceleration_bound"], "acceleration_bound");
    if (e.acceleration_bound < 0.0 || e.acceleration_bound > ccd::kMaxSceneMagnitude)
      r.fail("acceleration_bound", "must be a number in [0, 1e+30]");
  }
  if (j.contains("repeats")) e.repeats = static_cast<int>(r.integer(j["repeats"], "repeats", 1, 1000));
  if (j.contains("description")) r.string(j["description"], "description");
  e.list_missed = r.optional_bool(j, "list_missed", "", false);
  e.source = j;
  return e;
}

Experiment load_experiment(const std::string& path) {
  Experiment e = experiment_from_json(ccd::read_json_file(path), path);
  if (!e.scene_path.empty()) {
    std::filesystem::path p(e.scene_path);
    if (p.is_relative()) p = std::filesystem::path(path).parent_path() / p;
    e.scene_path = p.lexically_normal().string();
  }
  return e;
}

void check_dt_against_horizon(const Experiment& e, double horizon, const std::string& file) {
  auto text = [](double x) { return json(x).dump(); };
  for (std::size_t i = 0; i < e.dt.size(); ++i) {
    if (e.dt[i] > horizon)
      throw ccd::InputError(file, "dt", "timestep " + text(e.dt[i]) + " is larger than the scene's horizon " + text(horizon));
    if (horizon / e.dt[i] > kMaxStepsPerJob)
      throw ccd::InputError(
          file, "dt",
          "timestep " + text(e.dt[i]) + " is below what the horizon " + text(horizon) +
               " can resolve: more than 2^52 steps, where consecutive sample times k dt are no longer distinct "
               "(smallest dt: horizon * 2^-52 = " + text(horizon * 0x1p-52) + ")");
  }
}

double steps_per_job(double horizon, double dt) {
  // As the runner counts them: samples k = 0 .. floor(T / dt), or the steps between them
  // plus the last partial one: at most floor(T / dt) + 1 either way.
  return std::floor(horizon / dt) + 1.0;
}

double experiment_work(const Experiment& e, std::size_t bodies, double horizon, int shard_index, int shard_count) {
  double work = 0.0;
  for (std::size_t m = 0; m < e.methods.size(); ++m)
    for (std::size_t d = 0; d < e.dt.size(); ++d) {
      const std::size_t job = m * e.dt.size() + d;
      if (static_cast<int>(job % static_cast<std::size_t>(shard_count)) != shard_index - 1) continue;
      work += steps_per_job(horizon, e.dt[d]) * static_cast<double>(bodies) * e.repeats;
    }
  return work;
}

json experiment_to_json(const Experiment& e) {
  json j = e.source;
  j["format"] = "ccdlab-experiment/1";
  j["name"] = e.name;
  if (!e.scene_path.empty()) j["scene"] = ccd::escape_invalid_utf8(e.scene_path); else j["scene"] = e.scene_generator;
  j["dt"] = e.dt;
  json hz = json::array();
  for (std::size_t i = 0; i < e.dt.size(); ++i)
    if (e.hz_given[i]) hz.push_back(e.hz[i]);
  if (hz.empty()) j.erase("hz"); else j["hz"] = hz;
  j["list_missed"] = e.list_missed;
  j["methods"] = method_names(e.methods);
  j["acceleration_bound"] = e.acceleration_bound < 0 ? json(nullptr) : json(e.acceleration_bound);
  j["repeats"] = e.repeats;
  return j;
}

}  // namespace ccdlab
