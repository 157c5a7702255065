#include "mesh_truth.hpp"

#include <cloth/ccd/certified_proximity.hpp>
#include <cloth/exact/exact_ccd.hpp>
#include <ccd/util/parallel_for.hpp>

#include <algorithm>
#include <map>

namespace ccd::cloth {

namespace {

// A primitive's box over both states of the motion (exact: min and max of doubles).
struct SweepBox {
  Vec3 lo, hi;
  std::uint32_t index;
  std::uint8_t kind;  // 0 vertex, 1 edge, 2 triangle
};

template <std::size_t N>
SweepBox box_of(const std::array<std::uint32_t, N>& vertices, std::span<const Vec3> x0, std::span<const Vec3> x1,
            std::uint32_t index, std::uint8_t kind) {
  SweepBox it{x0[vertices[0]], x0[vertices[0]], index, kind};
  for (std::uint32_t v : vertices)
    for (const Vec3& p : {x0[v], x1[v]}) {
      it.lo = it.lo.cwiseMin(p);
      it.hi = it.hi.cwiseMax(p);
    }
  return it;
}

// The gap between two closed intervals is at most d, decided in doubles: the gap
// lo_b - hi_a rounds monotonically, so an exact gap <= d (a double) never rounds above d.
bool within(double lo_a, double hi_a, double lo_b, double hi_b, double d) {
  return lo_b - hi_a <= d && lo_a - hi_b <= d;
}

}  // namespace

bool exact_pair_contact(const ClothMesh& mesh, const Candidate& c, std::span<const Vec3> x0, std::span<const Vec3> x1,
                        double thickness, MeshTruthCounts* counts) {
  MeshTruthCounts local;
  MeshTruthCounts& n = counts ? *counts : local;
  ++n.pairs;
  const LinearQuery q = candidate_query(mesh, c, x0, x1);
  switch (certified_proximity(c.kind, q, thickness).decision) {  // Within and Apart are proofs
    case Proximity::Within: ++n.within; return true;
    case Proximity::Apart: ++n.apart; return false;
    case Proximity::Undecided: break;
  }
  ++n.exact;
  const mpq_class d(thickness);
  const mpq_class d2 = d * d;
  // A contact at t = 0 or t = 1 is decided by a still query (constant polynomials: cheap).
  const RationalQuery exact = to_rational(q);
  for (int end : {0, 4}) {
    RationalQuery still = exact;
    for (int i = 0; i < 4; ++i) still.x[static_cast<std::size_t>(i + 4 - end)] = still.x[static_cast<std::size_t>(i + end)];
    if (exact_contact(c.kind, still, d2)) return true;
  }
  return exact_contact(c.kind, exact, d2);
}

std::vector<Candidate> contacts_among(const ClothMesh& mesh, std::span<const Candidate> candidates,
                                      std::span<const Vec3> x0, std::span<const Vec3> x1, double thickness,
                                      MeshTruthCounts* counts) {
  std::vector<Candidate> out;
  for (const Candidate& c : candidates)
    if (exact_pair_contact(mesh, c, x0, x1, thickness, counts)) out.push_back(c);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Candidate> interval_contacts(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1,
                                         double thickness, MeshTruthCounts* counts) {
  std::vector<SweepBox> items;
  items.reserve(x0.size() + mesh.edges.size() + mesh.triangles.size());
  for (std::uint32_t v = 0; v < x0.size(); ++v) items.push_back(box_of(std::array<std::uint32_t, 1>{v}, x0, x1, v, 0));
  for (std::uint32_t e = 0; e < mesh.edges.size(); ++e) items.push_back(box_of(mesh.edges[e], x0, x1, e, 1));
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) items.push_back(box_of(mesh.triangles[t], x0, x1, t, 2));
  std::sort(items.begin(), items.end(), [](const SweepBox& a, const SweepBox& b) { return a.lo.x() < b.lo.x(); });
  std::vector<Candidate> candidates;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const SweepBox& a = items[i];
    // Sorted by lo.x: once lo_b.x - hi_a.x rounds above d it stays above for later b.
    for (std::size_t j = i + 1; j < items.size() && items[j].lo.x() - a.hi.x() <= thickness; ++j) {
      const SweepBox& b = items[j];
      Candidate c;
      if (a.kind == 1 && b.kind == 1)
        c = {PrimitivePair::EdgeEdge, std::min(a.index, b.index), std::max(a.index, b.index)};
      else if (a.kind + b.kind == 2 && a.kind != 1)
        c = {PrimitivePair::VertexFace, a.kind == 0 ? a.index : b.index, a.kind == 0 ? b.index : a.index};
      else
        continue;
      if (!within(a.lo.y(), a.hi.y(), b.lo.y(), b.hi.y(), thickness) ||
          !within(a.lo.z(), a.hi.z(), b.lo.z(), b.hi.z(), thickness) || adjacent(mesh, c))
        continue;
      candidates.push_back(c);
    }
  }
  return contacts_among(mesh, candidates, x0, x1, thickness, counts);
}

MeshTruth compute_mesh_truth(const ClothMesh& mesh, std::span<const std::vector<Vec3>> frames, double thickness,
                             unsigned threads, const std::atomic<bool>* cancel) {
  auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
  MeshTruth truth;
  truth.thickness = thickness;
  const std::size_t steps = frames.size() - 1;
  truth.step_contacts.resize(steps);
  truth.state_contacts.resize(frames.size());
  std::vector<MeshTruthCounts> step_counts(steps), state_counts(frames.size());
  parallel_for(steps, threads, [&](std::size_t s, unsigned) {
    if (cancelled()) return;
    truth.step_contacts[s] = interval_contacts(mesh, frames[s], frames[s + 1], thickness, &step_counts[s]);
  });
  // A contact of state s is a contact of each step that contains it (s - 1 and s).
  parallel_for(frames.size(), threads, [&](std::size_t s, unsigned) {
    if (cancelled()) return;
    const auto& superset = truth.step_contacts[s < steps ? s : s - 1];
    truth.state_contacts[s] = contacts_among(mesh, superset, frames[s], frames[s], thickness, &state_counts[s]);
  });
  for (const MeshTruthCounts& c : step_counts) truth.counts += c;
  for (const MeshTruthCounts& c : state_counts) truth.counts += c;
  return truth;
}

std::vector<MeshContactEvent> contact_events(const MeshTruth& truth) {
  std::map<Candidate, std::vector<std::uint32_t>> steps_of;
  for (std::uint32_t s = 0; s < truth.step_contacts.size(); ++s)
    for (const Candidate& c : truth.step_contacts[s]) steps_of[c].push_back(s);
  std::vector<MeshContactEvent> events;
  for (const auto& [pair, steps] : steps_of)
    for (std::size_t i = 0; i < steps.size();) {
      std::size_t j = i;
      while (j + 1 < steps.size() && steps[j + 1] == steps[j] + 1) ++j;
      events.push_back({pair, steps[i], steps[j]});
      i = j + 1;
    }
  std::sort(events.begin(), events.end(), [](const MeshContactEvent& a, const MeshContactEvent& b) {
    return a.first_step != b.first_step ? a.first_step < b.first_step : a.pair < b.pair;
  });
  return events;
}

}  // namespace ccd::cloth
