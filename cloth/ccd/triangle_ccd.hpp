#pragma once
// The conservative floating-point kernel for vertex-face and edge-edge CCD under linear
// motion over t in [0, 1], with a minimum separation.
//
// Guarantee: never a false negative. If the primitives (closed sets; see linear_query.hpp)
// come within `separation` of each other at some t in [0, 1], the result is Hit, and its
// toi is <= the first such time. A Miss is a proof: every rounding error is bounded.
//
// Method (an inclusion test in the spirit of Tight-Inclusion, with a static error bound).
// The difference between the two primitives' points, F(t, a, b) (vertex-face: vertex minus
// the face point with barycentric (a, b); edge-edge: point a of edge A minus point b of
// edge B), is multilinear in (t, a, b): over a box of parameters each component lies
// between its smallest and largest corner value. Corner values are computed in doubles
// with a proved error bound of 16 eps M (eps = 2^-52; the derivation is in triangle_ccd.cpp),
// after the query is moved so that its bounding box is centred on the origin: M is the
// largest coordinate of the moved query, whose own rounding (measured exactly) is added to
// the bound. A query far from the origin is thus decided as finely as the same one near it.
// A box is proved contact-free when some component is above separation + error on every
// corner, or below its negative, or when n.F is, for n the mean corner value or da x db (the face normal, or the edges' common normal), above
// |n| separation plus its error bound on every corner, or below its negative. Boxes are split in
// halves (parameters stay dyadic, so the corner parameters are exact), earliest time first.
//
// With a separation > 0, Hit is also reported, proved, when some corner's |F| plus its
// error bound is within the separation (a contact found long before the boxes get narrow).
// A box whose image is narrower than `tolerance` times the query's extent (its largest
// coordinate range over the eight points), or that cannot be split further, is a
// tolerance stop. It is decided, in order: the box is excluded along the nearest point to
// the origin of the hull of its corner values (hull_direction.hpp: a near miss is
// resolved at once, since the hull of a narrow box hugs F's image); a zero of F is proved
// in a small box around Newton's root (root_proof.hpp: a transversal crossing); otherwise
// the exact reference (exact_ccd.hpp) decides the whole query on its doubles, a rare
// last resort (contact exactly at t = 0 or 1, on a primitive's boundary, a tangent or
// coplanar touch, or a miss within the rounding bound). With keep_tolerance_stops every
// tolerance stop is reported as a contact instead (a false positive is then a near miss
// within about tolerance x extent): the kernel without its exact fallback. When the
// budget of boxes is spent, Hit is reported (conservative). Vertex-face boxes wholly
// outside a + b <= 1 are dropped.
//
// Degenerate-case policy: degenerate triangles and edges are handled as closed convex
// hulls (no special case is needed: the parametrisation covers them). Input that is not
// finite, or larger than 1e300 in magnitude, returns Degenerate (callers treat it as a
// possible contact).
#include <cloth/ccd/linear_query.hpp>
#include <ccd/queries/query_status.hpp>

#include <cstdint>
#include <limits>
#include <string_view>

namespace ccd::cloth {

/// Why a Hit was reported. Proved: a contact proved in floating point (a corner within the
/// separation, or a zero of F); Exact: a tolerance stop decided by the exact reference;
/// Tolerance: a tolerance stop reported as it is (keep_tolerance_stops); Budget: max_boxes
/// spent. None for Miss and Degenerate.
enum class HitReason : std::uint8_t { None, Proved, Exact, Tolerance, Budget };

/// "none", "proved", "exact", "tolerance", "budget".
constexpr std::string_view to_string(HitReason r) {
  constexpr std::string_view names[] = {"none", "proved", "exact", "tolerance", "budget"};
  return names[static_cast<int>(r)];
}

struct TriangleCcdOptions {
  double separation = 0.0;          ///< minimum separation, scene units, >= 0
  double tolerance = 1e-9;          ///< image width of a tolerance stop, relative to the query's extent
  std::uint32_t max_boxes = 20000;  ///< budget of parameter boxes; spent = Hit (conservative)
  bool keep_tolerance_stops = false;  ///< report tolerance stops as Hit, undecided (for measurement)
};

struct TriangleCcdResult {
  QueryStatus status = QueryStatus::Miss;  ///< Hit, Miss or Degenerate
  double toi = std::numeric_limits<double>::infinity();  ///< Hit: a lower bound of the first contact time
  /// A Hit certified at a time: at some t in [toi, toi_upper] the primitives are within the
  /// separation of each other (a proved contact), or every coordinate of their difference
  /// is within separation + w + twice the error bound, w the image width (a narrow
  /// image: w <= max(tolerance x extent, 4 x the error bound)). Infinity when nothing is
  /// certified: a spent budget, a box at the split depth limit, Degenerate input, a Miss.
  double toi_upper = std::numeric_limits<double>::infinity();
  std::uint32_t boxes = 0;                 ///< parameter boxes examined
  bool budget_spent = false;               ///< Hit because max_boxes ran out
  HitReason reason = HitReason::None;      ///< why a Hit was reported
  bool decided_exactly = false;            ///< a tolerance stop was handed to the exact reference (Hit or Miss)
};

TriangleCcdResult triangle_ccd(PrimitivePair kind, const LinearQuery& q, const TriangleCcdOptions& options = {});

}  // namespace ccd::cloth
