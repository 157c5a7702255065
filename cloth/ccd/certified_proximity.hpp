#pragma once
// A certified floating-point decision of "do the two primitives come within `separation`
// at some t in [0, 1]?" under linear motion (the question the exact reference, exact_ccd,
// answers), with a third answer when floating point cannot decide.
//
// Guarantee: Within and Apart are proofs. Within: some point (t, a, b) of the parameter
// domain has |F(t, a, b)| <= separation exactly. Apart: |F| > separation on the whole
// domain. Undecided: neither was proved within the budget; the caller asks the exact
// reference (cloth/truth/mesh_truth.cpp does). So "filtered, then exact on Undecided"
// decides exactly what the exact reference decides.
//
// Method. F(t, a, b) is the difference between the primitives' points (vertex minus face
// point with barycentric (a, b); or edge A's point at a minus edge B's point at b), multilinear
// in (t, a, b). Boxes of parameters are split in halves (dyadic parameters, exact corners),
// earliest time first. At each box the corner values of F are computed in doubles, each
// component within err = 16 eps M of its exact value (M the largest input magnitude; the
// derivation is in triangle_ccd.cpp and applies unchanged here). Then:
//  - Within when a corner has sum_k (|f_k| + err)^2 <= separation^2, evaluated with upward
//    rounding margins (every corner lies in the domain: vertex-face corners are clipped to
//    a + b <= 1 exactly);
//  - the box is excluded when one component is above separation + err at every corner (or
//    below its negative), or n.F is above |n| separation plus its error bound at every
//    corner for n = the mean corner value or da x db (F is multilinear, so its range over
//    the box is spanned by the corners);
//  - Undecided when a box narrower than `min_width` times the query's extent (and 4 err) is
//    neither, or when `max_boxes` boxes have been examined.
// Apart when every box is excluded.
//
// With separation 0 Within needs F = 0 with err = 0, which never happens: contacts at
// separation 0 are all Undecided (misses are still proved Apart).
// Input that is not finite or above 1e300 in magnitude is Undecided.
#include <cloth/ccd/linear_query.hpp>

#include <cstdint>

namespace ccd::cloth {

enum class Proximity : std::uint8_t { Within, Apart, Undecided };

/// "within", "apart", "undecided".
constexpr const char* to_string(Proximity p) {
  return p == Proximity::Within ? "within" : p == Proximity::Apart ? "apart" : "undecided";
}

struct ProximityOptions {
  double min_width = 1e-12;        ///< relative to the query's extent: below it a box is Undecided
  std::uint32_t max_boxes = 4096;  ///< budget of parameter boxes; spent = Undecided
};

struct ProximityResult {
  Proximity decision = Proximity::Undecided;
  std::uint32_t boxes = 0;  ///< parameter boxes examined
};

/// separation >= 0 (scene units).
ProximityResult certified_proximity(PrimitivePair kind, const LinearQuery& q, double separation,
                                    const ProximityOptions& options = {});

}  // namespace ccd::cloth
