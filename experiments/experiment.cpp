#include "experiment.hpp"

#include "method.hpp"

#include <ccd/io/json_reader.hpp>
#include <ccd/scene/input_error.hpp>
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

std::vector<double> parse_dt(const JsonReader& r, const json& j) {
  std::vector<double> dt;
  if (j.is_array()) {
    if (j.empty()) r.fail("dt", "must not be empty");
    for (std::size_t i = 0; i < j.size(); ++i) dt.push_back(positive_number(r, j[i], "dt[" + std::to_string(i) + "]"));
  } else if (j.is_object()) {
    const double from = positive_number(r, r.require(j, "from", "dt"), "dt.from");
    const double to = positive_number(r, r.require(j, "to", "dt"), "dt.to");
    const auto count = static_cast<int>(r.integer(r.require(j, "count", "dt"), "dt.count", 1, 100000));
    std::string spacing = "log";
    if (j.contains("spacing")) {
      spacing = r.string(j["spacing"], "dt.spacing");
      if (spacing != "log" && spacing != "linear") r.fail("dt.spacing", "must be \"log\" or \"linear\"");
    }
    if (count == 1) {
      dt.push_back(from);
    } else {
      for (int i = 0; i < count; ++i) {
        const double f = double(i) / double(count - 1);
        double x = spacing == "log" ? std::exp(std::log(from) + f * (std::log(to) - std::log(from)))
                                    : from + f * (to - from);
        if (i == 0) x = from;
        if (i == count - 1) x = to;  // endpoints exactly as written
        dt.push_back(x);
      }
    }
  } else {
    r.fail("dt", "must be an array of numbers or {\"from\", \"to\", \"count\", \"spacing\"}");
  }
  std::sort(dt.begin(), dt.end(), std::greater<>());
  dt.erase(std::unique(dt.begin(), dt.end()), dt.end());
  return dt;
}

}  // namespace

Experiment experiment_from_json(const json& j, const std::string& file) {
  const JsonReader r{file};
  if (!j.is_object()) r.fail("", "an experiment must be a JSON object");
  if (r.string(r.require(j, "format", ""), "format") != "ccdlab-experiment/1")
    r.fail("format", "must be \"ccdlab-experiment/1\"");
  Experiment e;
  if (j.contains("name")) {
    e.name = r.string(j["name"], "name");
    // The name becomes a file name (results/NAME.json): never a path.
    if (e.name.empty() || e.name.size() > 200 || e.name.front() == '.' || e.name.front() == '-' ||
        !std::all_of(e.name.begin(), e.name.end(), [](char c) {
          return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
        }))
      r.fail("name", "'" + e.name + "' is not a plain file name: 1 to 200 letters, digits, '.', '_' or '-', not "
                     "starting with '.' or '-' (the default results file is results/NAME.json)");
  } else {
    // The file's stem, with anything but letters, digits, '.', '_' and '-' made '_'.
    e.name = std::filesystem::path(file).stem().string().substr(0, 200);
    for (char& c : e.name)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-')) c = '_';
    if (e.name.empty()) e.name = "experiment";
    if (e.name.front() == '.' || e.name.front() == '-') e.name.front() = '_';
  }
  const json& scene = r.require(j, "scene", "");
  if (scene.is_string()) {
    e.scene_path = scene.get<std::string>();
    if (e.scene_path.empty()) r.fail("scene", "must not be empty");
  } else if (scene.is_object()) {
    if (!scene.contains("generator") || !scene["generator"].is_string())
      r.fail("scene.generator", "missing required field (a generator name)");
    e.scene_generator = scene;
  } else {
    r.fail("scene", "must be a scene file path or {\"generator\": NAME, ...}");
  }
  e.dt = parse_dt(r, r.require(j, "dt", ""));
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
                        e.methods[static_cast<std::size_t>(first - identities.begin())] + "')");
    identities.push_back(std::move(resolved));
    e.methods.push_back(m.name);
  }
  if (j.contains("acceleration_bound") && !j["acceleration_bound"].is_null()) {
    e.acceleration_bound = r.number(j["acceleration_bound"], "acceleration_bound");
    if (e.acceleration_bound < 0.0 || e.acceleration_bound > ccd::kMaxSceneMagnitude)
      r.fail("acceleration_bound", "must be a number in [0, 1e+30]");
  }
  if (j.contains("repeats")) e.repeats = static_cast<int>(r.integer(j["repeats"], "repeats", 1, 1000));
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
  if (!e.scene_path.empty()) j["scene"] = e.scene_path; else j["scene"] = e.scene_generator;
  j["dt"] = e.dt;
  j["methods"] = e.methods;
  j["acceleration_bound"] = e.acceleration_bound < 0 ? json(nullptr) : json(e.acceleration_bound);
  j["repeats"] = e.repeats;
  return j;
}

}  // namespace ccdlab
