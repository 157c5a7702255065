// ccdlab's broad phases side by side with FCL 0.7, Bullet 3.24 (double precision) and
// Boost.Geometry 1.74 on the shared moving-spheres scene (benchmarks/support/peer_scene.hpp), following the peers' protocol: frame 0 = setup (register
// the bodies, first query; timed apart), frames 1-2 warm-up, frames 3-22 measured, median
// per frame. A frame is the method's update + query + collection of its pairs; the scene's
// motion is not timed. Both the thread's CPU time and wall-clock time are recorded (on a
// shared machine the CPU time is the one other processes do not inflate).
//
// Exactness: the reference pair count and pair-set checksum of every frame 0..22 come from
// brute force (N <= 10,000) or `grid` (larger N; `grid` is tested against brute force in
// tests/ccd/broad_phase/), and frames 0 and 22 are checked against the published table.
// Every method's count AND checksum are compared with the reference in EVERY frame; a
// mismatch is reported as an error. Peers whose libraries report supersets are filtered to
// the exact pairs inside the timed frame; the output says which ("filtered").
//
// Isolation and memory: each (method, N) runs in a forked child process on its own copy of
// the scene, so one method's heap cannot slow another. Peak memory = the child's peak
// resident set (VmHWM, reset just before the method is created) minus its resident set at
// that moment: the method's structures and its pair list, not the scene.
//
// Skipping: sizes run in increasing order. A method is skipped at a larger size when its
// median CPU ms/frame, scaled linearly to that size, exceeds --max-frame-s (2 s), or when
// its setup is quadratic (btAxisSweep3) and the scaled setup exceeds 10x that. A frame
// that itself exceeds the limit stops the run ("skipped").
//
//   peers_bench [--sizes=1000,10000,100000,1000000] [--methods=grid,fcl_sap,...]
//               [--json OUT.json] [--max-frame-s=2]
#include "peer_method.hpp"

#include <ccd/broad_phase/brute_force.hpp>
#include <ccd/broad_phase/grid.hpp>
#include <benchmarks/support/peer_scene.hpp>
#include <ccd/io/atomic_file.hpp>
#include <ccd/util/integer_text.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <ctime>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace {

using ccdlab::peers::PeerInfo;

constexpr int kWarmup = 2;
constexpr int kMeasured = 20;
constexpr int kFrames = 1 + kWarmup + kMeasured;  // 0 .. 22

double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

double wall_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return 0.5 * (v[(v.size() - 1) / 2] + v[v.size() / 2]);
}

long status_kb(const char* field) {
  std::ifstream f("/proc/self/status");
  std::string line;
  const std::size_t len = std::strlen(field);
  while (std::getline(f, line))
    if (line.compare(0, len, field) == 0) return std::strtol(line.c_str() + len + 1, nullptr, 10);
  return -1;
}

std::string load_average() {
  std::ifstream f("/proc/loadavg");
  std::string a, b, c;
  f >> a >> b >> c;
  return a + " " + b + " " + c;
}

struct FrameRef {
  std::uint64_t pairs = 0;
  std::uint64_t checksum = 0;
};

/// Result of one (method, N) run, passed from the child through a pipe.
struct RunResult {
  enum Status : int { kOk = 0, kMismatch = 1, kSkipped = 2, kCrashed = 3, kNotRun = 4 };
  int status = kNotRun;
  double setup_ms = 0;         // wall
  double median_cpu_ms = 0;
  double min_cpu_ms = 0;
  double median_wall_ms = 0;
  double pairs_per_frame = 0;
  double reported_per_frame = 0;  // before the exact filter (0: the method has no such count)
  double peak_mb = 0;
  int frames_verified = 0;
  char message[240] = {};
};

void set_message(RunResult& r, const std::string& m) {
  std::snprintf(r.message, sizeof r.message, "%s", m.c_str());
}

