// `ccdlab truth SCENE.json [-o OUT.json] [--threads N] [--windows N] [--quiet]`:
// exact contact intervals of every pair (ground truth, format ccdlab-truth/2).
#include "command.hpp"

#include "../progress.hpp"
#include "../work_estimate.hpp"

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

constexpr const char* kUsage =
    "usage: ccdlab truth SCENE.json [-o OUT.json] [--threads N] [--windows N] [--quiet] [--force]\n"
    "\n"
    "Computes every maximal closed time interval in [0, horizon] during which two bodies\n"
    "touch or overlap (distance of centres <= sum of radii), exactly (docs/truth.md), and,\n"
    "for a scene with scenery, every interval during which a body touches a static polygon\n"
    "(static_events, docs/scenery.md).\n"
    "\n"
    "  -o OUT.json   write the intervals as ccdlab-truth/2 (atomically; '-' = stdout); checked\n"
    "                before the work: a regular file, not the scene, in a folder that takes a file\n"
    "  --threads N   worker threads, at most 4096 (default: one per core); the result does not\n"
    "                depend on it\n"
    "  --windows N   time windows of the space-time broad phase, at most 1000000 (default:\n"
    "                automatic)\n"
    "  --quiet       print no summary and no progress\n"
    "  --force       compute a scene with shapes whose estimated work (certified pair tests:\n"
    "                candidate pairs x bracket evaluations x hull points, docs/formats.md) is\n"
    "                above 1e9; without it such a scene is refused before the work with the\n"
    "                estimate\n"
    "\n"
    "Without -o a summary is printed. Exit status: 0 success, 1 runtime failure,\n"
    "2 bad input or usage (no file written).\n";

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

int usage_error(const std::string& what) {
  std::cerr << "ccdlab truth: " << what << " (see ccdlab truth --help)\n";
  return kExitBadInput;
}

int run_truth(std::span<const std::string> args) {
  std::string scene_path, out_path;
  bool quiet = false, force = false;
  ccd::TruthOptions options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-o" || a == "--output" || a == "--threads" || a == "--windows") {
      if (i + 1 >= args.size()) return usage_error("missing value after " + a);
      const std::string& v = args[++i];
      if (a == "-o" || a == "--output") {
        out_path = v;
      } else {
        const auto n = ccd::parse_integer(v, 1, 999999999);
        if (!n) return usage_error(a + " needs a positive integer, got '" + v + "'");
        if (a == "--threads" && *n > 4096) return usage_error("--threads must be at most 4096, got " + v);
        if (a == "--windows" && *n > kMaxWindows)
          return usage_error("--windows must be at most " + std::to_string(kMaxWindows) + ", got " + v);
        if (a == "--threads") options.threads = static_cast<unsigned>(*n);
        else options.windows = *n;
      }
    } else if (a == "--quiet" || a == "-q") {
      quiet = true;
    } else if (a == "--force") {
      force = true;
    } else if (!a.empty() && a[0] == '-' && a != "-") {
      return usage_error("unknown option '" + a + "'");
    } else if (scene_path.empty()) {
      scene_path = a;
    } else {
      return usage_error("unexpected argument '" + a + "'");
    }
  }
  if (scene_path.empty()) return usage_error("missing SCENE.json");
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
                                      kUsage, run_truth};

}  // namespace ccdlab
