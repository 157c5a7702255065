// `ccdlab truth SCENE.json [-o OUT.json] [--threads N] [--windows N] [--quiet]`:
// exact contact intervals of every pair (ground truth, format ccdlab-truth/2).
#include "command.hpp"
#include "command_line.hpp"

#include "../experiments/progress.hpp"
#include "../experiments/work_estimate.hpp"

#include <ccd/io/atomic_file.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_digest.hpp>
#include <ccd/scene/scene_io.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/truth/truth.hpp>
#include <ccd/truth/truth_io.hpp>
#include <ccd/util/integer_text.hpp>

#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>
#include <new>
#include <optional>

namespace ccdlab {
namespace {

constexpr const char* kTruthDescription =
    "Computes every maximal closed time interval in [0, horizon] during which two bodies\n"
    "touch or overlap (distance of centres <= sum of radii), exactly (docs/truth.md), and,\n"
    "for a scene with scenery, every interval during which a body touches a static polygon\n"
    "(static_events, docs/scenery.md).\n";

constexpr const char* kTruthFooter =
    "Without -o a summary is printed. Exit status: 0 success, 1 runtime failure,\n"
    "2 bad input or usage (no file written).";

// More windows than this cost more in box work and memory than they can save.
constexpr unsigned long kMaxWindows = 1000000;

// A scene with shapes: the certified truth's work, refused past the limit unless forced;
// returns it (the summary prints it).
double check_truth_work(const ccd::Scene& scene, const ccd::Trajectories& traj, bool force, const std::string& file) {
  const double work = certified_pair_work(ccd::RigidMotion(scene, traj));
  check_work({work, kMaxPairWorkWithoutForce, "certified pair tests",
              std::to_string(scene.bodies.size()) + " bodies with shapes, " + kPairWorkDetail},
             force, file, "bodies");
  return work;
}

int run_truth(std::span<const std::string> args) {
  std::string scene_path, out_path;
  bool quiet = false, force = false;
  ccd::TruthOptions options;
  CommandLine cli("truth", kTruthDescription, "truth");
  cli.footer(kTruthFooter);
  cli.positional("SCENE.json", scene_path, "the scene (ccdlab-scene/1 or /2, or binary)");
  cli.text("-o,--output", out_path, "OUT.json",
           "write the intervals as ccdlab-truth/2 (atomically; '-' = stdout); checked\n"
           "before the work: a regular file, not the scene, in a folder that takes a file",
           "missing value after -o");
  // The integers' messages name the limit when a value is a positive integer above it.
  auto positive = [&cli](const std::string& name, const std::string& v, unsigned long most) {
    const auto n = ccd::parse_integer(v, 1, 999999999);
    if (!n) cli.fail(name + " needs a positive integer, got '" + v + "'");
    if (*n > most) cli.fail(name + " must be at most " + std::to_string(most) + ", got " + v);
    return *n;
  };
  cli.value(
      "--threads", "N",
      "worker threads, at most 4096 (default: one per core); the result does not\n"
      "depend on it",
      [&](const std::string& v) { options.threads = static_cast<unsigned>(positive("--threads", v, 4096)); },
      "missing value after --threads");
  cli.value(
      "--windows", "N",
      "time windows of the space-time broad phase, at most 1000000 (default:\n"
      "automatic)",
      [&](const std::string& v) { options.windows = positive("--windows", v, kMaxWindows); },
      "missing value after --windows");
  cli.flag("-q,--quiet", quiet, "print no summary and no progress");
  cli.flag("--force", force,
           "compute a scene with shapes whose estimated work (certified pair tests:\n"
           "candidate pairs x bracket evaluations x hull points, docs/formats.md) is\n"
           "above 1e9; without it such a scene is refused before the work with the\n"
           "estimate");
  try {
    if (!cli.parse(args)) return 0;
    if (scene_path.empty()) cli.fail("missing SCENE.json");
  } catch (...) {
    return command_failed("truth");
  }
  std::string doing = "reading " + scene_path;
  try {
    std::optional<ccd::OutputFile> output;
    const std::string inputs[] = {scene_path};
    if (!out_path.empty()) output.emplace(out_path, inputs);
    const auto start = std::chrono::steady_clock::now();
    const ccd::Scene scene = ccd::load_scene(scene_path);
    const auto loaded = std::chrono::steady_clock::now();
    doing = "building the trajectories of " + std::to_string(scene.bodies.size()) + " bodies";
    const ccd::Trajectories traj = [&] {
      try {
        return ccd::Trajectories(scene);
      } catch (const ccd::TooManyPieces& e) {
        throw ccd::InputError(scene_path, "bodies[" + std::to_string(e.body()) + "]",
                              "needs more than " + std::to_string(e.limit()) +
                                  " trajectory pieces over the horizon (wall reflections and acceleration changes; "
                                  "a body bouncing ever faster or too fast for its box)");
      }
    }();
    const double work = scene.has_non_spheres() ? check_truth_work(scene, traj, force, scene_path) : 0.0;
    const auto built = std::chrono::steady_clock::now();
    doing = "computing the ground truth of " + std::to_string(scene.bodies.size()) + " bodies" +
            (options.windows ? " in " + std::to_string(options.windows) + " windows" : std::string());
    Progress progress(0, quiet);  // on stderr: a bar on a terminal, a line every 10 s otherwise
    options.progress = [&progress](std::size_t solved, std::size_t total) {
      progress.advance("candidate pairs solved", solved, total);
    };
    if (!scene.scenery.empty())
      doing += " and their static events against " + std::to_string(scene.scenery.size()) + " polygons";
    // One call for every kind of scene (ccd/truth/truth.hpp): exact for spheres, certified
    // brackets for other shapes, static events with scenery.
    const ccd::RigidMotion motion(scene, traj);
    ccd::Truth truth = ccd::compute_truth(motion, scene.scenery, options);
    truth.scene_sha256 = ccd::scene_digest(scene);
    const auto done = std::chrono::steady_clock::now();
    auto secs = [](auto from, auto to) { return std::chrono::duration<double>(to - from).count(); };
    doing = "writing " + out_path;
    if (output) output->commit(ccd::truth_to_text(truth));
    if (quiet || out_path == "-") return 0;
    std::size_t tangent = 0;
    for (const ccd::ContactEvent& e : truth.events) tangent += e.enter == e.exit;
    const ccd::TruthStats& st = truth.stats;
    std::cout << "scene        " << scene_path << "\n"
              << "bodies       " << scene.bodies.size() << " (horizon " << scene.horizon << " s, motion "
              << ccd::to_string(scene.motion_kind()) << ", " << traj.total_pieces() << " trajectory pieces)\n"
              << "events       " << truth.events.size() << " (" << tangent << " tangent"
              << (truth.errors.empty() ? std::string()
                                       : ", " + std::to_string(st.grazing) + " grazing, " +
                                             std::to_string(st.undecided) + " undecided")
              << ")\n"
              << "pairs        " << st.pairs_in_contact << " in contact; " << st.candidate_pair_windows
              << " candidate pair-windows in " << st.windows << " windows, " << st.candidate_runs
              << " solved exactly\n";
    if (!scene.scenery.empty()) {
      std::size_t static_tangent = 0;
      for (const ccd::StaticEvent& e : truth.static_events) static_tangent += e.enter == e.exit;
      std::cout << "static       " << truth.static_events.size() << " events (" << static_tangent << " tangent"
                << (scene.has_non_spheres() ? ", " + std::to_string(st.static_grazing) + " grazing, " +
                                                  std::to_string(st.static_undecided) + " undecided"
                                            : std::string())
                << ") against "
                << scene.scenery.size() << " polygons\n";
    }
    if (scene.has_non_spheres())
      std::cout << "work         " << work_number(work) << " certified pair tests estimated (limit "
                << work_number(kMaxPairWorkWithoutForce) << " without --force)\n";
    char time_text[160];
    std::snprintf(time_text, sizeof time_text, "%.3f s: load %.3f s, trajectories %.3f s, truth %.3f s (%u threads)",
                  secs(start, done), secs(start, loaded), secs(loaded, built), secs(built, done), st.threads);
    std::cout << "time         " << time_text << "\n";
    if (!out_path.empty()) std::cout << "written      " << out_path << "\n";
  } catch (...) {
    return command_failed("truth", doing);
  }
  return 0;
}

}  // namespace

extern const Command kTruthCommand = {"truth", "exact contact intervals of every pair of a scene (ground truth)",
                                      run_truth};

}  // namespace ccdlab
