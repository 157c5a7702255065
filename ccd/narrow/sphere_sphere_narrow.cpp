#include <ccd/narrow/sphere_sphere_narrow.hpp>

#include <ccd/truth/contact_function.hpp>
#include <ccd/truth/pair_contact.hpp>

namespace ccd {

ContactResult sphere_sphere_narrow(const NarrowInput& in, std::uint32_t a, std::uint32_t b) {
  ContactResult r;
  const Trajectories& m = in.motion->centres();
  if (in.sample) {
    const bool touch = in.start_piece.empty() ? in_contact(m, a, b, in.t0)
                                              : in_contact(m, a, in.start_piece[a], b, in.start_piece[b], in.t0);
    if (!touch) return r;
    const BodyState& sa = in.start[a];
    const BodyState& sb = in.start[b];
    r.status = QueryStatus::Overlapping;
    r.toi = in.t0;
    r.signed_distance = (sa.position - sb.position).norm() - (sa.radius + sb.radius);
    return r;
  }
  const auto toi = pair_first_contact(m, a, b, in.t0, in.t1);
  if (!toi) return r;
  r.status = *toi == in.t0 ? QueryStatus::Overlapping : QueryStatus::Hit;
  r.toi = *toi;
  r.signed_distance = sphere_signed_distance(m, a, b, *toi);
  return r;
}

double sphere_signed_distance(const Trajectories& motion, std::uint32_t a, std::uint32_t b, double t) {
  return Vec3(motion.position(a, t) - motion.position(b, t)).norm() - (motion.radius(a) + motion.radius(b));
}

}  // namespace ccd
