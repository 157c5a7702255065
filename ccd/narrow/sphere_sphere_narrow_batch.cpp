#include <ccd/narrow/sphere_sphere_narrow_batch.hpp>

#include <ccd/narrow/sphere_sphere_narrow.hpp>
#include <ccd/queries/pair_motion.hpp>
#include <ccd/queries/sphere_pair_filter.hpp>

#include <algorithm>
#include <stdexcept>

namespace ccd {
namespace {

// The index of the one piece of `body` that covers [u0, u1] as the exact query sees it
// (the first piece ending at or after u0 is also the one containing u0), or -1. A piece
// that ends exactly at u1 covers the window only when it is the body's last (a step ending
// at the horizon): otherwise the exact query also meets the next piece at u1.
std::ptrdiff_t single_piece(const Trajectories& m, std::span<const std::size_t> start_piece, std::uint32_t body,
                            double u0, double u1) {
  const std::span<const Piece> ps = m.pieces(body);
  const std::size_t k = start_piece.empty() ? m.piece_index(body, u0) : start_piece[body];
  if (k >= ps.size()) return -1;
  const Piece& q = ps[k];
  const bool starts_before = q.t0 < u0 || (k == 0 && q.t0 <= u0);
  const bool ends_after = u1 < q.t1 || (k + 1 == ps.size() && u1 <= q.t1);
  return starts_before && ends_after ? static_cast<std::ptrdiff_t>(k) : -1;
}

// Asks the cache for body's piece at u0 and its trailing parts (two lines each), when the
// cursor's piece index is given: the pairs of a block read the pieces of scattered bodies,
// and asking for those of the pair a few places ahead while gathering this one lets their
// misses overlap. Always inlined: GCC would find a separate function free of side effects
// and drop its calls.
[[gnu::always_inline]] inline void prefetch_piece(const Trajectories& m, std::span<const std::size_t> start_piece, std::uint32_t body) {
  const std::size_t k = start_piece[body];
  const char* q = reinterpret_cast<const char*>(m.pieces(body).data() + k);
  const char* l = reinterpret_cast<const char*>(m.lows(body).data() + k);
  __builtin_prefetch(q);
  __builtin_prefetch(q + sizeof(Piece) - 1);
  __builtin_prefetch(l);
  __builtin_prefetch(l + sizeof(PieceLow) - 1);
}

}  // namespace

void sphere_sphere_narrow_batch(const NarrowInput& in, std::span<const BodyPair> pairs, std::span<ContactResult> out) {
  if (out.size() != pairs.size()) throw std::invalid_argument("sphere_sphere_narrow_batch: out.size() != pairs.size()");
  const Trajectories& m = in.motion->centres();
  const double u0 = in.t0, u1 = in.t1;
  if (in.sample || m.periodic() || !(u1 >= u0)) {
    for (std::size_t i = 0; i < pairs.size(); ++i) out[i] = sphere_sphere_narrow(in, pairs[i].a, pairs[i].b);
    return;
  }
  RelativeMotionBlock block;
  PairVerdict verdicts[RelativeMotionBlock::capacity];
  bool eligible[RelativeMotionBlock::capacity];
  for (std::size_t first = 0; first < pairs.size(); first += RelativeMotionBlock::capacity) {
    const std::size_t count = std::min(RelativeMotionBlock::capacity, pairs.size() - first);
    block.count = count;
    for (std::size_t i = 0; i < count; ++i) {
      const BodyPair p = pairs[first + i];
      if (constexpr std::size_t kAhead = 8; !in.start_piece.empty() && first + i + kAhead < pairs.size()) {
        prefetch_piece(m, in.start_piece, pairs[first + i + kAhead].a);
        prefetch_piece(m, in.start_piece, pairs[first + i + kAhead].b);
      }
      const std::ptrdiff_t ka = single_piece(m, in.start_piece, p.a, u0, u1);
      const std::ptrdiff_t kb = ka < 0 ? -1 : single_piece(m, in.start_piece, p.b, u0, u1);
      bool ok = kb >= 0;
      if (ok) {
        const Piece& qa = m.pieces(p.a)[static_cast<std::size_t>(ka)];
        const Piece& qb = m.pieces(p.b)[static_cast<std::size_t>(kb)];
        const PieceLow& la = m.lows(p.a)[static_cast<std::size_t>(ka)];
        const PieceLow& lb = m.lows(p.b)[static_cast<std::size_t>(kb)];
        ok = qa.a == qb.a && la.a == lb.a;  // linear relative motion
        if (ok) {
          const Vec3 d = qb.position(u0) - qa.position(u0);
          const Vec3 v = qb.velocity(u0) - qa.velocity(u0);
          block.dx[i] = d.x();
          block.dy[i] = d.y();
          block.dz[i] = d.z();
          block.vx[i] = v.x();
          block.vy[i] = v.y();
          block.vz[i] = v.z();
          block.radius_sum[i] = m.radius(p.a) + m.radius(p.b);
          // P at u1 bounds every magnitude met at u0 (it grows with the piece's time).
          block.magnitude[i] = std::max(piece_magnitude(qa, u1), piece_magnitude(qb, u1));
          block.model[i] = la.edge_error + lb.edge_error + la.start_error + lb.start_error +
                           (la.velocity_error + lb.velocity_error) * (u1 - std::min(qa.t0, qb.t0));
        }
      }
      eligible[i] = ok;
      if (!ok) {  // harmless values; the verdict is overridden below
        block.dx[i] = block.dy[i] = block.dz[i] = block.vx[i] = block.vy[i] = block.vz[i] = 0.0;
        block.radius_sum[i] = block.magnitude[i] = block.model[i] = 0.0;
      }
    }
    classify_relative_motion(block, u1 - u0, verdicts);
    for (std::size_t i = 0; i < count; ++i) {
      const BodyPair p = pairs[first + i];
      ContactResult& r = out[first + i];
      switch (eligible[i] ? verdicts[i] : PairVerdict::Solve) {
        case PairVerdict::Apart: r = ContactResult{}; break;
        case PairVerdict::Contact:
          r = ContactResult{};
          r.status = QueryStatus::Overlapping;
          r.toi = u0;
          r.signed_distance = sphere_signed_distance(m, p.a, p.b, u0);
          break;
        case PairVerdict::Solve: r = sphere_sphere_narrow(in, p.a, p.b); break;
      }
    }
  }
}

}  // namespace ccd