RunResult run_child(const PeerInfo& info, std::size_t n, const std::vector<FrameRef>& ref, double max_frame_ms) {
  RunResult r;
  ccdlab::bench::PeerScene scene(n, 1);
  std::vector<ccd::Aabb> boxes;
  std::vector<ccd::BodyPair> pairs;
  scene.boxes(boxes);
  {  // reset the peak resident set to the current one (Linux >= 4.0)
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
  }
  const long base_kb = status_kb("VmRSS:");
  auto method = info.make();
  const double s0 = wall_ms();
  method->setup(scene, boxes, pairs);
  r.setup_ms = wall_ms() - s0;
  auto check = [&](int f) {
    const std::uint64_t sum = ccdlab::bench::peer_pair_checksum(pairs);
    if (pairs.size() == ref[f].pairs && sum == ref[f].checksum) {
      ++r.frames_verified;
      return true;
    }
    std::ostringstream os;
    os << "frame " << f << ": " << pairs.size() << " pairs (checksum " << std::hex << sum << std::dec
       << "), reference " << ref[f].pairs;
    set_message(r, os.str());
    r.status = RunResult::kMismatch;
    return false;
  };
  if (!check(0)) return r;
  std::vector<double> cpu, wall;
  double pair_sum = 0, reported_sum = 0;
  for (int f = 1; f < kFrames; ++f) {
    scene.step();
    scene.boxes(boxes);
    const double w0 = wall_ms(), c0 = thread_cpu_ms();
    method->frame(scene, boxes, pairs);
    const double c1 = thread_cpu_ms(), w1 = wall_ms();
    if (!check(f)) return r;
    if (c1 - c0 > max_frame_ms) {
      r.status = RunResult::kSkipped;
      set_message(r, "frame " + std::to_string(f) + " took " + std::to_string((c1 - c0) / 1e3) + " s CPU");
      r.median_cpu_ms = c1 - c0;
      return r;
    }
    if (f > kWarmup) {
      cpu.push_back(c1 - c0);
      wall.push_back(w1 - w0);
      pair_sum += static_cast<double>(pairs.size());
      reported_sum += static_cast<double>(method->reported_pairs());
    }
  }
  r.status = RunResult::kOk;
  r.median_cpu_ms = median(cpu);
  r.min_cpu_ms = *std::min_element(cpu.begin(), cpu.end());
  r.median_wall_ms = median(wall);
  r.pairs_per_frame = pair_sum / kMeasured;
  r.reported_per_frame = reported_sum / kMeasured;
  r.peak_mb = static_cast<double>(status_kb("VmHWM:") - base_kb) / 1024.0;
  return r;
}

RunResult run_isolated(const PeerInfo& info, std::size_t n, const std::vector<FrameRef>& ref, double max_frame_ms) {
  int fd[2];
  RunResult r;
  if (pipe(fd) != 0) {
    r.status = RunResult::kCrashed;
    set_message(r, "pipe failed");
    return r;
  }
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    const RunResult c = run_child(info, n, ref, max_frame_ms);
    const ssize_t w = write(fd[1], &c, sizeof c);
    close(fd[1]);
    _exit(w == static_cast<ssize_t>(sizeof c) ? 0 : 1);
  }
  close(fd[1]);
  std::size_t got = 0;
  auto* bytes = reinterpret_cast<char*>(&r);
  while (got < sizeof r) {
    const ssize_t k = read(fd[0], bytes + got, sizeof r - got);
    if (k <= 0) break;
    got += static_cast<std::size_t>(k);
  }
  close(fd[0]);
  int wstatus = 0;
  waitpid(pid, &wstatus, 0);
  if (got != sizeof r) {
    r = RunResult{};
    r.status = RunResult::kCrashed;
    set_message(r, "child process died (status " + std::to_string(wstatus) + ")");
  }
  return r;
}

const char* status_name(int s) {
  switch (s) {
    case RunResult::kOk: return "ok";
    case RunResult::kMismatch: return "MISMATCH";
    case RunResult::kSkipped: return "skipped";
    case RunResult::kCrashed: return "CRASHED";
    default: return "not run";
  }
}

bool is_ccdlab(const PeerInfo& p) { return p.library == "ccdlab"; }

struct Options {
  std::vector<std::size_t> sizes = {1000, 10000, 100000, 1000000};
  std::vector<std::string> only;  ///< --methods (empty: all)
  std::string json_path;
  double max_frame_s = 2.0;
};

