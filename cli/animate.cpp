// `ccdlab animate SCENE.json --results RESULTS.json --method M --dt DT ...`: the arguments
// are parsed and checked here, then scripts/animate.py draws (see python_script.hpp).
#include "command.hpp"
#include "command_line.hpp"
#include "python_script.hpp"

#include <ccd/util/integer_text.hpp>

#include <cmath>
#include <cstdlib>
#include <string_view>
#include <vector>

namespace ccdlab {
namespace {

constexpr const char* kAnimateDescription =
    "Animates the scene from T0 to T1 (default: the whole horizon): every body, projected on\n"
    "the two widest axes of the box; the samples the method took (every dt); each contact\n"
    "the method missed, highlighted in red where and when it happened; a zoom on the missed\n"
    "contact nearest in time; a time line of the samples and the missed contacts. The method\n"
    "and dt must be a record of RESULTS.json, whose scene must be SCENE.json (same digest); the\n"
    "missed contacts are recomputed with the ccdlab Python module and checked against the\n"
    "record's count. .mp4 needs ffmpeg. Runs scripts/animate.py with /usr/bin/python3.\n";

constexpr const char* kAnimateFooter =
    "The work is estimated first: more than 2000 frames, 2e6 body-frames (bodies x frames) or\n"
    "1e11 body-steps for the run that finds the missed contacts (bodies x horizon / dt) is\n"
    "refused with the estimate unless --force (docs/formats.md).\n"
    "\n"
    "Exit status: 0 success, 1 runtime failure, 2 bad input (one line naming the file and the field).";

// True when `text` is a finite number (what the script reads with float()).
bool finite_number(const std::string& text) {
  char* end = nullptr;
  const double x = text.empty() ? 0.0 : std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size() && std::isfinite(x);
}

int run_animate(std::span<const std::string> args) {
  std::string scene, results, method, dt, from, to, fps, per_step, out;
  bool force = false;
  CommandLine cli("animate", kAnimateDescription, "animate");
  cli.footer(kAnimateFooter);
  cli.positional("SCENE.json", scene, "the scene of the results");
  cli.text("--results", results, "RESULTS.json", "a results file of this scene (ccdlab run)");
  cli.text("--method", method, "METHOD", "the method whose record is drawn (e.g. aabb/sap)");
  // Each number is checked here and handed to the script as it was written.
  auto number = [&cli](const char* name, std::string& slot, double above) {
    return [&cli, name, &slot, above](const std::string& v) {
      if (!finite_number(v) || !(std::strtod(v.c_str(), nullptr) > above))
        cli.fail(std::string(name) + ": must be a finite number" + (std::isinf(above) ? "" : " > 0") + ", got '" +
                 v + "'");
      slot = v;
    };
  };
  auto count = [&cli](const char* name, std::string& slot) {
    return [&cli, name, &slot](const std::string& v) {
      if (!ccd::parse_integer(v, 1, 100)) cli.fail(std::string(name) + ": must be an integer in [1, 100], got '" + v + "'");
      slot = v;
    };
  };
  cli.value("--dt", "DT", "the record's timestep (s), a finite number > 0", number("--dt", dt, 0.0));
  cli.value("--from", "T0", "first time drawn (s; default 0)", number("--from", from, -INFINITY));
  cli.value("--to", "T1", "last time drawn (s; default the horizon)", number("--to", to, -INFINITY));
  cli.value("--fps", "N", "frames per second of the animation, in [1, 100] (default 12)", count("--fps", fps));
  cli.value("--frames-per-step", "K", "frames drawn per timestep dt, in [1, 100] (default 6)",
            count("--frames-per-step", per_step));
  cli.text("-o,--output", out, "OUT", "the animation: OUT.gif, or OUT.mp4 (with ffmpeg)");
  cli.flag("--force", force, "animate past the work estimate's limits");
  try {
    if (!cli.parse(args)) return 0;
    if (scene.empty()) cli.fail("missing SCENE.json");
    if (results.empty()) cli.fail("missing --results RESULTS.json");
    if (method.empty()) cli.fail("missing --method METHOD");
    if (dt.empty()) cli.fail("missing --dt DT");
    if (out.empty()) cli.fail("missing -o OUT.gif or -o OUT.mp4");
  } catch (...) {
    return command_failed("animate");
  }
  // The script gets the arguments in a form no file name can be mistaken in: options
  // joined to their values, the scene after "--".
  std::vector<std::string> script_args = {"--results=" + results, "--method=" + method, "--dt=" + dt,
                                          "--output=" + out};
  if (!from.empty()) script_args.push_back("--from=" + from);
  if (!to.empty()) script_args.push_back("--to=" + to);
  if (!fps.empty()) script_args.push_back("--fps=" + fps);
  if (!per_step.empty()) script_args.push_back("--frames-per-step=" + per_step);
  if (force) script_args.emplace_back(std::string_view("--force"));
  script_args.emplace_back(std::string_view("--"));
  script_args.push_back(scene);
  return run_python_script("animate", "animate.py", script_args);
}

}  // namespace

extern const Command kAnimateCommand = {
    "animate", "draw what a method saw and every contact it missed, as a GIF or MP4", run_animate};

}  // namespace ccdlab
