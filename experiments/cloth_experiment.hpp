#pragma once
// A cloth experiment (`ccdlab-cloth-experiment/1`, docs/experiments.md#cloth-experiments):
// one cloth scene, a list of check intervals k (in integrator steps, swept as dt is for
// spheres), cullers from the culler registry (cloth/cull/cullers.hpp) and detection modes.
// Parsing fills in every default, so the results file records exactly what ran.
#include <cloth/sim/cloth_scene.hpp>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ccdlab {

inline constexpr const char* kClothExperimentFormat = "ccdlab-cloth-experiment/1";

struct ClothExperiment {
  std::string name;              ///< a plain file name (results/NAME.json)
  std::string scene;             ///< a built-in scene (drape, twist, pile) ...
  std::string scene_path;        ///< ... or a ccdlab-cloth/1 file (resolved against the experiment's folder)
  int n = 32;                    ///< particles per side of a built-in scene
  int steps = 0;                 ///< integrator steps; 0: the scene's own
  double thickness = -1.0;       ///< the scene's thickness (obstacles and self-contact distance); < 0: the scene's own
  std::vector<int> k;            ///< check intervals in integrator steps, ascending, unique, each in [1, steps]
  std::vector<std::string> cullers;  ///< registry names, registry order when not given
  std::vector<std::string> modes;    ///< "discrete", "continuous" (both when not given)
  int repeats = 1;               ///< timing repeats (counts must not change)
  nlohmann::json source;         ///< the parsed file with defaults filled in
};

/// True when `j` is an object whose "format" is the cloth experiment's.
bool is_cloth_experiment(const nlohmann::json& j);

/// Parses and validates; throws ccd::InputError naming `file` and the field. The k <= steps
/// check needs the scene: see load_cloth_experiment_scene.
ClothExperiment cloth_experiment_from_json(const nlohmann::json& j, const std::string& file);
ClothExperiment load_cloth_experiment(const std::string& path);

/// The experiment's scene with its step count applied; checks every k against it. Throws
/// ccd::InputError naming `file` (or the scene file) and the field.
ccd::cloth::ClothScene load_cloth_experiment_scene(const ClothExperiment& e, const std::string& file);

/// The JSON form with defaults filled in (what the results file records).
nlohmann::json cloth_experiment_to_json(const ClothExperiment& e);

}  // namespace ccdlab
