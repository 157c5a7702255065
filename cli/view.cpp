// `ccdlab view SCENE.json [--results RESULTS.json] [--truth TRUTH.json] -o view.html`: one
// self-contained HTML page that plays the scene in a browser, with the bounds, the truth's
// contacts and every contact a method missed (docs/viewer.md).
#include "command.hpp"
#include "command_line.hpp"

#include "../experiments/view_data.hpp"
#include "../experiments/view_page.hpp"
#include "../experiments/work_estimate.hpp"

#include <ccd/io/atomic_file.hpp>
#include <ccd/io/json_reader.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_binary.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/truth/truth_io.hpp>

#include <exception>
#include <filesystem>
#include <iostream>
#include <new>
#include <optional>
#include <vector>

namespace ccdlab {
namespace {

// The bytes of each input (scene or frames, results, truth) read without --force: the
// page holds all of it and its parsed form several times over.
constexpr double kMaxViewInputBytes = 1e8;

constexpr const char* kViewDescription =
    "Writes one self-contained HTML page (three.js inlined; open it from disk, no server and no\n"
    "network needed) that plays the scene: play, pause, scrub time; spheres and rigid shapes;\n"
    "for a method and dt of the results, its sample instants, its bounds, the truth's contacts\n"
    "and a table of every contact it missed (click a row to jump there). The URL fragment\n"
    "selects the view: VIEW.html#method=aabb/sap&dt=0.05&t=0.5 (docs/viewer.md).\n";

int run_view(std::span<const std::string> args) {
  std::string scene_path, results_path, truth_path, out_path;
  bool force = false;
  CommandLine cli("view", kViewDescription, "view");
  cli.footer("Exit status: 0 success, 1 runtime failure, 2 bad input or usage (no file written).");
  cli.positional("SCENE.json", scene_path,
                 "a ccdlab-scene/1 or /2 file, or the frames of a cloth run\n"
                 "(ccdlab-cloth-frames/1, from ccdlab cloth ... -o FRAMES.json)");
  // Each file option once, never empty.
  auto file = [&cli](const std::string& names, std::string& slot, const std::string& value_name,
                     const std::string& help) {
    const std::string name = option_name(names);
    cli.value(
        names, value_name, help,
        [&cli, &slot, name](const std::string& v) {
          if (!slot.empty()) cli.fail(name + " given twice");
          if (v.empty()) cli.fail(name + " needs a file name");
          slot = v;
        },
        "missing value after " + name);
  };
  file("--results", results_path, "RESULTS.json",
       "a results file of this scene (ccdlab run --list-missed lists the\n"
       "missed contacts the page shows)");
  file("--truth", truth_path, "TRUTH.json", "the scene's ground truth (ccdlab truth -o): its contacts are drawn");
  file("-o,--output", out_path, "VIEW.html", "the page (written atomically; checked before the work)");
  cli.flag("--force", force,
           "build a page of more than 5e6 entries (trajectory pieces and\n"
           "sampled poses of free spins, or a cloth run's particle positions\n"
           "over its frames, about 150 bytes each) or read an input of more\n"
           "than 1e8 bytes; without it such work is refused before it starts\n"
           "with the estimate");
  try {
    if (!cli.parse(args)) return 0;
    if (scene_path.empty()) cli.fail("missing SCENE.json");
    if (out_path.empty()) cli.fail("missing -o VIEW.html");
  } catch (...) {
    return command_failed("view");
  }
  try {
    std::vector<std::string> inputs{scene_path};
    if (!results_path.empty()) inputs.push_back(results_path);
    if (!truth_path.empty()) inputs.push_back(truth_path);
    ccd::OutputFile output(out_path, inputs);
    // Each input's size before it is read (a missing file or a device is named by its reader).
    for (const std::string& input : inputs)
      if (std::error_code ec; std::filesystem::is_regular_file(input, ec))
        check_input_file(input, kMaxViewInputBytes, force);
    // A binary scene (ccd/scene/scene_binary.hpp) is a body scene; anything else is JSON.
    const bool binary = ccd::is_binary_scene_file(scene_path);
    const nlohmann::json scene_json = binary ? nlohmann::json() : ccd::read_json_file(scene_path);
    const nlohmann::json* format = scene_json.is_object() && scene_json.contains("format") ? &scene_json["format"] : nullptr;
    nlohmann::json data;
    if (format && *format == "ccdlab-cloth-frames/1") {
      if (!results_path.empty() || !truth_path.empty())
        cli.fail("--results and --truth are for body scenes, not for cloth frames");
      data = cloth_view_data(scene_json, scene_path, force);
    } else if (format && *format == "ccdlab-cloth/1") {
      throw ccd::InputError(scene_path, "format",
                            "a cloth scene is shown from its frames: run `ccdlab cloth " + scene_path +
                                " -o FRAMES.json` and view FRAMES.json");
    } else {
      const ccd::Scene scene = binary ? ccd::load_scene(scene_path) : ccd::scene_from_json(scene_json, scene_path);
      ViewInputs in;
      in.scene_file = scene_path;
      in.force = force;
      if (!results_path.empty()) {
        in.results_file = results_path;
        in.results = ccd::read_json_file(results_path);
      }
      if (!truth_path.empty()) {
        in.truth_file = truth_path;
        in.truth = ccd::load_truth(truth_path);
      }
      try {
        data = body_view_data(scene, in);
      } catch (const ccd::TooManyPieces& e) {
        throw ccd::InputError(scene_path, "bodies[" + std::to_string(e.body()) + "]",
                              "needs more than " + std::to_string(e.limit()) + " trajectory pieces over the horizon");
      }
    }
    output.commit(view_page(data));
    if (!output.is_stdout()) std::cout << "written      " << out_path << "\n";
  } catch (...) {
    return command_failed("view", "building the page of " + scene_path);
  }
  return 0;
}

}  // namespace

extern const Command kViewCommand = {
    "view", "an interactive HTML page of a scene: its motion, a method's bounds and every contact it missed",
    run_view};

}  // namespace ccdlab
