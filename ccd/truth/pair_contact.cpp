#include <ccd/truth/pair_contact.hpp>

#include <ccd/truth/contact_function.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cassert>
#include <limits>

namespace ccd {
namespace {

// Periodic scenes: the contact intervals of one common piece [c0, c1] against every image
// of b that can come within r_a + r_b of a, clipped to [u0, u1] and sorted (into `out`).
// Positions on a wrapped axis stay in [min, max] (pieces end at the faces), so the relative
// coordinate lies in (-L, L) and only the shifts -1, 0, +1 can bring b within
// r_a + r_b <= L / 2; per axis, the shifts whose centre boxes come within that distance
// (plus a rounding slack) are solved exactly, each on the whole piece as above. Returns
// false when no shift is possible.
bool periodic_piece_intervals(const PeriodicBox& box, const Piece& qa, const PieceLow& la, double ra, const Piece& qb,
                              const PieceLow& lb, double rb, double c0, double c1, double u0, double u1,
                              std::vector<RootInterval>& out) {
  out.clear();
  const Aabb ba = qa.centre_bounds(c0, c1), bb = qb.centre_bounds(c0, c1);
  const double R = ra + rb;
  std::array<std::array<std::int32_t, 3>, 3> shifts{};
  std::array<int, 3> count{};
  for (std::size_t k = 0; k < 3; ++k) {
    count[k] = box.contact_shifts(ba, bb, R, static_cast<int>(k), shifts[k]);
    if (count[k] == 0) return false;
  }
  for (int x = 0; x < count[0]; ++x)
    for (int y = 0; y < count[1]; ++y)
      for (int z = 0; z < count[2]; ++z) {
        const ImageShift s{shifts[0][static_cast<std::size_t>(x)], shifts[1][static_cast<std::size_t>(y)],
                           shifts[2][static_cast<std::size_t>(z)]};
        Piece q = qb;
        PieceLow l = lb;
        shift_piece(q, l, image_offset(box, s));
        const PairMotion motion(qa, la, ra, q, l, rb);
        const bool clipped = c0 < u0 || c1 > u1;
        if (clipped && motion.certainly_apart(std::max(c0, u0), std::min(c1, u1))) continue;
        const SublevelSet set = motion.contact_set(c0, c1);
        for (int k = 0; k < set.count; ++k) {
          const RootInterval& iv = set.intervals[k];
          if (iv.hi < u0 || iv.lo > u1) continue;
          out.push_back(iv);
        }
      }
  std::sort(out.begin(), out.end(), [](const RootInterval& p, const RootInterval& q) { return p.lo < q.lo; });
  return true;
}

// Calls visit(enter, exit) for every contact interval of the pair on each common piece
// that overlaps [u0, u1], in time order, clipped to [u0, u1]. visit returns false to stop.
template <class Visit>
void for_each_piece_interval(const Trajectories& traj, std::uint32_t a, std::uint32_t b, double u0, double u1,
                             Visit&& visit) {
  assert(a < traj.size() && b < traj.size() && a != b);
  if (!(u1 >= u0)) return;
  const auto pa = traj.pieces(a);
  const auto pb = traj.pieces(b);
  auto first_ending_after = [u0](std::span<const Piece> ps) {
    auto it = std::lower_bound(ps.begin(), ps.end(), u0, [](const Piece& q, double x) { return q.t1 < x; });
    return static_cast<std::size_t>(it - ps.begin());
  };
  std::size_t ia = first_ending_after(pa);
  std::size_t ib = first_ending_after(pb);
  const double ra = traj.radius(a), rb = traj.radius(b);
  const auto la = traj.lows(a);
  const auto lb = traj.lows(b);
  const PeriodicBox* periodic = traj.periodic();
  std::vector<RootInterval> found;
  auto advance = [&] {
    if (pa[ia].t1 < pb[ib].t1) {
      ++ia;
    } else if (pb[ib].t1 < pa[ia].t1) {
      ++ib;
    } else {
      ++ia;
      ++ib;
    }
  };
  while (ia < pa.size() && ib < pb.size()) {
    const Piece& qa = pa[ia];
    const Piece& qb = pb[ib];
    const double c0 = std::max(qa.t0, qb.t0);
    const double c1 = std::min(qa.t1, qb.t1);
    if (c0 > u1) return;
    if (c1 >= c0 && c1 >= u0 && periodic) {
      if (!periodic_piece_intervals(*periodic, qa, la[ia], ra, qb, lb[ib], rb, c0, c1, u0, u1, found)) {
        advance();
        continue;
      }
      for (const RootInterval& iv : found)
        if (!visit(std::max(iv.lo, u0), std::min(iv.hi, u1))) return;
    } else if (c1 >= c0 && c1 >= u0) {
      const PairMotion motion(qa, la[ia], ra, qb, lb[ib], rb);
      // The cheap filter on the part of the piece inside the window first: the exact
      // solve below always covers the whole piece (so that times do not depend on the
      // window), which a runner step asking about a short window rarely needs.
      const bool clipped = c0 < u0 || c1 > u1;
      if (clipped && motion.certainly_apart(std::max(c0, u0), std::min(c1, u1))) {
        advance();
        continue;
      }
      const SublevelSet set = motion.contact_set(c0, c1);
      for (int k = 0; k < set.count; ++k) {
        const RootInterval& iv = set.intervals[k];
        if (iv.hi < u0 || iv.lo > u1) continue;
        if (!visit(std::max(iv.lo, u0), std::min(iv.hi, u1))) return;
      }
    }
    advance();
  }
}

}  // namespace

double merge_gap(double horizon) { return 16.0 * std::numeric_limits<double>::epsilon() * horizon; }

void pair_contact_intervals(const Trajectories& traj, std::uint32_t a, std::uint32_t b, double u0, double u1,
                            std::vector<ContactInterval>& out) {
  const std::size_t first = out.size();
  const double gap = merge_gap(traj.horizon());
  for_each_piece_interval(traj, a, b, u0, u1, [&](double enter, double exit) {
    if (out.size() > first && enter <= out.back().exit + gap) {
      out.back().exit = std::max(out.back().exit, exit);
    } else {
      out.push_back({enter, exit});
    }
    return true;
  });
}

std::optional<double> pair_first_contact(const Trajectories& traj, std::uint32_t a, std::uint32_t b, double u0,
                                         double u1) {
  // Deep in contact at u0 (certain in double precision): u0 lies inside a truth interval.
  if (u1 >= u0 &&
      certain_contact(traj, a, traj.piece_index(a, u0), b, traj.piece_index(b, u0), u0) == ContactCertainty::Contact)
    return u0;
  std::optional<double> result;
  for_each_piece_interval(traj, a, b, u0, u1, [&](double enter, double) {
    result = enter;
    return false;
  });
  return result;
}

}  // namespace ccd
