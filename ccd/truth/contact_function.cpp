#include <ccd/truth/contact_function.hpp>
#include <ccd/geometry/numeric_limits.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ccd {
namespace {

// Piece ib of b, moved to b's periodic image nearest to a at time t in a periodic scene
// (with the edge condition the only image that can touch a: ccd/scene/periodic.hpp).
struct ImagePiece {
  Piece q;
  PieceLow low;
};
ImagePiece nearest_image(const Trajectories& traj, const Piece& qa, std::uint32_t b, std::size_t ib, double t) {
  ImagePiece r{traj.pieces(b)[ib], traj.lows(b)[ib]};
  if (const PeriodicBox* box = traj.periodic()) {
    const ImageShift s = box->nearest(qa.position(t), r.q.position(t));
    if (s != ImageShift{0, 0, 0}) shift_piece(r.q, r.low, image_offset(*box, s));
  }
  return r;
}

}  // namespace

ContactCertainty certain_contact(const Trajectories& traj, std::uint32_t a, std::size_t ia, std::uint32_t b,
                                 std::size_t ib, double t) {
  const Piece& qa = traj.pieces(a)[ia];
  const ImagePiece image = nearest_image(traj, qa, b, ib, t);
  const Piece& qb = image.q;
  const double R = traj.radius(a) + traj.radius(b);
  const Vec3 d = qb.position(t) - qa.position(t);
  const double dn = d.norm();
  const double f = d.squaredNorm() - R * R;
  const double P = std::max(piece_magnitude(qa, t), piece_magnitude(qb, t));
  const PieceLow& la = traj.lows(a)[ia];
  const PieceLow& lb = image.low;
  const double edge = la.edge_error + lb.edge_error + la.start_error + lb.start_error +
                      la.velocity_error * std::fabs(t - qa.t0) + lb.velocity_error * std::fabs(t - qb.t0);
  const double band = 64.0 * kEps * (dn + R) * (dn + R + P) + 4.0 * (dn + R) * edge;
  if (f > band) return ContactCertainty::Apart;
  if (f < -band) return ContactCertainty::Contact;
  return ContactCertainty::Unsure;
}

bool in_contact(const Trajectories& traj, std::uint32_t a, std::size_t ia, std::uint32_t b, std::size_t ib, double t) {
  switch (certain_contact(traj, a, ia, b, ib, t)) {
    case ContactCertainty::Apart: return false;
    case ContactCertainty::Contact: return true;
    case ContactCertainty::Unsure: break;
  }
  const ImagePiece image = nearest_image(traj, traj.pieces(a)[ia], b, ib, t);
  const PairMotion m(traj.pieces(a)[ia], traj.lows(a)[ia], traj.radius(a), image.q, image.low, traj.radius(b));
  const ContactValue v = m.value(t);
  return v.f <= v.error;
}

bool in_contact(const Trajectories& traj, std::uint32_t a, std::uint32_t b, double t) {
  return in_contact(traj, a, traj.piece_index(a, t), b, traj.piece_index(b, t), t);
}

}  // namespace ccd
