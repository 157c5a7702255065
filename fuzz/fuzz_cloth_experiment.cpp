// The cloth experiment reader (`ccdlab-cloth-experiment/1`, experiments/cloth_experiment.hpp)
// and, for a built-in scene of at most 8 particles per side, the scene it names with its
// step count and check intervals applied (a scene file is not opened: fuzz_cloth_scene
// covers that reader).
//
// Invariants: what the results file records parses again to the same experiment; the
// check intervals are ascending and distinct; the name is a plain file name.
#include "fuzz_support.hpp"

#include <experiments/cloth_experiment.hpp>

#include <ccd/io/json_reader.hpp>
#include <ccd/io/input_error.hpp>

#include <algorithm>
#include <functional>

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  ccdlab::ClothExperiment e;
  try {
    e = ccdlab::cloth_experiment_from_json(ccd::parse_json_text(ccdfuzz::as_text(data, size), "fuzz.json"),
                                           "fuzz.json");
  } catch (const ccd::InputError&) {
    return 0;
  }
  const ccdlab::ClothExperiment again = ccdlab::cloth_experiment_from_json(ccdlab::cloth_experiment_to_json(e), "again");
  FUZZ_CHECK(again.name == e.name && again.scene == e.scene && again.scene_path == e.scene_path && again.n == e.n &&
             again.steps == e.steps && again.thickness == e.thickness && again.k == e.k &&
             again.cullers == e.cullers && again.modes == e.modes && again.repeats == e.repeats);
  FUZZ_CHECK(!e.name.empty() && e.name.find('/') == std::string::npos);
  FUZZ_CHECK(!e.k.empty() && std::adjacent_find(e.k.begin(), e.k.end(), std::greater_equal<>()) == e.k.end());
  if (!e.scene_path.empty() || e.n > 8) return 0;
  try {
    const ccd::cloth::ClothScene scene = ccdlab::load_cloth_experiment_scene(e, "fuzz.json");
    FUZZ_CHECK(e.k.back() <= scene.steps);
    if (e.steps > 0) FUZZ_CHECK(scene.steps == e.steps);
  } catch (const ccd::InputError&) {
  }
  return 0;
}
