#pragma once
// The peers of ccdlab's broad phases (FCL 0.7, Bullet 3.24 in double precision,
// Boost.Geometry 1.74) and ccdlab's own registry, behind one small interface so that
// peers_bench drives every method with one protocol. Each adapter drives its library the
// way the library's documentation intends: setup() registers the bodies and finds frame 0's
// pairs (not timed per frame; reported as setup time), frame() is one timed frame: the
// library's per-frame update, its pair query, and the collection of the pairs it reports
// into `out` (a < b, any order). Adapters read the scene's spheres (FCL takes sphere
// geometries and translations) or its boxes (Bullet, Boost, ccdlab); both give bit-identical
// boxes [p - r, p + r].
//
// Exactness. Every method must end with exactly the closed-interval AABB-overlap pairs
// (ccd/geometry/aabb.hpp). Libraries whose pair lists are supersets (FCL's spatial hash
// reports pairs sharing a cell; Bullet keeps fattened or quantised boxes and lingering
// pairs in its pair cache) get the exact box test on each reported pair, inside the timed
// frame; reported_pairs() tells how many the library gave before that filter, so the
// output can say which methods were filtered.
#include <ccd/broad_phase/broad_phase.hpp>
#include <benchmarks/support/peer_scene.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace ccdlab::peers {

class PeerMethod {
 public:
  virtual ~PeerMethod() = default;
  /// Registers the scene's bodies and writes frame 0's pairs into `out`.
  virtual void setup(const ccdlab::bench::PeerScene& scene, std::span<const ccd::Aabb> boxes,
                     std::vector<ccd::BodyPair>& out) = 0;
  /// One frame: update from the moved scene, query, write the pairs into `out`.
  virtual void frame(const ccdlab::bench::PeerScene& scene, std::span<const ccd::Aabb> boxes,
                     std::vector<ccd::BodyPair>& out) = 0;
  /// Pairs the library reported in the last call, before the exact filter (with
  /// duplicates, if it reports any).
  virtual std::uint64_t reported_pairs() const = 0;
};

struct PeerInfo {
  std::string name;     ///< e.g. "fcl_dynamic_aabb_tree"
  std::string library;  ///< e.g. "fcl-0.7"
  std::string note;     ///< how it is driven, one line
  std::function<std::unique_ptr<PeerMethod>()> make;
  /// Setup (registering N bodies) is quadratic in N (Bullet's btAxisSweep3).
  bool quadratic_setup = false;
};

/// Exact closed-interval overlap of two boxes given as lo/hi arrays.
inline bool boxes_overlap(const double alo[3], const double ahi[3], const double blo[3], const double bhi[3]) {
  return alo[0] <= bhi[0] && blo[0] <= ahi[0] && alo[1] <= bhi[1] && blo[1] <= ahi[1] && alo[2] <= bhi[2] &&
         blo[2] <= ahi[2];
}

std::vector<PeerInfo> fcl_peers();
std::vector<PeerInfo> bullet_peers();
std::vector<PeerInfo> boost_peers();
/// Every entry of ccd::broad_phase_registry() except `brute`, as a PeerMethod (library "ccdlab").
std::vector<PeerInfo> ccdlab_methods();

}  // namespace ccdlab::peers
