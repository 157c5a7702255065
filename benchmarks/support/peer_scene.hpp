#pragma once
// The shared moving-spheres scene on which ccdlab's broad phases are compared with FCL,
// Bullet and Boost.Geometry (its definition, shared with the
// peer programs, is this header's). A deterministic function of (N, seed): N spheres with radius
// in [0.5, 1.5] in the cube [0, L]^3 (L from a fixed table or cbrt), moving linearly with
// speed in [0, 10) and reflecting their centres at the walls, one frame = dt = 1/60.
//
// Reproduction is bit-exact: the uniform draws follow libstdc++'s
// uniform_real_distribution<double> over std::mt19937_64 written out by hand (so another
// standard library gives the same doubles) and the library is built with
// -ffp-contract=off (no FMA). The state hash and the pair checksum are the ones the peer
// programs print; peer_scene_references() holds their published values.
#include <ccd/broad_phase/broad_phase.hpp>
#include <ccd/geometry/aabb.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace ccdlab::bench {

/// Published checks of the peer scene for seed 1 (frame 22 = after 22 steps).
struct PeerSceneReference {
  std::size_t n = 0;
  std::uint64_t state_hash_0 = 0;
  std::uint64_t state_hash_22 = 0;
  std::uint64_t pairs_0 = 0;
  std::uint64_t pairs_22 = 0;
  std::uint64_t checksum_0 = 0;
  std::uint64_t checksum_22 = 0;
};

/// The table for N = 1000, 5000, 10000, 100000, 1000000 (seed 1).
std::span<const PeerSceneReference> peer_scene_references();

/// Side L of the cube: the table value of docs/peers.md for the listed N, else its cbrt formula.
double peer_scene_side(std::size_t n);

/// splitmix64's finaliser of (min << 32 | max): the pair hash of docs/peers.md.
std::uint64_t peer_pair_hash(std::uint32_t i, std::uint32_t j);
/// Sum mod 2^64 of peer_pair_hash over the pairs (order does not matter).
std::uint64_t peer_pair_checksum(std::span<const ccd::BodyPair> pairs);

/// Structure of arrays: positions, velocities, radii. Units: scene lengths, seconds.
class PeerScene {
 public:
  static constexpr double kDt = 1.0 / 60.0;  ///< seconds per frame

  PeerScene(std::size_t n, std::uint64_t seed);

  std::size_t size() const { return r_.size(); }
  double side() const { return side_; }
  /// Advances one frame: x = p + v dt, reflected at 0 and L (velocity component flips).
  void step();
  /// Box of sphere i is [p - r, p + r]; `out` is resized to size().
  void boxes(std::vector<ccd::Aabb>& out) const;
  /// Centre coordinate `axis` (0, 1, 2) of every sphere, and the radii: what a library
  /// that takes spheres (FCL) is given; boxes() is [p - r, p + r] of these.
  std::span<const double> centres(int axis) const { return p_[axis]; }
  std::span<const double> radii() const { return r_; }
  /// Velocity component `axis` of every sphere (scene lengths per second).
  std::span<const double> velocities(int axis) const { return v_[axis]; }
  /// FNV-1a 64 over the little-endian bytes of p.x p.y p.z v.x v.y v.z r per sphere.
  std::uint64_t state_hash() const;

 private:
  double side_ = 0.0;
  std::vector<double> p_[3];
  std::vector<double> v_[3];
  std::vector<double> r_;
};

}  // namespace ccdlab::bench
