#include "mesh_ccd.hpp"
#include <ccd/geometry/numeric_limits.hpp>

#include <cloth/ccd/triangle_ccd.hpp>
#include <cloth/cull/cullers.hpp>
#include <cloth/exact/exact_ccd.hpp>
#include <cloth/mesh_ccd/mesh_sweep.hpp>
#include <cloth/mesh_ccd/mesh_topology.hpp>
#include <ccd/util/parallel_for.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace ccd::cloth {

namespace {

using Clock = std::chrono::steady_clock;
/// Candidates per block handed to the narrow phase (one fixed buffer per thread).
constexpr std::size_t kBlock = 4096;

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// What one thread found; merged in a fixed way after the threads are done.
struct WorkerState {
  std::vector<Candidate> buffer = std::vector<Candidate>(kBlock);
  std::vector<Candidate> hits, refuted, kept;
  std::uint64_t candidates_vf = 0, candidates_ee = 0, budget_spent = 0;
  double toi = kInf, toi_upper = kInf;
  double busy = 0.0, narrow = 0.0;  // seconds spent in the stage, and in the narrow phase
};

class NarrowPhase {
 public:
  NarrowPhase(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1, const MeshCcdOptions& o)
      : mesh_(mesh), x0_(x0), x1_(x1), exact_(o.exact), keep_(o.keep_candidates) {
    options_.separation = o.separation;
    // Mesh frames are full of resting and sliding contacts (touches on a boundary, coplanar
    // pairs) that only the exact reference decides: deciding every tolerance stop took the
    // narrow phase of a 20,000-face crumpled pair from 3.8 s to 21 s. A tolerance stop is
    // reported as a contact (conservative); `exact` decides every hit instead.
    options_.keep_tolerance_stops = true;
    const mpq_class d(o.separation);  // exact
    separation_squared_ = d * d;
  }

  void run(std::span<const Candidate> block, WorkerState& w) const {
    const auto start = Clock::now();
    if (keep_) w.kept.insert(w.kept.end(), block.begin(), block.end());
    for (const Candidate& c : block) {
      (c.kind == PrimitivePair::VertexFace ? w.candidates_vf : w.candidates_ee) += 1;
      const LinearQuery q = candidate_query(mesh_, c, x0_, x1_);
      const TriangleCcdResult r = triangle_ccd(c.kind, q, options_);
      if (r.status == QueryStatus::Miss) continue;  // proved: no contact
      w.budget_spent += r.budget_spent;
      if (exact_ && !exact_contact(c.kind, to_rational(q), separation_squared_)) {
        w.refuted.push_back(c);
        continue;
      }
      w.hits.push_back(c);
      w.toi = std::min(w.toi, r.toi);
      w.toi_upper = std::min(w.toi_upper, r.toi_upper);
    }
    w.narrow += since(start);
  }

