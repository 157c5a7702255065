// `ccdlab truth SCENE.json [-o OUT.json]`: exact contact intervals of every pair.
#include "command.hpp"

#include <ccd/motion/trajectory.hpp>
#include <ccd/scene/input_error.hpp>
#include <ccd/scene/scene_io.hpp>

#include <iostream>

namespace ccdlab {
namespace {

int run_truth(std::span<const std::string> args) {
  if (args.empty()) {
    std::cerr << "ccdlab truth: missing SCENE.json (see ccdlab truth --help)\n";
    return kExitBadInput;
  }
  try {
    const ccd::Scene scene = ccd::load_scene(args[0]);
    const ccd::Trajectories traj(scene);
    std::cout << "scene " << args[0] << ": " << scene.bodies.size() << " bodies, horizon " << scene.horizon
              << " s, motion " << ccd::to_string(scene.motion_kind()) << ", " << traj.total_pieces()
              << " trajectory pieces\n";
  } catch (const ccd::InputError& e) {
    std::cerr << "ccdlab truth: " << e.what() << "\n";
    return kExitBadInput;
  }
  return 0;
}

}  // namespace

extern const Command kTruthCommand = {
    "truth", "exact contact intervals of every pair of a scene (ground truth)",
    "usage: ccdlab truth SCENE.json [-o OUT.json]\n", run_truth};

}  // namespace ccdlab
