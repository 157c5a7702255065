#include <ccd/queries/sphere_sphere_contact.hpp>

#include <ccd/queries/pair_motion.hpp>

#include <cmath>

namespace ccd {
namespace {

bool finite_input(const MovingSphere& a, const MovingSphere& b, double S) {
  return std::isfinite(S) && a.position.allFinite() && a.velocity.allFinite() && a.acceleration.allFinite() &&
         b.position.allFinite() && b.velocity.allFinite() && b.acceleration.allFinite() &&
         std::isfinite(a.radius) && std::isfinite(b.radius);
}

}  // namespace

SublevelSet sphere_sphere_contact_intervals(const MovingSphere& a, const MovingSphere& b, double S) {
  if (!(S >= 0.0) || !finite_input(a, b, S)) return {};
  // One piece per sphere over [0, S]; the data are exact (no trailing parts, no edge error).
  const Piece qa{0.0, S, a.position, a.velocity, a.acceleration};
  const Piece qb{0.0, S, b.position, b.velocity, b.acceleration};
  const PieceLow exact{};
  return PairMotion(qa, exact, a.radius, qb, exact, b.radius).contact_set(0.0, S);
}

SphereSphereContact sphere_sphere_first_contact(const MovingSphere& a, const MovingSphere& b, double S) {
  const SublevelSet set = sphere_sphere_contact_intervals(a, b, S);
  if (set.count == 0) return {};
  const double t = set.intervals[0].lo;
  return {t == 0.0 ? ContactStatus::Overlapping : ContactStatus::Hit, t};
}

}  // namespace ccd
