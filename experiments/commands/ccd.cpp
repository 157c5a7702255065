// `ccdlab ccd FILE.csv --kind vf|ee [-o OUT.json]`: runs triangle CCD queries stored in the
// public CCD benchmark's format and measures misses, false positives and time per query.
#include "command.hpp"
#include "mesh_ccd_command.hpp"

#include "../work_estimate.hpp"

#include <cloth/ccd/hard_queries.hpp>
#include <cloth/ccd/triangle_ccd.hpp>
#include <cloth/exact/exact_ccd.hpp>
#include <cloth/io/query_file.hpp>
#include <ccd/io/utf8_text.hpp>
#include <ccd/io/atomic_file.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/util/integer_text.hpp>

#include <algorithm>
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

std::optional<double> parse_non_negative(const std::string& s) {
  if (s.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !std::isfinite(v) || v < 0) return std::nullopt;
  return v;
}

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

int run_ccd(std::span<const std::string> args) {
  if (is_mesh_ccd_call(args)) return run_mesh_ccd(args);  // two mesh frames (mesh_ccd.cpp)
  auto usage_error = [](const std::string& msg) {
    std::cerr << "ccdlab ccd: " << msg << " (see ccdlab ccd --help)\n";
    return kExitBadInput;
  };
  std::string input, out_path, kind_text;
  bool exact = false, write_hard = false, force = false;
  ccd::cloth::TriangleCcdOptions options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool has_value = i + 1 < args.size();
    if (a == "-o" || a == "--output") {
      if (!has_value) return usage_error("-o needs a file name");
      out_path = args[++i];
    } else if (a == "--kind") {
      if (!has_value) return usage_error("--kind needs vf or ee");
      kind_text = args[++i];
    } else if (a == "--separation") {
      const auto v = has_value ? parse_non_negative(args[++i]) : std::nullopt;
      if (!v) return usage_error("--separation needs a finite number >= 0");
      options.separation = *v;
    } else if (a == "--tolerance") {
      const auto v = has_value ? parse_non_negative(args[++i]) : std::nullopt;
      if (!v) return usage_error("--tolerance needs a finite number >= 0");
      options.tolerance = *v;
    } else if (a == "--max-boxes") {
      const auto v = has_value ? ccd::parse_integer(args[++i], 1, 1u << 30) : std::nullopt;
      if (!v) return usage_error("--max-boxes needs an integer in [1, 2^30]");
      options.max_boxes = static_cast<std::uint32_t>(*v);
    } else if (a == "--exact") {
      exact = true;
    } else if (a == "--write-hard") {
      write_hard = true;
    } else if (a == "--force") {
      force = true;
    } else if (a.size() > 1 && a[0] == '-') {
      return usage_error("unknown option '" + a + "'");
    } else if (input.empty()) {
      input = a;
    } else {
      return usage_error("one query file only");
    }
  }
  if (kind_text != "vf" && kind_text != "ee") return usage_error("--kind vf or --kind ee is required");
  const PrimitivePair kind = kind_text == "vf" ? PrimitivePair::VertexFace : PrimitivePair::EdgeEdge;
  try {
    if (write_hard) {
      if (!input.empty() || out_path.empty()) return usage_error("--write-hard takes no query file and needs -o FILE.csv");
      ccd::OutputFile output(out_path);
      std::vector<ccd::cloth::LinearQuery> queries;
      std::vector<bool> expected;
      for (const auto& c : ccd::cloth::hard_queries(kind)) {
        queries.push_back(c.query);
        expected.push_back(ccd::cloth::exact_contact(kind, ccd::cloth::to_rational(c.query), 0));  // decided exactly
      }
      output.commit(ccd::cloth::format_query_file(queries, expected));
      std::cout << "queries: " << queries.size() << " written to " << out_path << "\n";
      return 0;
    }
    if (input.empty()) return usage_error("need a query file");
    std::optional<ccd::OutputFile> output;
    if (!out_path.empty()) output.emplace(out_path, std::vector<std::string>{input});
    check_input_file(input, kMaxQueryFileBytes, force);  // a regular file, not /dev/zero or a folder
    const ccd::cloth::QueryFile file = ccd::cloth::read_query_file(input);
    const mpq_class sep(options.separation);  // exact
    const mpq_class sep2 = sep * sep;
    const std::size_t n = file.queries.size();
    std::vector<int> results(n);
    std::vector<double> seconds(n);
    std::size_t false_negatives = 0, false_positives = 0, positives = 0, budget_spent = 0, degenerate = 0;
    for (std::size_t i = 0; i < n; ++i) {
      bool hit = false;
      const auto start = std::chrono::steady_clock::now();
      if (exact) {
        hit = ccd::cloth::exact_contact(kind, file.exact[i], sep2);
      } else {
        const auto r = ccd::cloth::triangle_ccd(kind, file.queries[i], options);
        hit = r.status != ccd::QueryStatus::Miss;  // Degenerate counts as a possible contact
        budget_spent += r.budget_spent;
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
    if (budget_spent) std::cout << "budget spent (reported as contact): " << budget_spent << "\n";
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
      j["options"] = {{"separation", options.separation}, {"tolerance", options.tolerance}, {"max_boxes", options.max_boxes}};
      j["queries"] = n;
      j["false_negatives"] = false_negatives;
      j["false_positives"] = false_positives;
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
    "ccd", "run vertex-face or edge-edge CCD queries from a benchmark query file",
    "usage: ccdlab ccd FILE.csv --kind vf|ee [-o OUT.json] [--separation D] [--tolerance T]\n"
    "                  [--max-boxes N] [--exact] [--force]\n"
    "       ccdlab ccd --write-hard --kind vf|ee -o FILE.csv\n"
    "       ccdlab ccd FRAME0 FRAME1 [-o OUT.json] [--separation D] [--cull NAME] [--threads N]\n"
    "                  [--exact] [--quiet]\n"
    "\n"
    "Reads queries in the public CCD benchmark's format (8 rows per query, 7 integer columns:\n"
    "numerator and denominator of x, y, z, then the expected 0/1 result; rows v, f0, f1, f2 or\n"
    "ea0, ea1, eb0, eb1 at t = 0, then the same at t = 1), runs each one with the conservative\n"
    "inclusion kernel (or, with --exact, the exact rational reference) and prints false\n"
    "negatives, false positives and the time per query (median, p99.9, max). -o writes JSON\n"
    "with `results` (0/1 per query, in file order) and `seconds` (per query).\n"
    "--separation D   minimum separation (default 0): contact means distance <= D\n"
    "--tolerance T    image width counted as contact, relative to the query's extent (1e-9)\n"
    "--max-boxes N    budget of parameter boxes per query (20000); spent = contact\n"
    "--write-hard     writes ccdlab's hand-built hard queries (expected result decided exactly)\n"
    "--force          read a query file larger than 1e9 bytes (refused before the work\n"
    "                 otherwise); FILE.csv must be a regular file (not a folder or a device)\n"
    "\n"
    "Mesh frames (FRAME0 FRAME1: PLY or OBJ files of one triangle mesh, same faces; every vertex\n"
    "moves linearly from FRAME0 at t = 0 to FRAME1 at t = 1): finds the vertex-face and edge-edge\n"
    "pairs that come within the separation, and the earliest time of impact (docs/mesh-ccd.md).\n"
    "Prints a summary; -o writes ccdlab-mesh-ccd/1 JSON (docs/formats.md).\n"
    "--separation D   minimum separation (default 0): contact means distance <= D\n"
    "--cull NAME      broad phase: mesh_sweep (default), brute, bvh, bvh_cones, sensors,\n"
    "                 boxes:<broad phase>[:options] (ccdlab methods lists the broad phases)\n"
    "--threads N      threads (default 0: one per core); results do not depend on it\n"
    "--exact          decide every kernel hit with the exact rational reference and list the\n"
    "                 kernel's false positives\n"
    "--quiet          no progress on standard error\n"
    "\n"
    "Exit status: 0 success, 1 runtime failure, 2 bad input or usage (nothing written).\n",
    run_ccd};

}  // namespace ccdlab
