#pragma once
// Finding a body's trajectory pieces over a window [u0, u1] from a piece that is already
// known, instead of searching: a state cursor (ccd/motion/state_cursor.hpp) knows each
// body's piece at the step start, and the bounds built from the pieces over the step
// (capsule, swept_aabb, obb_sat) walk from it. A body's pieces are in time order, each
// starting where the one before ends, so the pieces that meet a window are consecutive and
// a window's pieces are at or after the piece at its start (except pieces that end exactly
// at u0, which the swept box includes).
//
// Every function here gives bit for bit what its searching counterpart of
// ccd/motion/trajectory.hpp gives (tests/ccd/motion/piece_walk_test.cpp), provided `k` is
// what the comment says.
#include <ccd/geometry/aabb.hpp>
#include <ccd/motion/trajectory.hpp>

#include <algorithm>
#include <cstddef>

namespace ccd {

/// Trajectories::piece_index(body, t) (the first piece ending after t, the last if none),
/// found by walking forward from piece `k`, which must not be after it (for instance
/// piece_index(body, t') for some t' <= t).
inline std::size_t piece_index_from(const Trajectories& tr, std::size_t body, std::size_t k, double t) {
  const auto ps = tr.pieces(body);
  while (k + 1 < ps.size() && t >= ps[k].t1) ++k;
  return k;
}

/// The box of the body swept over [u0, u1]: every piece with t1 >= u0 and t0 <= u1, merged
/// in order, widened by the radius. Any k at or before the first such piece works (0: what
/// Trajectories::swept_bounds does); given k = piece_index(body, u0) the pieces before k
/// that end exactly at u0 are included too.
inline Aabb swept_bounds_from(const Trajectories& tr, std::size_t body, std::size_t k, double u0, double u1) {
  const auto ps = tr.pieces(body);
  while (k > 0 && ps[k - 1].t1 >= u0) --k;
  Aabb box;
  bool first = true;
  for (; k < ps.size() && !(ps[k].t0 > u1); ++k) {
    const Piece& q = ps[k];
    if (q.t1 < u0) continue;
    const Aabb b = q.centre_bounds(std::max(u0, q.t0), std::min(u1, q.t1));
    if (first) {
      box = b;
      first = false;
    } else {
      box.merge(b);
    }
  }
  const double r = tr.radius(body);
  box.lo.array() -= r;
  box.hi.array() -= -r;
  return box;
}

}  // namespace ccd
