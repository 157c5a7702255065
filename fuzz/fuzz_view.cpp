// What `ccdlab view` reads (experiments/view_data.hpp): a scene, optionally with a results
// file and a truth file, or the frames of a cloth run.
//
// Input: `SCENE`, `SCENE NUL RESULTS` or `SCENE NUL RESULTS NUL TRUTH` (an empty part: not
// given). A first part whose format is `ccdlab-cloth-frames/1` goes to the cloth frames
// reader instead, as in the command. Body scenes of at most 8 bodies go past the scene
// reader (fuzz_scene covers larger ones).
//
// Invariants: the page data has one entry per body (per frame for cloth), every missed event
// it shows names bodies of the scene within the horizon, and every cloth triangle index is
// below nx ny.
#include "fuzz_support.hpp"

#include <experiments/view_data.hpp>

#include <ccd/io/json_reader.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/truth/truth_io.hpp>

#include <string>
#include <vector>

namespace {

std::vector<std::string_view> split_at_nul(std::string_view text) {
  std::vector<std::string_view> parts;
  while (parts.size() < 2) {
    const std::size_t nul = text.find('\0');
    if (nul == std::string_view::npos) break;
    parts.push_back(text.substr(0, nul));
    text.remove_prefix(nul + 1);
  }
  parts.push_back(text);
  return parts;
}

void check_cloth(const nlohmann::json& frames, const nlohmann::json& data) {
  FUZZ_CHECK(data["frames"].size() == frames["frames"].size());
  const auto particles = data["nx"].get<std::uint64_t>() * data["ny"].get<std::uint64_t>();
  for (const nlohmann::json& v : data["triangles"]) FUZZ_CHECK(v.get<std::uint64_t>() < particles);
}

void check_bodies(const ccd::Scene& scene, const nlohmann::json& data) {
  FUZZ_CHECK(data["bodies"]["count"].get<std::size_t>() == scene.bodies.size());
  FUZZ_CHECK(data["bodies"]["pieces"].size() == scene.bodies.size());
  for (const nlohmann::json& run : data["runs"])
    if (run.contains("missed_events"))
      for (const nlohmann::json& e : run["missed_events"]) {
        FUZZ_CHECK(e["a"].get<std::uint64_t>() < e["b"].get<std::uint64_t>());
        FUZZ_CHECK(e["b"].get<std::uint64_t>() < scene.bodies.size());
        FUZZ_CHECK(e["exit"].get<double>() <= scene.horizon);
      }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  const std::vector<std::string_view> parts = split_at_nul(ccdfuzz::as_text(data, size));
  try {
    const nlohmann::json first = ccd::parse_json_text(parts[0], "scene.json");
    if (first.is_object() && first.contains("format") && first["format"] == "ccdlab-cloth-frames/1") {
      check_cloth(first, ccdlab::cloth_view_data(first, "scene.json"));
      return 0;
    }
    const ccd::Scene scene = ccd::scene_from_json(first, "scene.json");
    if (scene.bodies.size() > 8) return 0;
    ccdlab::ViewInputs in;
    in.scene_file = "scene.json";
    if (parts.size() > 1 && !parts[1].empty()) {
      in.results_file = "results.json";
      in.results = ccd::parse_json_text(parts[1], "results.json");
    }
    if (parts.size() > 2 && !parts[2].empty()) {
      in.truth_file = "truth.json";
      in.truth = ccd::truth_from_json(ccd::parse_json_text(parts[2], "truth.json"), "truth.json");
    }
    check_bodies(scene, ccdlab::body_view_data(scene, in));
  } catch (const ccd::InputError&) {
  } catch (const ccd::TooManyPieces&) {  // the command reports it as an input error
  }
  return 0;
}
