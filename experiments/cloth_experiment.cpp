#include "cloth_experiment.hpp"
#include "experiment.hpp"

#include <cloth/cull/cullers.hpp>
#include <ccd/io/utf8_text.hpp>
#include <ccd/io/json_reader.hpp>
#include <ccd/util/nearest_name.hpp>

#include <algorithm>
#include <filesystem>

namespace ccdlab {

using nlohmann::json;

bool is_cloth_experiment(const json& j) {
  return j.is_object() && j.contains("format") && j["format"] == kClothExperimentFormat;
}

ClothExperiment cloth_experiment_from_json(const json& j, const std::string& file) {
  const ccd::JsonReader r{file};
  if (!j.is_object()) r.fail("", "a cloth experiment must be a JSON object");
  if (r.string(r.require(j, "format", ""), "format") != kClothExperimentFormat)
    r.fail("format", std::string("must be \"") + kClothExperimentFormat + "\"");
  r.only_fields(j, "", {"format", "name", "description", "scene", "n", "steps", "thickness", "k", "cullers", "modes",
                        "repeats"});
  ClothExperiment e;
  e.name = experiment_name(j, file, "cloth-experiment");
  const std::string scene = r.string(r.require(j, "scene", ""), "scene");
  if (scene.empty()) r.fail("scene", "must be a built-in scene (drape, twist, pile) or a ccdlab-cloth/1 file");
  const auto names = ccd::cloth::builtin_cloth_scene_names();
  if (std::find(names.begin(), names.end(), scene) != names.end()) e.scene = scene;
  else e.scene_path = scene;
  if (j.contains("n")) {
    if (!e.scene_path.empty()) r.fail("n", "applies to a built-in scene only (a scene file sets its grid)");
    e.n = static_cast<int>(r.integer(j["n"], "n", 4, 1000));
  }
  if (j.contains("steps") && !j["steps"].is_null())  // null: the scene's own steps (as written back)
    e.steps = static_cast<int>(r.integer(j["steps"], "steps", 1, 1000000));
  if (j.contains("thickness") && !j["thickness"].is_null()) {
    e.thickness = r.number(j["thickness"], "thickness");
    if (e.thickness < 0.0 || e.thickness > 1e30) r.fail("thickness", "must be a number in [0, 1e+30]");
  }
  const json& k = r.require(j, "k", "");
  if (!k.is_array() || k.empty()) r.fail("k", "must be a non-empty array of check intervals (integrator steps)");
  for (std::size_t i = 0; i < k.size(); ++i)
    e.k.push_back(static_cast<int>(r.integer(k[i], "k[" + std::to_string(i) + "]", 1, 1000000)));
  std::sort(e.k.begin(), e.k.end());
  if (std::adjacent_find(e.k.begin(), e.k.end()) != e.k.end()) r.fail("k", "check intervals must be distinct");
  if (j.contains("cullers")) {
    const json& c = j["cullers"];
    if (!c.is_array() || c.empty()) r.fail("cullers", "must be a non-empty array of culler names");
    std::vector<std::string_view> known;
    for (const auto& entry : ccd::cloth::cullers()) known.push_back(entry.name);
    for (std::size_t i = 0; i < c.size(); ++i) {
      const std::string field = "cullers[" + std::to_string(i) + "]";
      const std::string name = r.string(c[i], field);
      if (!ccd::cloth::find_culler(name)) r.fail(field, "unknown culler '" + name + "'" + ccd::suggestion(name, known));
      if (std::find(e.cullers.begin(), e.cullers.end(), name) != e.cullers.end())
        r.fail(field, "culler '" + name + "' is listed twice");
      e.cullers.push_back(name);
    }
  } else {
    for (const auto& entry : ccd::cloth::cullers()) e.cullers.emplace_back(entry.name);
  }
  if (j.contains("modes")) {
    const json& m = j["modes"];
    if (!m.is_array() || m.empty()) r.fail("modes", "must be a non-empty array of \"discrete\", \"continuous\"");
    for (std::size_t i = 0; i < m.size(); ++i) {
      const std::string field = "modes[" + std::to_string(i) + "]";
      const std::string mode = r.string(m[i], field);
      if (mode != "discrete" && mode != "continuous") r.fail(field, "must be \"discrete\" or \"continuous\"");
      if (std::find(e.modes.begin(), e.modes.end(), mode) != e.modes.end()) r.fail(field, "mode listed twice");
      e.modes.push_back(mode);
    }
  } else {
    e.modes = {"discrete", "continuous"};
  }
  if (j.contains("repeats")) e.repeats = static_cast<int>(r.integer(j["repeats"], "repeats", 1, 1000));
  if (j.contains("description")) r.string(j["description"], "description");
  e.source = j;
  return e;
}

ClothExperiment load_cloth_experiment(const std::string& path) {
  ClothExperiment e = cloth_experiment_from_json(ccd::read_json_file(path), path);
  if (!e.scene_path.empty()) {
    std::filesystem::path p(e.scene_path);
    if (p.is_relative()) p = std::filesystem::path(path).parent_path() / p;
    e.scene_path = p.lexically_normal().string();
  }
  return e;
}

ccd::cloth::ClothScene load_cloth_experiment_scene(const ClothExperiment& e, const std::string& file) {
  ccd::cloth::ClothScene s =
      e.scene_path.empty() ? ccd::cloth::builtin_cloth_scene(e.scene, e.n) : ccd::cloth::read_cloth_scene(e.scene_path);
  if (e.steps > 0) s.steps = e.steps;
  if (e.thickness >= 0.0) s.thickness = e.thickness;
  for (std::size_t i = 0; i < e.k.size(); ++i)
    if (e.k[i] > s.steps)
      throw ccd::InputError(file, "k[" + std::to_string(i) + "]",
                            "check interval " + std::to_string(e.k[i]) + " is longer than the run (" +
                                std::to_string(s.steps) + " steps)");
  return s;
}

json cloth_experiment_to_json(const ClothExperiment& e) {
  json j = e.source;
  j["format"] = kClothExperimentFormat;
  j["name"] = e.name;
  j["scene"] = e.scene_path.empty() ? e.scene : ccd::escape_invalid_utf8(e.scene_path);
  if (e.scene_path.empty()) j["n"] = e.n;
  j["steps"] = e.steps > 0 ? json(e.steps) : json(nullptr);
  j["thickness"] = e.thickness >= 0.0 ? json(e.thickness) : json(nullptr);
  j["k"] = e.k;
  j["cullers"] = e.cullers;
  j["modes"] = e.modes;
  j["repeats"] = e.repeats;
  return j;
}

}  // namespace ccdlab
