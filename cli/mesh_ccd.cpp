// `ccdlab ccd FRAME0 FRAME1 [-o OUT.json] [--separation D] [--cull NAME] [--threads N]
// [--exact] [--quiet]`: which vertex-face and edge-edge pairs of a triangle mesh collide
// while it moves linearly from frame 0 to frame 1 (cloth/mesh_ccd/mesh_ccd.hpp), written
// as `ccdlab-mesh-ccd/1` (docs/formats.md, docs/mesh-ccd.md).
#include "command.hpp"
#include "mesh_ccd_command.hpp"

#include "../experiments/environment.hpp"
#include "../experiments/progress.hpp"

#include <cloth/cull/cullers.hpp>
#include <cloth/io/mesh_file.hpp>
#include <cloth/mesh_ccd/mesh_ccd.hpp>
#include <cloth/mesh_ccd/mesh_ccd_json.hpp>
#include <ccd/io/atomic_file.hpp>
#include <ccd/io/input_error.hpp>
#include <ccd/util/integer_text.hpp>
#include <ccd/util/parallel_for.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>

namespace ccdlab {
namespace {

bool ends_with_nocase(const std::string& s, std::string_view suffix) {
  if (s.size() < suffix.size()) return false;
  for (std::size_t i = 0; i < suffix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) != suffix[i]) return false;
  return true;
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g s", s);
  return buf;
}

void print_summary(std::ostream& out, const ccd::cloth::MeshCcdResult& r, const ccd::cloth::MeshCcdOptions& o,
                   double read_seconds) {
  out << "mesh: " << r.vertices << " vertices, " << r.edges << " edges, " << r.faces << " faces\n"
            << "culler: " << o.culler << ", separation " << o.separation << "\n"
            << "candidates: " << r.candidates_vf << " vertex-face, " << r.candidates_ee << " edge-edge\n"
            << "collisions" << (o.exact ? " (decided exactly)" : " (conservative kernel)") << ": " << r.vf.size()
            << " vertex-face, " << r.ee.size() << " edge-edge\n";
  if (o.exact)
    out << "kernel false positives: " << r.false_vf.size() << " vertex-face, " << r.false_ee.size()
              << " edge-edge\n";
  if (r.toi) {
    out << "earliest time of impact: " << r.toi->time;
    if (std::isfinite(r.toi->error)) out << " (certified within " << r.toi->error << ")";
    out << "\n";
  } else {
    out << "earliest time of impact: none\n";
  }
  if (r.budget_spent) out << "budget spent (reported as contact): " << r.budget_spent << "\n";
  out << "seconds: read " << seconds_text(read_seconds) << ", boxes " << seconds_text(r.seconds.boxes)
            << ", broad " << seconds_text(r.seconds.broad) << ", narrow " << seconds_text(r.seconds.narrow) << "\n";
}

}  // namespace

bool is_mesh_file(const std::string& path) {
  if (ends_with_nocase(path, ".ply") || ends_with_nocase(path, ".obj")) return true;
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  return in.read(magic, 4) && magic[0] == 'p' && magic[1] == 'l' && magic[2] == 'y' &&
         (magic[3] == '\n' || magic[3] == '\r');
}

int run_mesh_ccd(MeshCcdArgs p) {
  try {
    std::optional<ccd::OutputFile> output;
    const std::string inputs[] = {p.frame0, p.frame1};
    if (!p.out_path.empty()) output.emplace(p.out_path, inputs);
    const auto start = std::chrono::steady_clock::now();
    const ccd::cloth::MeshFrames frames = ccd::cloth::read_mesh_frames(p.frame0, p.frame1);
    const double read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Progress progress(0, p.quiet);  // on stderr: a bar on a terminal, a line every 10 s otherwise
    p.options.progress = [&progress](std::size_t done, std::size_t total) {
      progress.advance("candidate blocks", done, total);
    };
    ccd::cloth::MeshCcdResult result;
    try {
      result = ccd::cloth::mesh_ccd(frames.vertices0, frames.vertices1, frames.faces, p.options);
    } catch (const std::invalid_argument& e) {
      // The frames were read and checked; what is left is the mesh's own shape (a face
      // naming one vertex twice), or a coordinate of frame 1.
      const std::string what = e.what();
      if (what.starts_with("frame 1: ")) throw ccd::InputError(p.frame1, "", what.substr(9));
      if (what.starts_with("frame 0: ")) throw ccd::InputError(p.frame0, "", what.substr(9));
      throw ccd::InputError(p.frame0, "", what);
    }
    progress.finish();
    const unsigned threads = ccd::resolve_threads(p.options.threads);
    // With -o - the JSON goes to standard output: the summary then goes to standard error.
    print_summary(output && output->is_stdout() ? std::cerr : std::cout, result, p.options, read_seconds);
    if (output) {
      nlohmann::json j = ccd::cloth::mesh_ccd_json(result, p.options, threads);
      j["frames"] = {p.frame0, p.frame1};
      j["seconds"]["read"] = read_seconds;
      j["peak_memory_bytes"] = peak_memory_bytes();
      output->commit(j.dump(1) + "\n");
      if (!output->is_stdout()) std::cout << "results: " << p.out_path << "\n";
    }
  } catch (...) {
    return command_failed("ccd", "during mesh CCD");
  }
  return 0;
}

}  // namespace ccdlab