// The options, or exit 2 with one line naming the bad one.
Options parse_options(int argc, char** argv) {
  Options o;
  std::string sizes;
  CLI::App app(
      "ccdlab's broad phases side by side with FCL, Bullet and Boost.Geometry on the shared\n"
      "moving-spheres scene (docs/peers.md).",
      "peers_bench");
  app.add_option("--sizes", sizes, "body counts, comma-separated (default 1000,10000,100000,1000000)");
  app.add_option("--methods", o.only, "methods to run, comma-separated (default: all)")->delimiter(',');
  app.add_option("--json", o.json_path, "also write the results to this JSON file");
  app.add_option("--max-frame-s", o.max_frame_s, "skip a method whose projected frame exceeds this (s)")
      ->check(CLI::Range(0.001, 86400.0));
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::printf("%s", app.help().c_str());
    std::exit(0);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "peers_bench: %s (peers_bench --help lists the options)\n", e.what());
    std::exit(2);
  }
  if (!sizes.empty()) {
    const auto list = ccd::parse_integer_list(sizes, 1, 100000000);
    if (!list) {
      std::fprintf(stderr, "peers_bench: --sizes needs integers in [1, 1e8], e.g. --sizes=1000,10000\n");
      std::exit(2);
    }
    o.sizes.assign(list->begin(), list->end());
  }
  std::sort(o.sizes.begin(), o.sizes.end());
  return o;
}

// Every method of every library, or those --methods names.
std::vector<PeerInfo> select_methods(const std::vector<std::string>& only) {
  std::vector<PeerInfo> methods;
  for (auto* group : {&ccdlab::peers::ccdlab_methods, &ccdlab::peers::fcl_peers, &ccdlab::peers::bullet_peers,
                      &ccdlab::peers::boost_peers})
    for (PeerInfo& p : (*group)())
      if (only.empty() || std::find(only.begin(), only.end(), p.name) != only.end())
        methods.push_back(std::move(p));
  return methods;
}

// The folder of --json is made (and checked) before the work, not after minutes of it.
bool json_folder_writable(const std::string& json_path) {
  const std::filesystem::path folder = std::filesystem::path(json_path).parent_path();
  std::error_code ec;
  if (!folder.empty()) std::filesystem::create_directories(folder, ec);
  return !ec && (folder.empty() || ::access(folder.c_str(), W_OK) == 0);
}

// The reference pair count and checksum of frames 0..22 at size n.
std::vector<FrameRef> reference_frames(std::size_t n, bool use_brute) {
  std::vector<FrameRef> ref(kFrames);
  ccdlab::bench::PeerScene scene(n, 1);
  std::vector<ccd::Aabb> boxes;
  std::vector<ccd::BodyPair> pairs;
  ccd::BruteForce brute;
  ccd::UniformGrid grid;
  for (int f = 0; f < kFrames; ++f) {
    if (f > 0) scene.step();
    scene.boxes(boxes);
    if (use_brute)
      brute.find_pairs(boxes, pairs);
    else
      grid.find_pairs(boxes, pairs);
    ref[f] = {pairs.size(), ccdlab::bench::peer_pair_checksum(pairs)};
  }
  return ref;
}

// Runs every method at every size, prints the tables and keeps the results.
class Session {
 public:
  Session(const Options& options, std::vector<PeerInfo> methods)
      : o_(options), methods_(std::move(methods)) {}

  void run_size(std::size_t n) {
    const bool use_brute = n <= 10000;
    const std::vector<FrameRef> ref = reference_frames(n, use_brute);
    std::string published = "not tabulated";
    for (const auto& p : ccdlab::bench::peer_scene_references())
      if (p.n == n) {
        const bool ok = ref[0].pairs == p.pairs_0 && ref[0].checksum == p.checksum_0 &&
                        ref[kFrames - 1].pairs == p.pairs_22 && ref[kFrames - 1].checksum == p.checksum_22;
        published = ok ? "frames 0 and 22 match the published table" : "DIFFERS from the published table";
        all_exact_ = all_exact_ && ok;
      }
    const std::string load0 = load_average();
    std::printf("\nN = %zu  (reference: %s, %s; load average %s)\n", n, use_brute ? "brute force" : "grid",
                published.c_str(), load0.c_str());
    std::printf("%-30s %-28s %10s %10s %10s %10s %11s %9s  %s\n", "method", "library", "cpu ms", "wall ms",
                "min cpu", "setup ms", "pairs/frame", "peak MB", "status");
    nlohmann::json ref_json = {{"n", n},
                               {"reference", use_brute ? "brute" : "grid"},
                               {"published", published},
                               {"load_average_start", load0}};
    for (const PeerInfo& info : methods_) run_method(info, n, ref);
    ref_json["load_average_end"] = load_average();
    references_.push_back(ref_json);
  }

