// `ccdlab run EXPERIMENT.json [-o RESULTS.json] [--threads N] [--shard K/N] [--truth FILE] [--quiet]
//  [--force] [--list-missed]`
#include "command.hpp"
#include "command_line.hpp"

#include "cloth_experiment_work.hpp"
#include "../experiments/run_cloth_experiment.hpp"
#include "../experiments/prepare_run.hpp"
#include "../experiments/run_experiment.hpp"
#include "../experiments/missed_list.hpp"
#include "../experiments/summary.hpp"
#include "../experiments/work_estimate.hpp"

#include <ccd/io/atomic_file.hpp>
#include <ccd/io/json_reader.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/truth/truth_io.hpp>
#include <ccd/util/integer_text.hpp>
#include <ccd/util/parallel_for.hpp>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <cstdio>
#include <iostream>
#include <new>
#include <optional>
#include <thread>
#include <unistd.h>

namespace ccdlab {
namespace {

std::atomic<bool> g_cancel{false};

// Leaves at once, writing nothing: the temporary files are removed.
extern "C" void leave_now(int) {
  constexpr char kLine[] = "ccdlab run: interrupted; no results written\n";
  ccd::remove_pending_temporary_files();
  [[maybe_unused]] const auto n = ::write(STDERR_FILENO, kLine, sizeof kLine - 1);
  ::_exit(130);
}

// The first SIGINT or SIGTERM asks the jobs to stop at their next step; if they have not
// within a second (a long truth or narrow-phase computation between two checks), the
// alarm leaves at once. A second signal leaves at once too.
extern "C" void on_signal(int sig) {
  if (g_cancel.exchange(true)) leave_now(sig);
  ::alarm(1);
}

void install_cancel_handlers() {
  std::signal(SIGALRM, leave_now);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

// The results and their summary side-file, written as one (neither is left without the other).
void commit_with_summary(ccd::OutputFile& output, std::optional<ccd::OutputFile>& summary,
                         const nlohmann::json& results) {
  const std::string text = results.dump(1) + "\n";
  if (!summary) return output.commit(text);
  const std::string markdown = summary_markdown(results);
  ccd::OutputFile* files[] = {&output, &*summary};
  const std::string_view texts[] = {text, markdown};
  ccd::commit_together(files, texts);
}

// A cloth experiment (ccdlab-cloth-experiment/1): simulate, exact mesh truth (cached in
// TRUTH_CACHE, by default the folder cloth-truth beside the results), every job.
int run_cloth(const std::string& experiment_path, std::string out_path, int threads, bool quiet,
              std::string truth_cache, bool force) {
  ClothExperiment e = load_cloth_experiment(experiment_path);
  const ccd::cloth::ClothScene scene = load_cloth_experiment_scene(e, experiment_path);
  check_cloth_experiment_work(e, scene, experiment_path, force);
  if (out_path.empty()) out_path = "results/" + e.name + ".json";
  if (truth_cache.empty() && out_path != "-")
    truth_cache = (std::filesystem::path(out_path).parent_path() / "cloth-truth").string();
  const std::string inputs[] = {experiment_path, e.scene_path.empty() ? std::string("-") : e.scene_path};
  ccd::OutputFile output(out_path, inputs, /*create_folder=*/true);
  std::optional<ccd::OutputFile> summary;  // the side-file, checked now and written with the results
  if (out_path != "-") summary.emplace(summary_path(out_path), inputs);
  ClothRunOptions options;
  options.threads = threads;
  options.quiet = quiet;
  options.truth_cache = truth_cache;
  options.cancel = &g_cancel;
  install_cancel_handlers();
  const nlohmann::json results = run_cloth_experiment(e, scene, options);
  if (results.is_null()) {
    ::alarm(0);  // stopped in time: the message once
    std::cerr << "ccdlab run: interrupted; no results written\n";
    return 130;
  }
  commit_with_summary(output, summary, results);
  (out_path == "-" ? std::cerr : std::cout) << "\n" << summary_text(results) << "\n";
  if (summary) std::cout << "results: " << out_path << "\nsummary: " << summary->path() << "\n";
  return 0;
}

constexpr const char* kRunDescription =
    "Runs every method of the experiment at every timestep against the scene's exact\n"
    "ground truth and writes a ccdlab-results/2 file (docs/experiments.md). Then prints a\n"
    "summary (the contacts to detect, body-body and body-scenery; per method: the largest\n"
    "dt with no miss at it and below, the cheapest zero-miss cost, the missed contacts at\n"
    "every dt) and writes it as Markdown beside the results (RESULTS.summary.md).\n"
    "\n"
    "A cloth experiment runs every culler in the discrete and continuous modes at every\n"
    "check interval k against the exact mesh truth (docs/experiments.md#cloth-experiments).\n";

constexpr const char* kRunFooter =
    "Ctrl-C or SIGTERM stops the run within a second, writing nothing.\n"
    "\n"
    "Exit status: 0 success, 1 runtime failure, 2 bad input (nothing written), 130 interrupted.";

// `ccdlab run`'s arguments.
struct RunArguments {
  std::string experiment_path, out_path, truth_path, truth_cache;
  bool force = false, list_missed = false;
};

void declare_run_options(CommandLine& cli, RunArguments& a, RunOptions& options) {
  cli.positional("EXPERIMENT.json", a.experiment_path, "the experiment (ccdlab-experiment/1 or ccdlab-cloth-experiment/1)");
  cli.text("-o,--output", a.out_path, "FILE",
           "results file (default results/NAME.json, relative to the current\n"
           "directory; '-' = standard output);\n"
           "checked before the run (a regular file, not an input, in a folder\n"
           "that takes a file), written atomically, never partially (Ctrl-C\n"
           "leaves no file); RESULTS.summary.md is checked with it and written\n"
           "with it (neither is left without the other)",
           "-o needs a file name");
  cli.integer("--threads", 1, 4096, "N",
              "worker threads over (method, dt) jobs and for the ground truth\n"
              "(default: all cores); counts do not depend on N",
              [&options](std::uint64_t n) { options.threads = static_cast<int>(n); });
  cli.value(
      "--shard", "K/N",
      "run only jobs j with j mod N == K-1 (1 <= K <= N), for batch\n"
      "systems; join the shard files with `ccdlab merge`",
      [&cli, &options](const std::string& v) {
        const auto slash = v.find('/');
        const auto k = slash == std::string::npos ? std::nullopt : ccd::parse_integer(v.substr(0, slash), 1, 4096);
        const auto n = slash == std::string::npos ? std::nullopt : ccd::parse_integer(v.substr(slash + 1), 1, 4096);
        if (!k || !n || *k > *n) cli.fail("--shard needs K/N with 1 <= K <= N");
        options.shard.index = static_cast<int>(*k);
        options.shard.count = static_cast<int>(*n);
      },
      "--shard needs K/N with 1 <= K <= N");
  cli.text("--truth", a.truth_path, "FILE",
           "reuse the ground truth in FILE (`ccdlab truth SCENE.json -o FILE`)\n"
           "instead of computing it; FILE's scene digest must be this scene's\n"
           "(else exit 2); a ccdlab-truth/1 file is checked only for its\n"
           "horizon and body indices",
           "--truth needs a truth file (ccdlab truth SCENE.json -o FILE)");
  cli.flag("-q,--quiet", options.quiet, "no progress on stderr");
  cli.flag("--force", a.force,
           "run even when the work estimate (bodies x steps, summed over the\n"
           "jobs) is above 1e11 body-steps or, with shaped bodies, the certified\n"
           "pair tests (candidate pairs x evaluations x hull points, of the truth and\n"
           "of the narrow phase) are above 1e9; a cloth experiment: above 1e9\n"
           "particle-steps of simulation, 4e9 bytes of states kept or 1e10\n"
           "particle-steps of checks over its jobs (docs/formats.md)");
  cli.flag("--list-missed", a.list_missed,
           "every record lists the contact events it missed (missed_events:\n"
           "a, b, enter, exit; static_missed_events: body, polygon, enter,\n"
           "exit), as the experiment option \"list_missed\": true; after the\n"
           "summary, per method at the largest dt at which it missed a contact,\n"
           "the missed contacts (at most 20 lines in all, then a count)");
  cli.value(
      "--truth-cache", "DIR",
      "cloth experiments (ccdlab-cloth-experiment/1): where the exact\n"
      "mesh truth is kept, one file per motion digest, read back when\n"
      "present (default: cloth-truth/ beside the results file)",
      [&cli, &a](const std::string& v) {
        if (v.empty()) cli.fail("--truth-cache needs a folder");
        a.truth_cache = v;
      },
      "--truth-cache needs a folder");
}

int run_run(std::span<const std::string> args) {
  CommandLine cli("run", kRunDescription, "run");
  cli.footer(kRunFooter);
  RunArguments a;
  RunOptions options;
  options.threads = static_cast<int>(ccd::resolve_threads(0));
  declare_run_options(cli, a, options);
  std::string& experiment_path = a.experiment_path;
  std::string& out_path = a.out_path;
  std::string& truth_path = a.truth_path;
  std::string& truth_cache = a.truth_cache;
  const bool& force = a.force;
  const bool& list_missed = a.list_missed;
  std::string summary_file;
  try {
    if (!cli.parse(args)) return 0;
    if (experiment_path.empty()) cli.fail("missing EXPERIMENT.json");
  } catch (...) {
    return command_failed("run");
  }

  try {
    // A pipe is read once, by the sphere runner; a cloth experiment is a regular file.
    std::error_code ec;
    if (std::filesystem::is_regular_file(experiment_path, ec) &&
        is_cloth_experiment(ccd::read_json_file(experiment_path))) {
      if (options.shard.count > 1 || !truth_path.empty() || list_missed)
        cli.fail("--shard, --truth and --list-missed apply to sphere and rigid experiments only");
      return run_cloth(experiment_path, out_path, options.threads, options.quiet, truth_cache, force);
    }
    if (!truth_cache.empty()) cli.fail("--truth-cache applies to cloth experiments only");
  } catch (...) {
    return command_failed("run", "running " + experiment_path);
  }

  // What is being done, for the one line that says what was too big if memory runs out.
  std::string doing = "reading " + experiment_path;
  try {
    RunRequest request;
    request.truth_file = truth_path;
    request.force = force;
    request.list_missed = list_missed;
    request.shard = options.shard;
    const PreparedRun run = prepare_run(experiment_path, request, &doing);  // the library's checks
    const Experiment& e = run.experiment;
    if (!truth_path.empty() && !run.truth_has_digest && !options.quiet)
      std::cerr << "ccdlab run: note: " << truth_path << " is " << ccd::kTruthFormatV1
                << " (no scene digest): only its horizon and body indices were checked\n";
    if (out_path.empty()) {
      out_path = "results/" + e.name +
                 (options.shard.count > 1 ? ".shard" + std::to_string(options.shard.index) + "of" +
                                                std::to_string(options.shard.count)
                                          : std::string()) +
                 ".json";
    }
    const std::string inputs[] = {experiment_path, e.scene_path.empty() ? std::string("-") : e.scene_path,
                                  truth_path.empty() ? std::string("-") : truth_path};
    ccd::OutputFile output(out_path, inputs, /*create_folder=*/true);
    std::optional<ccd::OutputFile> summary;  // the side-file, checked now and written with the results
    if (out_path != "-") summary.emplace(summary_path(out_path), inputs);
    if (!options.quiet)
      std::cerr << "ccdlab: work: " << work_number(run.work) << " body-steps (" << run.scene.bodies.size()
                << " bodies, up to " << work_number(run.most_steps) << " steps per job)"
                << (run.pair_work > 0.0 ? ", " + work_number(run.pair_work) + " certified pair tests" : std::string())
                << "\n";

    options.cancel = &g_cancel;
    install_cancel_handlers();
    doing = "running " + std::to_string(e.methods.size() * e.dt.size()) + " jobs over " +
            std::to_string(run.scene.bodies.size()) + " bodies";
    const nlohmann::json results = run_prepared(run, options);
    if (results.is_null()) {
      ::alarm(0);  // stopped in time: the message once
      std::cerr << "ccdlab run: interrupted; no results written\n";
      return 130;
    }
    doing = "writing " + out_path;
    // The answer in one table: on the terminal (stderr when the results go to stdout) and
    // beside the results as Markdown, written together with them.
    commit_with_summary(output, summary, results);
    std::ostream& terminal = out_path == "-" ? std::cerr : std::cout;
    terminal << "\n" << summary_text(results) << "\n";
    if (e.list_missed) terminal << missed_list_text(results) << "\n";  // which contacts, after the table
    if (summary) summary_file = summary->path();
    if (!options.quiet) {
      std::size_t flagged = 0;
      for (const auto& r : results["records"]) flagged += !r["self_check"]["ok"].get<bool>();
      std::cerr << "ccdlab: " << results["records"].size() << " records, ground truth "
                << results["truth"]["events"] << " events"
                << (flagged ? ", " + std::to_string(flagged) + " records FAILED the self-check" : std::string())
                << "\n";
    }
  } catch (...) {
    return command_failed("run", doing);
  }
  if (out_path != "-") std::cout << "results: " << out_path << "\nsummary: " << summary_file << "\n";
  return 0;
}

}  // namespace

extern const Command kRunCommand = {
    "run", "run an experiment: sweep dt, run every method, compare with ground truth (JSON results)", run_run};

}  // namespace ccdlab
