#include "run_cloth_experiment.hpp"

#include "environment.hpp"

#include <cloth/ccd/triangle_ccd.hpp>
#include <cloth/sim/cloth_simulator.hpp>
#include <cloth/truth/mesh_truth_file.hpp>
#include <ccd/io/utf8_text.hpp>
#include <ccd/io/atomic_file.hpp>
#include <ccd/io/json_reader.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <ccd/util/parallel_for.hpp>

namespace ccdlab {

using nlohmann::json;
using ccd::cloth::Candidate;

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The separation over a check interval start -> end with linear motion assumed between its
// two states: d + 2 D, D the largest distance of an intermediate state's vertex from the
// chord. The margins (relative 2^-30 on D, 2^-40 times the largest coordinate magnitude,
// relative 2^-40 on d) exceed every rounding error of the few operations here by orders.
double chord_separation(const ClothMotion& m, std::size_t start, std::size_t end) {
  const double d = m.truth.thickness;
  if (end - start <= 1) return d;
  const auto& x0 = m.frames[start];
  const auto& x1 = m.frames[end];
  double D = 0.0, M = 0.0;
  for (std::size_t s = start; s <= end; ++s)
    for (const ccd::Vec3& p : m.frames[s]) M = std::max(M, p.cwiseAbs().maxCoeff());
  for (std::size_t s = start + 1; s < end; ++s) {
    const double tau = static_cast<double>(s - start) / static_cast<double>(end - start);
    for (std::size_t v = 0; v < x0.size(); ++v)
      D = std::max(D, (m.frames[s][v] - (x0[v] + tau * (x1[v] - x0[v]))).norm());
  }
  return d * (1.0 + 0x1p-40) + 2.0 * (D * (1.0 + 0x1p-30) + 0x1p-40 * M);
}

bool contains(const std::vector<Candidate>& sorted, const Candidate& c) {
  return std::binary_search(sorted.begin(), sorted.end(), c);
}

std::uint64_t count_not_in(const std::vector<Candidate>& confirmed, const std::vector<Candidate>& truth) {
  std::uint64_t n = 0;
  for (const Candidate& c : confirmed) n += !contains(truth, c);
  return n;
}

template <class T>
T median(std::vector<T> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

ClothMotion prepare_cloth_motion(const ccd::cloth::ClothScene& scene, unsigned threads, const std::string& truth_cache,
                                 const std::atomic<bool>* cancel) {
  ClothMotion m;
  m.scene = scene;
  m.frames = ccd::cloth::simulate_cloth(scene);
  m.mesh = ccd::cloth::make_grid_mesh(scene);
  m.digest = ccd::cloth::motion_digest(m.mesh, m.frames, scene.thickness);
  const auto t0 = Clock::now();
  if (!truth_cache.empty()) {
    m.truth_file = (std::filesystem::path(truth_cache) / (m.digest + ".json")).string();
    std::error_code ec;
    if (std::filesystem::exists(m.truth_file, ec)) {
      m.truth = ccd::cloth::mesh_truth_from_json(ccd::read_json_file(m.truth_file), m.truth_file, m.mesh,
                                                 scene.particle_count(), m.digest);
      if (m.truth.thickness != scene.thickness || m.truth.step_contacts.size() + 1 != m.frames.size())
        throw ccd::InputError(m.truth_file, "thickness", "is not the truth of this motion");
      m.truth_reused = true;
    }
  }
  if (!m.truth_reused) {
    m.truth = ccd::cloth::compute_mesh_truth(m.mesh, m.frames, scene.thickness, threads, cancel);
    if (cancel && cancel->load()) return m;
    if (!m.truth_file.empty()) {
      std::filesystem::create_directories(truth_cache);
      ccd::write_file_atomically(m.truth_file, ccd::cloth::mesh_truth_to_json(m.truth, m.digest).dump() + "\n");
    }
  }
  m.truth_seconds = since(t0);
  m.events = ccd::cloth::contact_events(m.truth);
  return m;
}

ClothRecord run_cloth_method(const ClothMotion& m, const ccd::cloth::CullerEntry& culler, bool continuous, int k,
                             int repeats, const std::atomic<bool>* cancel) {
  ClothRecord r;
  r.culler = std::string(culler.name);
  r.continuous = continuous;
  r.method = r.culler + (continuous ? "/continuous" : "/discrete");
  r.conservative = continuous && !culler.may_drop;
  r.k = k;
  r.dt = k * m.scene.step;
  r.hz = 1.0 / r.dt;
  r.events = m.events.size();
  const std::size_t S = m.frames.size() - 1;
  const std::size_t K = static_cast<std::size_t>(k);
  // Check c: the state c K (discrete) or the interval [c K, min(c K + K, S)] (continuous).
  const std::size_t checks = continuous ? (S + K - 1) / K : S / K + 1;
  r.checks = checks;
  const double d = m.truth.thickness;
  ccd::cloth::TriangleCcdOptions kernel;
  kernel.keep_tolerance_stops = true;  // as mesh CCD (cloth/mesh_ccd/mesh_ccd.cpp): resting contacts stay cheap
  std::vector<double> cull_s, narrow_s, total_s;
  std::vector<std::vector<Candidate>> confirmed(checks);
  for (int rep = 0; rep < repeats; ++rep) {
    const auto t_total = Clock::now();
    // One instance per pass over the run: cullers that keep state (the bvh refits its tree)
    // carry it from one check to the next, as in a simulation.
    const std::unique_ptr<ccd::cloth::Culler> instance = culler.make();
    double cull = 0.0, narrow = 0.0;
    std::uint64_t candidates = 0, hits = 0;
    double max_sep = 0.0;
    for (std::size_t c = 0; c < checks; ++c) {
      if (cancel && cancel->load(std::memory_order_relaxed)) {
        r.cancelled = true;
        return r;
      }
      const std::size_t start = c * K, end = continuous ? std::min(start + K, S) : start;
      const double sep = continuous ? chord_separation(m, start, end) : d;
      max_sep = std::max(max_sep, sep);
      const auto& x0 = m.frames[start];
      const auto& x1 = m.frames[end];
      auto t0 = Clock::now();
      const std::vector<Candidate> found = instance->cull(m.mesh, x0, x1, sep);
      cull += since(t0);
      t0 = Clock::now();
      kernel.separation = sep;
      std::vector<Candidate> hit;
      for (const Candidate& cand : found)
        if (ccd::cloth::triangle_ccd(cand.kind, ccd::cloth::candidate_query(m.mesh, cand, x0, x1), kernel).status !=
            ccd::QueryStatus::Miss)
          hit.push_back(cand);
      narrow += since(t0);
      candidates += found.size();
      hits += hit.size();
      std::sort(hit.begin(), hit.end());
      if (rep == 0) confirmed[c] = std::move(hit);
      else if (confirmed[c] != hit) r.counts_stable = false;
    }
    total_s.push_back(since(t_total));
    cull_s.push_back(cull);
    narrow_s.push_back(narrow);
    if (rep == 0) {
      r.candidates = candidates;
      r.narrow_calls = candidates;
      r.confirmed = hits;
      r.max_separation = max_sep;
    }
  }
  r.cull_seconds = median(cull_s);
  r.narrow_seconds = median(narrow_s);
  r.total_seconds = median(total_s);
  r.seconds_per_simulated_second = r.total_seconds / (static_cast<double>(S) * m.scene.step);

  // Matching against the truth.
  for (const ccd::cloth::MeshContactEvent& e : m.events) {
    bool found = false;
    if (continuous) {
      found = contains(confirmed[e.first_step / K], e.pair);
    } else {
      for (std::size_t c = (e.first_step + K - 1) / K; !found && c < checks && c * K <= e.last_step + 1u; ++c)
        found = contains(confirmed[c], e.pair) && contains(m.truth.state_contacts[c * K], e.pair);
    }
    (found ? r.detected : r.missed) += 1;
  }
  for (std::size_t c = 0; c < checks; ++c) {
    if (continuous) {
      std::vector<Candidate> truth;
      for (std::size_t s = c * K; s < std::min(c * K + K, S); ++s)
        truth.insert(truth.end(), m.truth.step_contacts[s].begin(), m.truth.step_contacts[s].end());
      std::sort(truth.begin(), truth.end());
      r.false_positives += count_not_in(confirmed[c], truth);
    } else {
      r.false_positives += count_not_in(confirmed[c], m.truth.state_contacts[c * K]);
    }
  }
  return r;
}

json to_json(const ClothRecord& r) {
  return {{"method", r.method},
          {"culler", r.culler},
          {"mode", r.continuous ? "continuous" : "discrete"},
          {"continuous", r.continuous},
          {"conservative", r.conservative},
          {"k", r.k},
          {"dt", r.dt},
          {"hz", r.hz},
          {"checks", r.checks},
          {"events", r.events},
          {"detected", r.detected},
          {"missed", r.missed},
          {"missed_fraction", r.events ? static_cast<double>(r.missed) / static_cast<double>(r.events) : 0.0},
          {"candidates", r.candidates},
          {"narrow_calls", r.narrow_calls},
          {"confirmed", r.confirmed},
          {"false_positives", r.false_positives},
          {"max_separation", r.max_separation},
          {"cull_seconds", r.cull_seconds},
          {"narrow_seconds", r.narrow_seconds},
          {"total_seconds", r.total_seconds},
          {"seconds_per_simulated_second", r.seconds_per_simulated_second},
          {"counts_stable", r.counts_stable}};
}

json run_cloth_experiment(const ClothExperiment& e, const ccd::cloth::ClothScene& scene, const ClothRunOptions& options) {
  const auto t0 = Clock::now();
  const unsigned threads = static_cast<unsigned>(std::max(1, options.threads));
  const ClothMotion m = prepare_cloth_motion(scene, threads, options.truth_cache, options.cancel);
  if (options.cancel && options.cancel->load()) return nullptr;
  if (!options.quiet)
    std::cerr << "ccdlab: cloth truth: " << m.events.size() << " contact events over " << scene.steps << " steps ("
              << (m.truth_reused ? "read from " + m.truth_file : "computed") << ", " << m.truth_seconds << " s)\n";
  struct Job {
    const ccd::cloth::CullerEntry* culler;
    bool continuous;
    int k;
  };
  std::vector<Job> jobs;
  for (const std::string& c : e.cullers)
    for (const std::string& mode : e.modes)
      for (int k : e.k) jobs.push_back({ccd::cloth::find_culler(c), mode == "continuous", k});
  std::vector<ClothRecord> records(jobs.size());
  ccd::parallel_for(jobs.size(), threads, [&](std::size_t j, unsigned) {
    records[j] = run_cloth_method(m, *jobs[j].culler, jobs[j].continuous, jobs[j].k, e.repeats, options.cancel);
  });
  if (options.cancel && options.cancel->load()) return nullptr;
  json out;
  out["format"] = "ccdlab-cloth-results/1";
  out["experiment"] = cloth_experiment_to_json(e);
  out["scene"] = {{"source", e.scene_path.empty() ? e.scene : ccd::escape_invalid_utf8(e.scene_path)},
                  {"particles", scene.particle_count()},
                  {"triangles", m.mesh.triangles.size()},
                  {"edges", m.mesh.edges.size()},
                  {"steps", scene.steps},
                  {"step", scene.step},
                  {"horizon", scene.steps * scene.step},
                  {"thickness", scene.thickness}};
  std::uint64_t step_contacts = 0;
  for (const auto& l : m.truth.step_contacts) step_contacts += l.size();
  out["truth"] = {{"format", ccd::cloth::kMeshTruthFormat},
                  {"digest", m.digest},
                  {"events", m.events.size()},
                  {"step_contacts", step_contacts},
                  {"seconds", m.truth_seconds},
                  {"pairs", m.truth.counts.pairs},
                  {"certified_within", m.truth.counts.within},
                  {"certified_apart", m.truth.counts.apart},
                  {"exact_pairs", m.truth.counts.exact},
                  {"file", m.truth_file.empty() ? json(nullptr) : json(ccd::escape_invalid_utf8(m.truth_file))},
                  {"reused", m.truth_reused}};
  out["environment"] = environment_json(options.threads);
  out["records"] = json::array();
  for (const ClothRecord& r : records) out["records"].push_back(to_json(r));
  out["seconds"] = since(t0);
  out["peak_memory_bytes"] = peak_memory_bytes();
  return out;
}

}  // namespace ccdlab
