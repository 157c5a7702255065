#include <ccd/narrow/sphere_sphere_narrow.hpp>

#include <ccd/queries/sphere_touch.hpp>
#include <ccd/truth/pair_contact.hpp>

namespace ccd {

ContactResult sphere_sphere_narrow(const NarrowInput& in, std::uint32_t a, std::uint32_t b) {
  ContactResult r;
  if (in.sample) {
    const BodyState& sa = in.start[a];
    const BodyState& sb = in.start[b];
    if (!spheres_touch(sa.position, sa.radius, sb.position, sb.radius)) return r;
    r.status = QueryStatus::Overlapping;
    r.toi = in.t0;
    r.signed_distance = (sa.position - sb.position).norm() - (sa.radius + sb.radius);
    return r;
  }
  const Trajectories& m = *in.motion;
  const auto toi = pair_first_contact(m, a, b, in.t0, in.t1);
  if (!toi) return r;
  r.status = *toi == in.t0 ? QueryStatus::Overlapping : QueryStatus::Hit;
  r.toi = *toi;
  r.signed_distance = Vec3(m.position(a, *toi) - m.position(b, *toi)).norm() - (m.radius(a) + m.radius(b));
  return r;
}

}  // namespace ccd
