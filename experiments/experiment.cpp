#include "experiment.hpp"

#include "method.hpp"

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

[[noreturn]] void fail(const std::string& file, const std::string& field, const std::string& what) {
  throw ccd::InputError(file, field, what);
}

double positive_number(const json& v, const std::string& file, const std::string& field) {
  if (!v.is_number()) fail(file, field, "must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x) || x <= 0.0) fail(file, field, "must be a finite number > 0");
  return x;
}

std::vector<double> parse_dt(const json& j, const std::string& file) {
  std::vector<double> dt;
  if (j.is_array()) {
    if (j.empty()) fail(file, "dt", "must not be empty");
    for (std::size_t i = 0; i < j.size(); ++i)
      dt.push_back(positive_number(j[i], file, "dt[" + std::to_string(i) + "]"));
  } else if (j.is_object()) {
    for (const char* k : {"from", "to", "count"})
      if (!j.contains(k)) fail(file, std::string("dt.") + k, "missing required field");
    const double from = positive_number(j["from"], file, "dt.from");
    const double to = positive_number(j["to"], file, "dt.to");
    if (!j["count"].is_number_integer() || j["count"].get<long long>() < 1 || j["count"].get<long long>() > 100000)
      fail(file, "dt.count", "must be an integer in [1, 100000]");
    const int count = j["count"].get<int>();
    std::string spacing = "log";
    if (j.contains("spacing")) {
      if (!j["spacing"].is_string()) fail(file, "dt.spacing", "must be \"log\" or \"linear\"");
      spacing = j["spacing"].get<std::string>();
      if (spacing != "log" && spacing != "linear") fail(file, "dt.spacing", "must be \"log\" or \"linear\"");
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
    fail(file, "dt", "must be an array of numbers or {\"from\", \"to\", \"count\", \"spacing\"}");
  }
  std::sort(dt.begin(), dt.end(), std::greater<>());
  dt.erase(std::unique(dt.begin(), dt.end()), dt.end());
  return dt;
}

}  // namespace

Experiment experiment_from_json(const json& j, const std::string& file) {
  if (!j.is_object()) fail(file, "", "an experiment must be a JSON object");
  if (!j.contains("format")) fail(file, "format", "missing required field");
  if (!j["format"].is_string() || j["format"].get<std::string>() != "ccdlab-experiment/1")
    fail(file, "format", "must be \"ccdlab-experiment/1\"");
  Experiment e;
  if (j.contains("name")) {
    if (!j["name"].is_string()) fail(file, "name", "must be a string");
    e.name = j["name"].get<std::string>();
    // The name becomes a file name (results/NAME.json): never a path.
    if (e.name.empty() || e.name.size() > 200 || e.name.front() == '.' || e.name.front() == '-' ||
        !std::all_of(e.name.begin(), e.name.end(), [](char c) {
          return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
        }))
      fail(file, "name",
           "'" + e.name + "' is not a plain file name: 1 to 200 letters, digits, '.', '_' or '-', not starting "
           "with '.' or '-' (the default results file is results/NAME.json)");
  } else {
    // The file's stem, with anything but letters, digits, '.', '_' and '-' made '_'.
    e.name = std::filesystem::path(file).stem().string().substr(0, 200);
    for (char& c : e.name)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-')) c = '_';
    if (e.name.empty()) e.name = "experiment";
    if (e.name.front() == '.' || e.name.front() == '-') e.name.front() = '_';
  }
  if (!j.contains("scene")) fail(file, "scene", "missing required field");
  const json& scene = j["scene"];
  if (scene.is_string()) {
    e.scene_path = scene.get<std::string>();
    if (e.scene_path.empty()) fail(file, "scene", "must not be empty");
  } else if (scene.is_object()) {
    if (!scene.contains("generator") || !scene["generator"].is_string())
      fail(file, "scene.generator", "missing required field (a generator name)");
    e.scene_generator = scene;
  } else {
    fail(file, "scene", "must be a scene file path or {\"generator\": NAME, ...}");
  }
  if (!j.contains("dt")) fail(file, "dt", "missing required field");
  e.dt = parse_dt(j["dt"], file);
  if (!j.contains("methods")) fail(file, "methods", "missing required field");
  const json& methods = j["methods"];
  if (!methods.is_array() || methods.empty()) fail(file, "methods", "must be a non-empty array of method names");
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const std::string field = "methods[" + std::to_string(i) + "]";
    if (!methods[i].is_string()) fail(file, field, "must be a string BOUND/BROADPHASE");
    try {
      e.methods.push_back(parse_method(methods[i].get<std::string>()).name);
    } catch (const std::invalid_argument& err) {
      fail(file, field, err.what());
    }
    // Compared by canonical name: "horn/grid", "horn:4/grid" and "horn:04/grid" are one method.
    const auto first = std::find(e.methods.begin(), e.methods.end(), e.methods.back());
    if (first != e.methods.end() - 1)
      fail(file, field,
           "method '" + methods[i].get<std::string>() + "' is '" + e.methods.back() + "', already listed as methods[" +
               std::to_string(first - e.methods.begin()) + "]");
  }
  if (j.contains("acceleration_bound") && !j["acceleration_bound"].is_null()) {
    const json& a = j["acceleration_bound"];
    if (!a.is_number() || !std::isfinite(a.get<double>()) || a.get<double>() < 0.0 ||
        a.get<double>() > ccd::kMaxSceneMagnitude)
      fail(file, "acceleration_bound", "must be a number in [0, 1e+30]");
    e.acceleration_bound = a.get<double>();
  }
  if (j.contains("repeats")) {
    if (!j["repeats"].is_number_integer() || j["repeats"].get<long long>() < 1 || j["repeats"].get<long long>() > 1000)
      fail(file, "repeats", "must be an integer in [1, 1000]");
    e.repeats = j["repeats"].get<int>();
  }
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
      fail(file, "dt", "timestep " + text(e.dt[i]) + " is larger than the scene's horizon " + text(horizon));
    if (horizon / e.dt[i] > kMaxStepsPerJob)
      fail(file, "dt",
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
