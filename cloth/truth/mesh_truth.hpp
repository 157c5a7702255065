#pragma once
// The exact self-contact truth of a cloth run (docs/cloth.md#mesh-truth).
//
// The motion is a sequence of states (frames) x_0, ..., x_S of the mesh's vertices, one per
// integrator step, and every vertex moves linearly between consecutive states. A typed
// candidate (vertex-face or edge-edge, adjacent primitives excluded: cloth/cull/candidate.hpp)
// is a contact
//  - of step s (0 <= s < S) when the two primitives come within `thickness` (distance <=
//    thickness, touching included) at some time of the closed step [s h, (s + 1) h] under
//    that linear motion;
//  - of state s (0 <= s <= S) when they are within `thickness` in state x_s.
// Both are decided exactly: the positions are the doubles of the frames, `thickness` is the
// double given, and a pair is a contact iff the exact rational reference (exact_contact)
// says so. A certified floating-point decision (certified_proximity: its Within and Apart
// are proofs) answers first; the exact reference runs only on the pairs it leaves
// Undecided. Pairs whose boxes (each primitive's box over both states of the step) are
// further apart than `thickness` on some axis are skipped before it: such a pair is proved
// apart, since the box gap is compared in doubles with a monotone rounding against the
// double thickness.
//
// A contact event is a maximal run of consecutive steps in which one pair is a contact.
// Events do not depend on any check interval: a method that checks every k steps is
// measured against the same events (experiments/run_cloth_experiment.hpp).
#include <cloth/cull/candidate.hpp>

#include <atomic>
#include <cstdint>
#include <span>
#include <vector>

namespace ccd::cloth {

/// How the pairs of a truth were decided (they do not change the truth).
struct MeshTruthCounts {
  std::uint64_t pairs = 0;     ///< pairs past the box filter (steps and states)
  std::uint64_t within = 0;    ///< proved contacts by the certified decision
  std::uint64_t apart = 0;     ///< proved apart by the certified decision
  std::uint64_t exact = 0;     ///< left undecided: decided by the exact reference
  MeshTruthCounts& operator+=(const MeshTruthCounts& o) {
    pairs += o.pairs;
    within += o.within;
    apart += o.apart;
    exact += o.exact;
    return *this;
  }
};

struct MeshTruth {
  double thickness = 0.0;  ///< the contact distance, scene units, >= 0
  /// [s]: the contacts of step s (states s -> s + 1), sorted; S entries.
  std::vector<std::vector<Candidate>> step_contacts;
  /// [s]: the contacts of state s, sorted; S + 1 entries.
  std::vector<std::vector<Candidate>> state_contacts;
  MeshTruthCounts counts;  ///< not stored in truth files (0 for a truth read back)
};

struct MeshContactEvent {
  Candidate pair;
  std::uint32_t first_step = 0;  ///< the event's steps are first_step..last_step
  std::uint32_t last_step = 0;
};

/// True iff the pair's primitives come within `thickness` at some time of the linear motion
/// x0 -> x1 (exact; the certified decision first, counted in `counts` when given).
bool exact_pair_contact(const ClothMesh& mesh, const Candidate& c, std::span<const Vec3> x0, std::span<const Vec3> x1,
                        double thickness, MeshTruthCounts* counts = nullptr);

/// The contacts, among `candidates`, of the linear motion x0 -> x1 (x1 = x0: of one state),
/// sorted.
std::vector<Candidate> contacts_among(const ClothMesh& mesh, std::span<const Candidate> candidates,
                                      std::span<const Vec3> x0, std::span<const Vec3> x1, double thickness,
                                      MeshTruthCounts* counts = nullptr);

/// Every contact of the linear motion x0 -> x1: the same set as contacts_among over
/// brute_force_candidates, with the box filter above in front.
std::vector<Candidate> interval_contacts(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1,
                                         double thickness, MeshTruthCounts* counts = nullptr);

/// The truth of a run: frames.size() >= 2 states of mesh's vertices (all the same size),
/// thickness >= 0 and finite. Steps are computed on `threads` threads; the result does not
/// depend on it. When `cancel` becomes true the work stops early and the result is partial.
MeshTruth compute_mesh_truth(const ClothMesh& mesh, std::span<const std::vector<Vec3>> frames, double thickness,
                             unsigned threads = 1, const std::atomic<bool>* cancel = nullptr);

/// The contact events of a truth, sorted by (first_step, pair).
std::vector<MeshContactEvent> contact_events(const MeshTruth& truth);

}  // namespace ccd::cloth
