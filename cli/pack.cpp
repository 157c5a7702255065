// `ccdlab pack SCENE -o SCENE.ccds [--json]`: writes a scene in the binary companion
// format (ccd/scene/scene_binary.hpp, docs/formats.md), or back as JSON with --json.
#include "command.hpp"
#include "command_line.hpp"

#include <ccd/io/atomic_file.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_binary.hpp>
#include <ccd/scene/scene_io.hpp>

#include <exception>
#include <iostream>
#include <new>
#include <string>

namespace ccdlab {
namespace {

constexpr const char* kPackDescription =
    "Writes the scene SCENE (JSON, or binary) in the binary scene format (docs/formats.md,\n"
    "\"ccdlab-scene-binary/1\"), which every command that reads a scene accepts in place of\n"
    "the JSON file and reads in a fraction of the time. It carries the scene's digest, so a\n"
    "truth file computed from either file fits both. Only sphere scenes (no shapes, spin or\n"
    "static scenery) have a binary form; others are refused.\n";

constexpr const char* kPackFooter =
    "A binary SCENE is checked on the way: its stored digest must be the digest of the scene\n"
    "it holds (loading it elsewhere does not recompute the digest).\n"
    "\n"
    "Exit status: 0 success, 1 runtime failure, 2 bad input or usage (no file written).";

int run_pack(std::span<const std::string> args) {
  std::string scene_path, out_path;
  bool json = false;
  CommandLine cli("pack", kPackDescription, "pack");
  cli.footer(kPackFooter);
  cli.positional("SCENE", scene_path, "the scene (JSON or binary)");
  cli.text("-o,--output", out_path, "OUT", "the output (written atomically; '-' = stdout)", "missing value after -o");
  cli.flag("--json", json,
           "write the scene as JSON instead (what `ccdlab scene` writes): unpacks a\n"
           "binary scene");
  try {
    if (!cli.parse(args)) return 0;
    if (scene_path.empty()) cli.fail("missing SCENE");
    if (out_path.empty()) cli.fail("missing -o OUT");
  } catch (...) {
    return command_failed("pack");
  }
  try {
    const std::string inputs[] = {scene_path};
    ccd::OutputFile output(out_path, inputs);
    ccd::Scene scene;
    if (ccd::is_binary_scene_file(scene_path)) {
      std::string stored;
      scene = ccd::load_binary_scene(scene_path, &stored);
      ccd::verify_binary_scene_digest(scene, stored, scene_path);
    } else {
      scene = ccd::load_scene(scene_path);
    }
    if (json) {
      output.commit(ccd::scene_to_json(scene).dump(1) + "\n");
    } else {
      output.commit(ccd::scene_to_binary(scene, scene_path));
    }
  } catch (...) {
    return command_failed("pack");
  }
  return 0;
}

}  // namespace

extern const Command kPackCommand = {"pack", "write a scene in the binary format that loads fast (or back as JSON)",
                                     run_pack};

}  // namespace ccdlab
