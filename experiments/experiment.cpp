#include "experiment.hpp"

#include "method.hpp"

#include <ccd/io/json_reader.hpp>
#include <ccd/scene/input_error.hpp>
#include <ccd/scene/scene_io.hpp>

#include <algorithm>
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
  e.name = j.contains("name") ? r.string(j["name"], "name") : std::filesystem::path(file).stem().string();
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
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const std::string field = "methods[" + std::to_string(i) + "]";
    if (!methods[i].is_string()) r.fail(field, "must be a string BOUND/BROADPHASE");
    try {
      e.methods.push_back(parse_method(methods[i].get<std::string>()).name);
    } catch (const std::invalid_argument& err) {
      r.fail(field, err.what());
    }
    if (std::count(e.methods.begin(), e.methods.end(), e.methods.back()) > 1)
      r.fail(field, "method '" + e.methods.back() + "' is listed twice");
  }
  if (j.contains("acceleration_bound") && !j["acceleration_bound"].is_null()) {
    e.acceleration_bound = r.number(j["acceleration_bound"], "acceleration_bound");
    if (e.acceleration_bound < 0.0) r.fail("acceleration_bound", "must be a finite number >= 0");
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
  for (std::size_t i = 0; i < e.dt.size(); ++i)
    if (e.dt[i] > horizon)
      throw ccd::InputError(file, "dt", "timestep " + std::to_string(e.dt[i]) + " is larger than the scene's horizon " +
                                            std::to_string(horizon));
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
