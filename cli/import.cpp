// `ccdlab import FRAMES.csv -o SCENE.json [--radius R] [--shapes SHAPES.json]`: recorded
// frames from any simulator turned into a scene whose motion is linear between frames
// (ccd/scene/recorded_frames.hpp, docs/import.md).
#include "command.hpp"
#include "command_line.hpp"

#include "../experiments/work_estimate.hpp"

#include <ccd/io/atomic_file.hpp>
#include <ccd/io/json_reader.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/recorded_frames.hpp>
#include <ccd/scene/scene_io.hpp>

#include <cmath>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <new>
#include <optional>
#include <string>
#include <vector>

namespace ccdlab {
namespace {

constexpr const char* kImportDescription =
    "usage: ccdlab import FRAMES.csv -o SCENE.json [--radius R] [--shapes SHAPES.json] [--force]\n"
    "\n"
    "Turns recorded frames (from any simulator) into a scene: between two frames of a body\n"
    "its centre moves linearly, i.e. its velocity changes at every frame, and a shaped body\n"
    "turns at the constant angular velocity that takes one frame's orientation to the next\n"
    "along the shortest arc (docs/import.md). CSV with a header row, columns in any order:\n"
    "  body,t,x,y,z     required: body label, time (s), centre (m)\n"
    "  radius           the body's radius (m), > 0, the same in all its rows\n"
    "  shape            a name from --shapes, or sphere:R, capsule:HALF_LENGTH,R, box:HX,HY,HZ\n"
    "  qw,qx,qy,qz      optional orientation (unit quaternion, body to world)\n"
    "A row gives a radius or a shape; rows in any order. Scene time 0 is the file's first\n"
    "time, the horizon its last; every body needs a frame at both. Bodies are ordered by\n"
    "label (numerically when all labels are integers). No walls, no gravity: the\n"
    "recording holds them. `ccdlab poses` output imports as it is, with --radius.\n";

constexpr const char* kImportFooter =
    "Exit status: 0 success, 1 runtime failure, 2 bad input or usage (no file written);\n"
    "a bad row is named by its line and column (frames.csv: line 7: radius: must be > 0).";

// A frames file above this many bytes (tens of millions of rows) is refused without --force.
constexpr double kMaxFramesFileBytes = 2e9;

int run_import(std::span<const std::string> args) {
  std::string csv_path, out_path, shapes_path;
  bool force = false;
  ccd::FrameImportOptions options;
  CommandLine cli("import", kImportDescription, "import");
  cli.footer(kImportFooter);
  cli.positional("FRAMES.csv", csv_path, "the recorded frames");
  cli.text("-o,--output", out_path, "SCENE.json", "the scene (written atomically; '-' = stdout)",
           "missing value after -o");
  cli.value(
      "--radius", "R", "radius of bodies whose rows give no radius and no shape",
      [&](const std::string& v) {
        char* end = nullptr;
        const double r = v.empty() ? 0.0 : std::strtod(v.c_str(), &end);
        if (v.empty() || end != v.c_str() + v.size() || !std::isfinite(r) || !(r > 0.0))
          cli.fail("--radius must be a number > 0, got '" + v + "'");
        options.radius = r;
      },
      "missing value after --radius");
  cli.text("--shapes", shapes_path, "FILE.json",
           "named shapes: a JSON array of shape objects as in a scene's\n"
           "\"shapes\" (docs/formats.md), or a scene file whose shapes are used",
           "missing value after --shapes");
  cli.flag("--force", force,
           "read a FRAMES.csv larger than 2e9 bytes (refused before the work\n"
           "otherwise; it must be a regular file, not a folder or a device)");
  try {
    if (!cli.parse(args)) return 0;
    if (csv_path.empty()) cli.fail("missing FRAMES.csv");
    if (out_path.empty()) cli.fail("missing -o SCENE.json");
  } catch (...) {
    return command_failed("import");
  }
  try {
    std::vector<std::string> inputs = {csv_path};
    if (!shapes_path.empty()) inputs.push_back(shapes_path);
    ccd::OutputFile output(out_path, inputs);
    if (!shapes_path.empty()) {
      options.shapes_file = shapes_path;
      const nlohmann::json j = ccd::read_json_file(shapes_path);
      if (j.is_array()) {
        options.shapes = j;
      } else if (j.is_object() && j.contains("shapes")) {
        if (!j["shapes"].is_array())
          throw ccd::InputError(shapes_path, "shapes", "must be an array of shape objects (docs/formats.md)");
        options.shapes = j["shapes"];
      } else {
        throw ccd::InputError(shapes_path, "", "must be an array of shapes or a scene with \"shapes\"");
      }
    }
    check_input_file(csv_path, kMaxFramesFileBytes, force);  // a regular file, not /dev/zero or a folder
    std::ifstream in(csv_path, std::ios::binary);
    if (!in) throw ccd::InputError(csv_path, "", "cannot be opened");
    const ccd::FrameImport imported = ccd::import_frames(in, csv_path, options);
    std::size_t changes = 0;
    for (const ccd::Body& b : imported.scene.bodies) changes += b.velocity_changes.size();
    output.commit(ccd::scene_to_json(imported.scene).dump(1) + "\n");
    (output.is_stdout() ? std::cerr : std::cout)
        << "ccdlab import: " << imported.scene.bodies.size() << " bodies, " << imported.frames << " frames, "
        << changes << " velocity changes, horizon " << imported.scene.horizon << " s (scene time 0 = t "
        << imported.time_origin << " of the file) -> " << out_path << "\n";
  } catch (...) {
    return command_failed("import", "importing " + csv_path);
  }
  return 0;
}

}  // namespace

extern const Command kImportCommand = {"import", "recorded frames (CSV from any simulator) to a scene, linear between frames",
                                       run_import};

}  // namespace ccdlab