  // Fastest ccdlab method against the fastest peer per size (median CPU ms/frame).
  nlohmann::json summary() {
    std::printf("\nMedian thread-CPU ms/frame (wall ms in brackets)\n%-30s", "method");
    for (std::size_t n : o_.sizes) std::printf(" %20zu", n);
    std::printf("\n");
    for (const PeerInfo& info : methods_) {
      std::printf("%-30s", info.name.c_str());
      for (std::size_t n : o_.sizes) {
        const RunResult& r = table_[info.name][n];
        char buf[48];
        if (r.status == RunResult::kOk)
          std::snprintf(buf, sizeof buf, "%.3g [%.3g]", r.median_cpu_ms, r.median_wall_ms);
        else
          std::snprintf(buf, sizeof buf, "%s", status_name(r.status));
        std::printf(" %20s", buf);
      }
      std::printf("\n");
    }
    nlohmann::json summary = nlohmann::json::array();
    for (std::size_t n : o_.sizes) {
      const PeerInfo* best_own = nullptr;
      const PeerInfo* best_peer = nullptr;
      for (const PeerInfo& info : methods_) {
        const RunResult& r = table_[info.name][n];
        if (r.status != RunResult::kOk) continue;
        const PeerInfo*& best = is_ccdlab(info) ? best_own : best_peer;
        if (!best || r.median_cpu_ms < table_[best->name][n].median_cpu_ms) best = &info;
      }
      if (!best_own || !best_peer) continue;
      const double a = table_[best_own->name][n].median_cpu_ms, b = table_[best_peer->name][n].median_cpu_ms;
      std::printf("N=%-8zu fastest ccdlab: %s %.3f ms; fastest peer: %s %.3f ms; ratio %.1fx\n", n,
                  best_own->name.c_str(), a, best_peer->name.c_str(), b, b / a);
      summary.push_back({{"n", n},
                         {"fastest_ccdlab", best_own->name},
                         {"fastest_ccdlab_cpu_ms", a},
                         {"fastest_peer", best_peer->name},
                         {"fastest_peer_cpu_ms", b},
                         {"speedup", b / a}});
    }
    return summary;
  }

  nlohmann::json document(const nlohmann::json& summary) const {
    return {{"benchmark", "peers_bench"},
            {"scene", "shared moving-spheres scene, seed 1 (benchmarks/support/peer_scene.hpp)"},
            {"protocol",
             {{"warmup_frames", kWarmup},
              {"measured_frames", kMeasured},
              {"statistic", "median"},
              {"frame", "update + query + pair collection"},
              {"max_frame_s", o_.max_frame_s}}},
            {"nproc", sysconf(_SC_NPROCESSORS_ONLN)},
            {"sizes", o_.sizes},
            {"references", references_},
            {"results", results_},
            {"summary", summary},
            {"all_exact", all_exact_}};
  }

  bool all_exact() const { return all_exact_; }

 private:
  // Why a method is not run at size n (projected from its last size), or "".
  std::string skip_reason(const PeerInfo& info, std::size_t n) const {
    const auto it = last_.find(info.name);
    if (it == last_.end()) return "";
    const auto& [n0, r0] = it->second;
    const double scale = static_cast<double>(n) / static_cast<double>(n0);
    const double max_frame_ms = o_.max_frame_s * 1e3;
    if (r0.status == RunResult::kSkipped) return "skipped at N=" + std::to_string(n0);
    if (r0.median_cpu_ms * scale > max_frame_ms)
      return "projected " + std::to_string(r0.median_cpu_ms * scale / 1e3) +
             " s/frame from N=" + std::to_string(n0);
    if (info.quadratic_setup && r0.setup_ms * scale * scale > 10 * max_frame_ms)
      return "quadratic setup: projected " + std::to_string(r0.setup_ms * scale * scale / 1e3) +
             " s from N=" + std::to_string(n0);
    return "";
  }