 private:
  const ClothMesh& mesh_;
  std::span<const Vec3> x0_, x1_;
  bool exact_, keep_;
  TriangleCcdOptions options_;
  mpq_class separation_squared_;
};

void check_input(std::span<const Vec3> x0, std::span<const Vec3> x1, const MeshCcdOptions& o) {
  if (x0.size() != x1.size())
    throw std::invalid_argument("the frames have different vertex counts (" + std::to_string(x0.size()) + " and " +
                                std::to_string(x1.size()) + ")");
  for (int frame = 0; frame < 2; ++frame) {
    const auto x = frame == 0 ? x0 : x1;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (!x[i].allFinite())
        throw std::invalid_argument("frame " + std::to_string(frame) + ": vertex " + std::to_string(i) +
                                    ": coordinate not finite");
  }
  if (!std::isfinite(o.separation) || !(o.separation >= 0))
    throw std::invalid_argument("separation must be a finite number >= 0");
}

void sort_unique(std::vector<Candidate>& v) { std::sort(v.begin(), v.end()); }

void to_vertex_pairs(const ClothMesh& mesh, const std::vector<Candidate>& found,
                     std::vector<std::array<std::uint32_t, 2>>& vf, std::vector<std::array<std::uint32_t, 4>>& ee) {
  for (const Candidate& c : found) {  // sorted: (kind, a, b), so both lists come out sorted
    if (c.kind == PrimitivePair::VertexFace) {
      vf.push_back({c.a, c.b});
    } else {
      const auto& a = mesh.edges[c.a];
      const auto& b = mesh.edges[c.b];
      ee.push_back({a[0], a[1], b[0], b[1]});
    }
  }
}

// Runs the broad and narrow phases; the workers' states hold what they found.
void run_stages(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1, const MeshCcdOptions& o,
                unsigned threads, std::vector<WorkerState>& workers, MeshCcdTimes& seconds) {
  const NarrowPhase narrow(mesh, x0, x1, o);
  std::atomic<std::size_t> done{0};
  auto report = [&](std::size_t total, unsigned worker) {
    const std::size_t d = done.fetch_add(1) + 1;
    if (o.progress && worker == 0) o.progress(d, total);  // worker 0 is the calling thread
  };
  if (o.culler == "mesh_sweep") {
    auto start = Clock::now();
    MeshSweep sweep;
    sweep.prepare(mesh, x0, x1, {o.separation, true, threads});
    seconds.boxes += since(start);
    start = Clock::now();
    const std::size_t chunks = sweep.chunks();
    parallel_for(chunks, threads, [&](std::size_t k, unsigned w) {
      WorkerState& state = workers[w];
      const auto busy = Clock::now();
      sweep.sweep(k, state.buffer, [&](std::span<const Candidate> block) { narrow.run(block, state); });
      state.busy += since(busy);
      report(chunks, w);
    });
    // Streamed: the stage's wall time split in proportion to the threads' time in each.
    const double wall = since(start);
    double busy = 0, in_narrow = 0;
    for (const WorkerState& w : workers) {
      busy += w.busy;
      in_narrow += w.narrow;
    }
    seconds.narrow = busy > 0 ? wall * std::min(1.0, in_narrow / busy) : 0.0;
    seconds.broad = wall - seconds.narrow;
    return;
  }
  const CullerEntry* entry = find_culler(o.culler);
  if (entry == nullptr) throw std::invalid_argument("unknown culler '" + o.culler + "'");
  auto start = Clock::now();
  const std::vector<Candidate> all = entry->cull(mesh, x0, x1, o.separation);
  seconds.broad = since(start);
  start = Clock::now();
  const std::size_t blocks = (all.size() + kBlock - 1) / kBlock;
  parallel_for(blocks, threads, [&](std::size_t k, unsigned w) {
    const std::span<const Candidate> block(all.data() + k * kBlock, std::min(kBlock, all.size() - k * kBlock));
    narrow.run(block, workers[w]);
    report(blocks, w);
  });
  seconds.narrow = since(start);
}

}  // namespace

MeshCcdResult mesh_ccd(std::span<const Vec3> x0, std::span<const Vec3> x1,
                       std::span<const std::array<std::uint32_t, 3>> faces, const MeshCcdOptions& options) {
  check_input(x0, x1, options);
  if (options.culler != "mesh_sweep" && find_culler(options.culler) == nullptr)
    throw std::invalid_argument("unknown culler '" + options.culler + "'");
  const unsigned threads = resolve_threads(options.threads);
  MeshCcdResult result;
  const auto start = Clock::now();
  const ClothMesh mesh = mesh_topology(faces, x0.size());
  result.seconds.boxes = since(start);
  result.vertices = x0.size();
  result.edges = mesh.edges.size();
  result.faces = mesh.triangles.size();

  std::vector<WorkerState> workers(threads);
  run_stages(mesh, x0, x1, options, threads, workers, result.seconds);

  std::vector<Candidate> hits, refuted;
  double toi = kInf, toi_upper = kInf;
  for (WorkerState& w : workers) {
    hits.insert(hits.end(), w.hits.begin(), w.hits.end());
    refuted.insert(refuted.end(), w.refuted.begin(), w.refuted.end());
    result.candidates.insert(result.candidates.end(), w.kept.begin(), w.kept.end());
    result.candidates_vf += w.candidates_vf;
    result.candidates_ee += w.candidates_ee;
    result.budget_spent += w.budget_spent;
    toi = std::min(toi, w.toi);
    toi_upper = std::min(toi_upper, w.toi_upper);
  }
  sort_unique(hits);
  sort_unique(refuted);
  sort_unique(result.candidates);
  to_vertex_pairs(mesh, hits, result.vf, result.ee);
  to_vertex_pairs(mesh, refuted, result.false_vf, result.false_ee);
  if (!hits.empty()) {
    // Rounded up: time + error >= the certified time.
    const double error = toi_upper == kInf ? kInf : std::nextafter(toi_upper - toi, kInf);
    result.toi = MeshToi{toi, error};
  }
  result.edge_list = mesh.edges;
  return result;
}

}  // namespace ccd::cloth
