// `ccdlab poses SCENE.json --times A:B:STEP -o POSES.csv`: every body's pose at
// A, A + STEP, ..., up to B, from the scene's motion model (centres from the exact
// trajectories, orientations from the prescribed or free spin), as CSV.
#include "command.hpp"
#include "command_line.hpp"

#include "../experiments/work_estimate.hpp"

#include <ccd/io/atomic_file.hpp>
#include <ccd/motion/rotation.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_io.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>
#include <optional>
#include <string>

namespace ccdlab {
namespace {

constexpr const char* kPosesDescription =
    "Writes every body's pose at the times A, A + STEP, A + 2 STEP, ... up to B (each time\n"
    "computed as A + k STEP) from the scene's motion model: the centre from the exact\n"
    "trajectory (walls, gravity, acceleration changes) and the orientation from the\n"
    "prescribed or free spin (docs/rigid_bodies.md). Columns:\n"
    "  body,t,x,y,z,qw,qx,qy,qz\n"
    "body is the index in the scene, (x, y, z) the centre in metres, q the unit quaternion\n"
    "(body to world, qw >= 0; the identity for bodies that do not turn); rows by time,\n"
    "then body; numbers with 17 significant digits.\n";

constexpr double kMaxRows = 1e7;

std::optional<double> parse_number(const std::string& s) {
  if (s.empty()) return std::nullopt;
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !std::isfinite(x)) return std::nullopt;
  return x;
}

// The times A:B:STEP of --times.
struct Times {
  double a = 0.0, b = 0.0, step = 0.0;
};

Times parse_times(const CommandLine& cli, const std::string& times) {
  const std::size_t c1 = times.find(':'), c2 = c1 == std::string::npos ? c1 : times.find(':', c1 + 1);
  if (c2 == std::string::npos || times.find(':', c2 + 1) != std::string::npos)
    cli.fail("--times must be A:B:STEP, got '" + times + "'");
  const auto A = parse_number(times.substr(0, c1)), B = parse_number(times.substr(c1 + 1, c2 - c1 - 1)),
             step = parse_number(times.substr(c2 + 1));
  if (!A || !B || !step) cli.fail("--times A:B:STEP needs three finite numbers, got '" + times + "'");
  if (!(*step > 0.0)) cli.fail("--times: STEP must be > 0, got '" + times + "'");
  if (!(*A >= 0.0 && *A <= *B)) cli.fail("--times: need 0 <= A <= B, got '" + times + "'");
  return {*A, *B, *step};
}

int run_poses(std::span<const std::string> args) {
  std::string scene_path, out_path, times;
  bool force = false;
  CommandLine cli("poses", kPosesDescription, "poses");
  cli.footer("Exit status: 0 success, 1 runtime failure, 2 bad input or usage (no file written).");
  cli.positional("SCENE.json", scene_path, "the scene");
  cli.text("--times", times, "A:B:STEP",
           "0 <= A <= B <= horizon, STEP > 0, at most 10000000 rows in all\n"
           "unless --force (refused before the work with the estimate)",
           "missing value after --times");
  cli.text("-o,--output", out_path, "POSES.csv", "the output (written atomically; '-' = stdout)",
           "missing value after -o");
  cli.flag("--force", force, "write more than 10000000 rows");
  Times t;
  try {
    if (!cli.parse(args)) return 0;
    if (scene_path.empty()) cli.fail("missing SCENE.json");
    if (times.empty()) cli.fail("missing --times A:B:STEP");
    if (out_path.empty()) cli.fail("missing -o POSES.csv");
    t = parse_times(cli, times);
  } catch (...) {
    return command_failed("poses");
  }
  const double* A = &t.a;
  const double* B = &t.b;
  const double* step = &t.step;
  try {
    const std::string inputs[] = {scene_path};
    ccd::OutputFile output(out_path, inputs);
    const ccd::Scene scene = ccd::load_scene(scene_path);
    if (*B > scene.horizon)
      cli.fail("--times: B must be at most the scene's horizon " + std::to_string(scene.horizon) + ", got '" + times +
               "'");
    const double count = std::floor((*B - *A) / *step) + 1.0;
    if (!(count <= 0x1p53))  // k STEP exact, k a long long, even with --force
      cli.fail("--times gives " + work_number(count) + " times, more than 2^53");
    check_work({count * static_cast<double>(scene.bodies.size()), kMaxRows, "rows",
                work_number(count) + " times x " + std::to_string(scene.bodies.size()) + " bodies"},
               force, scene_path, "--times");
    const ccd::Trajectories traj(scene);
    const ccd::Rotations rot(scene);
    std::string text = "body,t,x,y,z,qw,qx,qy,qz\n";
    char line[512];
    const auto n = static_cast<long long>(count);
    for (long long k = 0; k < n; ++k) {
      const double t = std::min(*A + static_cast<double>(k) * *step, *B);
      for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const ccd::Vec3 p = traj.position(i, t);
        ccd::Quat q = rot.empty() ? ccd::Quat::Identity() : rot.orientation(i, t);
        if (q.w() < 0.0) q.coeffs() = -q.coeffs();
        std::snprintf(line, sizeof line, "%zu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", i, t, p.x(), p.y(),
                      p.z(), q.w(), q.x(), q.y(), q.z());
        text += line;
      }
    }
    output.commit(text);
  } catch (...) {
    return command_failed("poses", "writing the poses of " + scene_path);
  }
  return 0;
}

}  // namespace

extern const Command kPosesCommand = {"poses", "every body's position and orientation at given times, as CSV",
                                      run_poses};

}  // namespace ccdlab
