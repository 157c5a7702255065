// `ccdlab animate SCENE.json --results RESULTS.json --method M --dt DT ...`: scripts/animate.py
// (see python_script.hpp).
#include "command.hpp"
#include "python_script.hpp"

namespace ccdlab {
namespace {

int run_animate(std::span<const std::string> args) {
  return run_python_script("animate", "animate.py", args);
}

}  // namespace

extern const Command kAnimateCommand = {
    "animate", "draw what a method saw and every contact it missed, as a GIF or MP4",
    "usage: ccdlab animate SCENE.json --results RESULTS.json --method METHOD --dt DT\n"
    "                      [--from T0] [--to T1] [--fps N] [--frames-per-step K] [--force]\n"
    "                      -o OUT.gif|OUT.mp4\n"
    "\n"
    "Animates the scene from T0 to T1 (default: the whole horizon): every body, projected on\n"
    "the two widest axes of the box; the samples the method took (every dt); each contact\n"
    "the method missed, highlighted in red where and when it happened; a zoom on the missed\n"
    "contact nearest in time; a time line of the samples and the missed contacts. The method\n"
    "and dt must be a record of RESULTS.json, whose scene must be SCENE.json (same digest); the\n"
    "missed contacts are recomputed with the ccdlab Python module and checked against the\n"
    "record's count. .mp4 needs ffmpeg. Runs scripts/animate.py with /usr/bin/python3.\n"
    "\n"
    "The work is estimated first: more than 2000 frames, 2e6 body-frames (bodies x frames) or\n"
    "1e11 body-steps for the run that finds the missed contacts (bodies x horizon / dt) is\n"
    "refused with the estimate unless --force (docs/formats.md).\n"
    "\n"
    "Exit status: 0 success, 1 runtime failure, 2 bad input (one line naming the file and the field).\n",
    run_animate};

}  // namespace ccdlab
