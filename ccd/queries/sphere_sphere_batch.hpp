#pragma once
// Batched exact first contact of sphere pairs under linear motion: for every pair i the
// answer of sphere_sphere_first_contact(a_i, b_i, duration) (ccd/queries/
// sphere_sphere_contact.hpp), bit for bit, for many pairs at once.
//
// The pairs are stored as a structure of arrays (one array per coordinate). They are
// processed in blocks of RelativeMotionBlock::capacity: the relative motion is formed,
// the certified SIMD filter of ccd/queries/sphere_pair_filter.hpp settles the pairs that
// are certainly apart over [0, duration] (Miss, toi = +inf) or certainly in contact at
// s = 0 (Overlapping, toi = 0), and the exact scalar query answers the rest (tangencies,
// contacts inside the window, degenerate data). The filter only ever answers what the
// exact query would answer (see its header), so the results are identical; the cost per
// pair is the filter's (a few ns) plus the exact query's share of the undecided pairs.
//
// Units: the scene's (length, seconds). Linear motion only: the spheres' accelerations
// are zero (push_back refuses others). No allocation in the query itself.
#include <ccd/queries/sphere_sphere_contact.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace ccd {

/// Pairs (a_i, b_i) of linearly moving spheres, structure of arrays.
struct LinearSpherePairs {
  std::array<std::vector<double>, 3> position_a, velocity_a, position_b, velocity_b;
  std::vector<double> radius_a, radius_b;

  std::size_t size() const { return radius_a.size(); }
  /// Appends a pair; throws std::invalid_argument when either acceleration is not zero.
  void push_back(const MovingSphere& a, const MovingSphere& b);
  MovingSphere a(std::size_t i) const;
  MovingSphere b(std::size_t i) const;
};

/// out[i] = sphere_sphere_first_contact(pairs.a(i), pairs.b(i), duration) for every pair;
/// out.size() must be pairs.size() (std::invalid_argument otherwise).
void sphere_sphere_first_contact_batch(const LinearSpherePairs& pairs, double duration,
                                       std::span<SphereSphereContact> out);

}  // namespace ccd