  void run_method(const PeerInfo& info, std::size_t n, const std::vector<FrameRef>& ref) {
    RunResult r;
    if (const std::string why = skip_reason(info, n); !why.empty()) {
      r.status = RunResult::kSkipped;
      set_message(r, why);
    } else {
      r = run_isolated(info, n, ref, o_.max_frame_s * 1e3);
      last_[info.name] = {n, r};
    }
    table_[info.name][n] = r;
    if (r.status == RunResult::kMismatch || r.status == RunResult::kCrashed) all_exact_ = false;
    const bool filtered = r.reported_per_frame > r.pairs_per_frame;
    std::string status = status_name(r.status);
    if (r.status == RunResult::kOk && filtered) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "ok, filtered from %.0f reported", r.reported_per_frame);
      status = buf;
    }
    if (r.message[0]) status += std::string(" (") + r.message + ")";
    if (r.status == RunResult::kOk)
      std::printf("%-30s %-28s %10.3f %10.3f %10.3f %10.1f %11.1f %9.1f  %s\n", info.name.c_str(),
                  info.library.c_str(), r.median_cpu_ms, r.median_wall_ms, r.min_cpu_ms, r.setup_ms,
                  r.pairs_per_frame, r.peak_mb, status.c_str());
    else
      std::printf("%-30s %-28s %10s %10s %10s %10s %11s %9s  %s\n", info.name.c_str(), info.library.c_str(),
                  "-", "-", "-", "-", "-", "-", status.c_str());
    std::fflush(stdout);
    nlohmann::json j = {{"method", info.name},
                        {"library", info.library},
                        {"note", info.note},
                        {"n", n},
                        {"status", status_name(r.status)},
                        {"message", r.message}};
    if (r.status == RunResult::kOk)
      j.update({{"median_cpu_ms", r.median_cpu_ms},
                {"min_cpu_ms", r.min_cpu_ms},
                {"median_wall_ms", r.median_wall_ms},
                {"setup_wall_ms", r.setup_ms},
                {"pairs_per_frame", r.pairs_per_frame},
                {"reported_pairs_per_frame", r.reported_per_frame},
                {"filtered_to_exact", filtered},
                {"peak_mb", r.peak_mb},
                {"frames_verified", r.frames_verified}});
    results_.push_back(j);
  }

  const Options& o_;
  std::vector<PeerInfo> methods_;
  nlohmann::json results_ = nlohmann::json::array();
  nlohmann::json references_ = nlohmann::json::array();
  std::map<std::string, std::pair<std::size_t, RunResult>> last_;  ///< last measured size per method
  std::map<std::string, std::map<std::size_t, RunResult>> table_;
  bool all_exact_ = true;
};

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse_options(argc, argv);
  std::vector<PeerInfo> methods = select_methods(options.only);
  if (methods.empty()) {
    std::fprintf(stderr, "peers_bench: no method matches --methods\n");
    return 2;
  }
  if (!options.json_path.empty() && !json_folder_writable(options.json_path)) {
    std::fprintf(stderr, "peers_bench: --json %s: cannot write into folder %s\n", options.json_path.c_str(),
                 std::filesystem::path(options.json_path).parent_path().c_str());
    return 2;
  }
  Session session(options, std::move(methods));
  for (const std::size_t n : options.sizes) session.run_size(n);
  const nlohmann::json summary = session.summary();
  std::printf("%s\n", session.all_exact() ? "every method reported the exact pair set in every frame"
                                          : "SOME METHOD DIFFERED FROM THE REFERENCE (see status)");
  if (!options.json_path.empty()) {
    ccd::write_file_atomically(options.json_path, session.document(summary).dump(1) + "\n");
    std::printf("wrote %s\n", options.json_path.c_str());
  }
  return session.all_exact() ? 0 : 1;
}
