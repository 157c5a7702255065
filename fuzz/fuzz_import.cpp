// The recorded-frames importer (`ccdlab import`, ccd/scene/recorded_frames.hpp).
//
// Input: the CSV text, or `OPTIONS NUL CSV` where OPTIONS is a JSON object standing for the
// command's options: {"radius": R} as `--radius R` (refused unless a finite number > 0, as
// the command refuses it) and {"shapes": ...} as the `shapes` of a `--shapes` file, handed
// to the reader as it is (the reader must refuse what is not an array of shapes).
//
// Invariants: one label per body; the scene starts at the file's earliest time and passes
// the scene validation; it writes and reads back to the same digest.
#include "fuzz_support.hpp"

#include <ccd/io/json_reader.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/recorded_frames.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>

#include <cmath>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  std::string_view text = ccdfuzz::as_text(data, size);
  ccd::FrameImportOptions options;
  options.shapes_file = "shapes.json";
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
    try {
      const nlohmann::json j = ccd::parse_json_text(text.substr(0, nul), "options");
      if (!j.is_object()) return 0;
      if (const auto r = j.find("radius"); r != j.end()) {
        if (!r->is_number() || !std::isfinite(r->get<double>()) || !(r->get<double>() > 0.0)) return 0;
        options.radius = r->get<double>();
      }
      if (const auto s = j.find("shapes"); s != j.end()) options.shapes = *s;
    } catch (const ccd::InputError&) {
      return 0;
    }
    text.remove_prefix(nul + 1);
  }
  std::istringstream csv{std::string(text)};
  ccd::FrameImport imported;
  try {
    imported = ccd::import_frames(csv, "fuzz.csv", options);
  } catch (const ccd::InputError&) {
    return 0;
  }
  const ccd::Scene& scene = imported.scene;
  FUZZ_CHECK(imported.labels.size() == scene.bodies.size());
  FUZZ_CHECK(std::isfinite(imported.time_origin) && scene.horizon > 0.0);
  ccd::validate_scene(scene, "imported");
  const ccd::Scene again = ccd::scene_from_json(ccd::parse_json_text(ccd::scene_to_json(scene).dump(), "again"), "again");
  FUZZ_CHECK(ccd::scene_digest(again) == ccd::scene_digest(scene));
  return 0;
}
