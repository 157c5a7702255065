// `ccdlab ccd FILE.csv --kind vf|ee [-o OUT.json]`: runs triangle CCD queries stored in the
// public CCD benchmark's format and measures misses, false positives and time per query.
#include "command.hpp"
#include "command_line.hpp"
#include "mesh_ccd_command.hpp"

#include "../experiments/work_estimate.hpp"

#include <cloth/ccd/hard_queries.hpp>
#include <cloth/ccd/near_miss_queries.hpp>
#include <cloth/cull/cullers.hpp>
#include <cloth/ccd/triangle_ccd.hpp>
#include <cloth/exact/exact_ccd.hpp>
#include <cloth/io/query_file.hpp>
#include <ccd/io/utf8_text.hpp>
#include <ccd/io/atomic_file.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/util/integer_text.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

namespace ccdlab {
namespace {

using ccd::cloth::PrimitivePair;

// A query file is 8 rows of 7 integers per query, about 100 bytes and more: 1e9 bytes
// is ten million queries or more (minutes of the inclusion kernel, hours exactly).
constexpr double kMaxQueryFileBytes = 1e9;

// Quantile q of sorted values (nearest rank).
double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0.0;
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
  return sorted[std::min(sorted.size() - 1, rank == 0 ? 0 : rank - 1)];
}

std::string micros(double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g us", seconds * 1e6);
  return buf;
}

constexpr const char* kCcdDescription =
    "Query files (FILE.csv): reads queries in the public CCD benchmark's format (8 rows per\n"
    "query, 7 integer columns: numerator and denominator of x, y, z, then the expected 0/1\n"
    "result; rows v, f0, f1, f2 or ea0, ea1, eb0, eb1 at t = 0, then the same at t = 1), runs\n"
    "each one with the conservative inclusion kernel (or, with --exact, the exact rational\n"
    "reference) and prints false negatives, false positives and the time per query (median,\n"
    "p99.9, max), and why the kernel reported each contact: proved (in floating point),\n"
    "exact (a tolerance stop decided by the exact reference), tolerance (a tolerance stop kept\n"
    "as a contact: --keep-tolerance-stops) or budget. -o writes JSON with `results` (0/1 per\n"
    "query, in file order), `seconds` (per query) and the split.\n"
    "\n"
    "Mesh frames (FRAME0 FRAME1: PLY or OBJ files of one triangle mesh, same faces; every vertex\n"
    "moves linearly from FRAME0 at t = 0 to FRAME1 at t = 1): finds the vertex-face and edge-edge\n"
    "pairs that come within the separation, and the earliest time of impact (docs/mesh-ccd.md).\n"
    "Prints a summary; -o writes ccdlab-mesh-ccd/1 JSON (docs/formats.md).\n"
    "\n"
    "usage: ccdlab ccd FILE.csv --kind vf|ee [-o OUT.json] [--separation D] [--tolerance T]\n"
    "                  [--max-boxes N] [--keep-tolerance-stops] [--exact] [--force]\n"
    "       ccdlab ccd --write-hard|--write-near-miss --kind vf|ee -o FILE.csv\n"
    "       ccdlab ccd FRAME0 FRAME1 [-o OUT.json] [--separation D] [--cull NAME] [--threads N]\n"
    "                  [--exact] [--quiet]\n";

// The options of both modes; those of one mode are refused in the other.
struct CcdArguments {
  std::vector<std::string> files;
  std::string out_path, kind_text;
  bool exact = false, write_hard = false, write_near_miss = false, force = false, quiet = false;
  ccd::cloth::TriangleCcdOptions query;
  MeshCcdArgs mesh;
  std::vector<CLI::Option*> query_only, mesh_only;
};

void declare_ccd_options(CommandLine& cli, CcdArguments& a) {
  cli.positionals("FILES", a.files, "a query file FILE.csv, or two mesh frames FRAME0 FRAME1 (.ply, .obj)", false);
  cli.text("-o,--output", a.out_path, "OUT.json", "the results as JSON (written atomically; '-' = stdout)",
           "-o needs a file name");
  cli.number("--separation", 0.0, false, "D", "minimum separation (default 0): contact means distance <= D",
             [&a](double d) { a.query.separation = a.mesh.options.separation = d; });
  cli.flag("--exact", a.exact,
           "query files: run the exact rational reference instead of the kernel;\n"
           "mesh frames: decide every kernel hit exactly and list the kernel's false positives");
  a.query_only = {
      cli.text("--kind", a.kind_text, "vf|ee", "query files: vertex-face or edge-edge queries", "--kind needs vf or ee"),
      cli.number("--tolerance", 0.0, false, "T",
                 "query files: image width counted as contact, relative to the query's extent (1e-9)",
                 [&a](double t) { a.query.tolerance = t; }),
      cli.integer("--max-boxes", 1, std::uint64_t{1} << 30, "N",
                  "query files: budget of parameter boxes per query (20000); spent = contact",
                  [&a](std::uint64_t n) { a.query.max_boxes = static_cast<std::uint32_t>(n); }),
      cli.flag("--write-hard", a.write_hard,
               "write ccdlab's hand-built hard queries to -o FILE.csv (expected result decided\n"
               "exactly); takes no query file"),
      cli.flag("--write-near-miss", a.write_near_miss,
               "write ccdlab's near-miss queries (misses and touches by 2^-27 to 2^-40) to\n"
               "-o FILE.csv (expected result decided exactly); takes no query file"),
      cli.flag("--keep-tolerance-stops", a.query.keep_tolerance_stops,
               "query files: report the kernel's tolerance stops as contacts, undecided\n"
               "(without the hull, root and exact decisions: for measurement)"),
      cli.flag("--force", a.force,
               "query files: read one larger than 1e9 bytes (refused before the work\n"
               "otherwise); FILE.csv must be a regular file (not a folder or a device)")};
  a.mesh_only = {
      cli.text("--cull", a.mesh.options.culler, "NAME",
               "mesh frames: broad phase: mesh_sweep (default), brute, bvh, bvh_cones, sensors,\n"
               "boxes:<broad phase>[:options] (ccdlab methods lists the broad phases)",
               "--cull needs a culler name"),
      cli.integer("--threads", 0, 1024, "N", "mesh frames: threads (default 0: one per core); results do not depend on it",
                  [&a](std::uint64_t n) { a.mesh.options.threads = static_cast<unsigned>(n); }),
      cli.flag("-q,--quiet", a.quiet, "mesh frames: no progress on standard error")};
}

// The mesh mode's arguments, checked.
MeshCcdArgs mesh_arguments(const CommandLine& cli, CcdArguments& a) {
  for (const CLI::Option* o : a.query_only)
    if (o->count() > 0)
      cli.fail(option_name(o->get_name()) + " is for query files (ccdlab ccd FILE.csv), not for mesh frames");
  if (a.files.size() != 2) cli.fail("mesh CCD needs two frame files, FRAME0 and FRAME1");
  if (ccd::cloth::find_culler(a.mesh.options.culler) == nullptr) {
    std::string names;
    for (const auto& c : ccd::cloth::cullers()) names += (names.empty() ? "" : ", ") + c.name;
    cli.fail("unknown culler '" + a.mesh.options.culler + "' (" + names + ", boxes:<broad phase>[:options])");
  }
  MeshCcdArgs p = a.mesh;
  p.frame0 = a.files[0];
  p.frame1 = a.files[1];
  p.out_path = a.out_path;
  p.options.exact = a.exact;
  p.quiet = a.quiet;
  return p;
}

int run_ccd(std::span<const std::string> args) {
  CommandLine cli("ccd", kCcdDescription, "ccd");
  cli.footer("Exit status: 0 success, 1 runtime failure, 2 bad input or usage (nothing written).");
  CcdArguments a;
  declare_ccd_options(cli, a);
  bool mesh = false;
  try {
    if (!cli.parse(args)) return 0;
    mesh = std::any_of(a.files.begin(), a.files.end(), [](const std::string& f) { return is_mesh_file(f); });
    if (!mesh) {
      for (const CLI::Option* o : a.mesh_only)
        if (o->count() > 0)
          cli.fail(option_name(o->get_name()) + " is for mesh frames (ccdlab ccd FRAME0 FRAME1), not for query files");
      if (a.kind_text != "vf" && a.kind_text != "ee") cli.fail("--kind vf or --kind ee is required");
      if (a.files.size() > 1) cli.fail("one query file only");
    }
  } catch (...) {
    return command_failed("ccd");
  }
  if (mesh) {  // two mesh frames (mesh_ccd.cpp)
    MeshCcdArgs p;
    try {
      p = mesh_arguments(cli, a);
    } catch (...) {
      return command_failed("ccd");
    }
    return run_mesh_ccd(std::move(p));
  }
  const std::string input = a.files.empty() ? std::string() : a.files[0];
  const std::string& out_path = a.out_path;
  const bool exact = a.exact, write_hard = a.write_hard, write_near_miss = a.write_near_miss, force = a.force;
  const ccd::cloth::TriangleCcdOptions& options = a.query;
  const PrimitivePair kind = a.kind_text == "vf" ? PrimitivePair::VertexFace : PrimitivePair::EdgeEdge;
  try {
    if (write_hard || write_near_miss) {
      const std::string flag = write_hard ? "--write-hard" : "--write-near-miss";
      if (write_hard && write_near_miss) cli.fail("--write-hard and --write-near-miss write one file each: give one");
      if (!input.empty() || out_path.empty()) cli.fail(flag + " takes no query file and needs -o FILE.csv");
      ccd::OutputFile output(out_path);
      std::vector<ccd::cloth::LinearQuery> queries;
      std::vector<bool> expected;
      for (const auto& c : write_hard ? ccd::cloth::hard_queries(kind) : ccd::cloth::near_miss_queries(kind)) {
        queries.push_back(c.query);
        expected.push_back(ccd::cloth::exact_contact(kind, ccd::cloth::to_rational(c.query), 0));  // decided exactly
      }
      output.commit(ccd::cloth::format_query_file(queries, expected));
      std::cout << "queries: " << queries.size() << " written to " << out_path << "\n";
      return 0;
    }
    if (input.empty()) cli.fail("need a query file");
    std::optional<ccd::OutputFile> output;
    if (!out_path.empty()) output.emplace(out_path, std::vector<std::string>{input});
    check_input_file(input, kMaxQueryFileBytes, force);  // a regular file, not /dev/zero or a folder
    const ccd::cloth::QueryFile file = ccd::cloth::read_query_file(input);
    const mpq_class sep(options.separation);  // exact
    const mpq_class sep2 = sep * sep;
    const std::size_t n = file.queries.size();
    std::vector<int> results(n);
    std::vector<double> seconds(n);
    std::size_t false_negatives = 0, false_positives = 0, positives = 0, degenerate = 0, decided_exactly = 0;
    // By HitReason (Budget is its last value).
    std::array<std::size_t, static_cast<std::size_t>(ccd::cloth::HitReason::Budget) + 1> reasons{};
    for (std::size_t i = 0; i < n; ++i) {
      bool hit = false;
      const auto start = std::chrono::steady_clock::now();
      if (exact) {
        hit = ccd::cloth::exact_contact(kind, file.exact[i], sep2);
      } else {
        const auto r = ccd::cloth::triangle_ccd(kind, file.queries[i], options);
        hit = r.status != ccd::QueryStatus::Miss;  // Degenerate counts as a possible contact
        ++reasons.at(static_cast<std::size_t>(r.reason));
        decided_exactly += r.decided_exactly;
        degenerate += r.status == ccd::QueryStatus::Degenerate;
      }
      seconds[i] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      results[i] = hit;
      positives += file.expected[i];
      false_negatives += file.expected[i] && !hit;
      false_positives += !file.expected[i] && hit;
    }
    std::vector<double> sorted = seconds;
    std::sort(sorted.begin(), sorted.end());
    const double median = quantile(sorted, 0.5), p999 = quantile(sorted, 0.999), worst = sorted.empty() ? 0 : sorted.back();
    std::cout << "queries: " << n << " (" << (kind == PrimitivePair::VertexFace ? "vertex-face" : "edge-edge")
              << "), expected contacts: " << positives << "\n"
              << "method: " << (exact ? "exact (rational)" : "inclusion (conservative)") << ", separation "
              << options.separation << "\n"
              << "false negatives: " << false_negatives << "\n"
              << "false positives: " << false_positives << " of " << n - positives << " without contact\n"
              << "time per query: median " << micros(median) << ", p99.9 " << micros(p999) << ", max " << micros(worst)
              << "\n";
    using ccd::cloth::HitReason;
    const auto count = [&](HitReason r) { return reasons.at(static_cast<std::size_t>(r)); };
    if (!exact)
      std::cout << "contacts reported: " << count(HitReason::Proved) << " proved, " << count(HitReason::Exact)
                << " decided exactly, " << count(HitReason::Tolerance) << " tolerance stops, "
                << count(HitReason::Budget) << " budget spent; exact reference called on " << decided_exactly
                << " queries\n";
    if (degenerate) std::cout << "degenerate input (reported as contact): " << degenerate << "\n";
    if (file.inexact_coordinates)
      std::cout << "note: " << file.inexact_coordinates
                << " coordinates are not doubles; the inclusion kernel ran on the nearest doubles\n";
    if (output) {
      nlohmann::json j;
      j["format"] = "ccdlab-ccd/1";
      j["file"] = ccd::escape_invalid_utf8(input);
      j["kind"] = std::string(to_string(kind));
      j["method"] = exact ? "exact" : "inclusion";
      j["options"] = {{"separation", options.separation},
                      {"tolerance", options.tolerance},
                      {"max_boxes", options.max_boxes},
                      {"keep_tolerance_stops", options.keep_tolerance_stops}};
      j["queries"] = n;
      j["false_negatives"] = false_negatives;
      j["false_positives"] = false_positives;
      if (!exact) {
        j["hits"] = {{"proved", count(HitReason::Proved)},
                     {"exact", count(HitReason::Exact)},
                     {"tolerance", count(HitReason::Tolerance)},
                     {"budget", count(HitReason::Budget)},
                     {"degenerate", degenerate}};
        j["decided_exactly"] = decided_exactly;
      }
      j["seconds_median"] = median;
      j["seconds_p999"] = p999;
      j["seconds_max"] = worst;
      j["results"] = results;
      j["seconds"] = seconds;
      output->commit(j.dump(1) + "\n");
      if (out_path != "-") std::cout << "results: " << out_path << "\n";
    }
  } catch (...) {
    return command_failed("ccd", "running the queries of " + input);
  }
  return 0;
}

}  // namespace

extern const Command kCcdCommand = {
    "ccd", "run vertex-face or edge-edge CCD queries from a benchmark query file", run_ccd};

}  // namespace ccdlab
