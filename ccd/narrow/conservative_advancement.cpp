#include <ccd/narrow/conservative_advancement.hpp>

#include <ccd/motion/rigid_motion.hpp>
#include <ccd/queries/convex_distance.hpp>

#include <cmath>
#include <limits>

namespace ccd {
namespace {

ConvexDistance distance_at(const RigidMotion& m, std::uint32_t a, std::uint32_t b, double t, double tolerance) {
  const Pose pa = m.pose(a, t), pb = m.pose(b, t);
  DistanceOptions o;
  o.tolerance = tolerance;
  return convex_distance(m.proxy(a), {pa.centre, pa.rotation}, m.proxy(b), {pb.centre, pb.rotation}, o);
}

}  // namespace

ContactResult conservative_advancement(const NarrowInput& in, std::uint32_t a, std::uint32_t b) {
  return conservative_advancement(in, a, b, AdvancementOptions{});
}

ContactResult conservative_advancement(const NarrowInput& in, std::uint32_t a, std::uint32_t b,
                                       const AdvancementOptions& options, int* iterations) {
  const RigidMotion& m = *in.rigid;
  const double inf = std::numeric_limits<double>::infinity();
  const double tol = options.tolerance;
  ContactResult r;
  ConvexDistance d = distance_at(m, a, b, in.t0, 0.25 * tol);
  if (iterations) *iterations = 1;
  if (d.status == ConvexDistance::Status::Failed) {
    r.status = QueryStatus::Failed;
    return r;
  }
  if (in.sample || d.status == ConvexDistance::Status::Overlapping) {
    if (d.status == ConvexDistance::Status::Separated) return r;  // Miss
    r.status = QueryStatus::Overlapping;
    r.toi = in.t0;
    r.signed_distance = d.upper;
    return r;
  }
  const double mu = m.max_point_speed(a, in.t0, in.t1) + m.max_point_speed(b, in.t0, in.t1);
  double t = in.t0;
  for (int it = 1;; ++it) {
    if (iterations) *iterations = it;
    if (d.status == ConvexDistance::Status::Failed) {
      r.status = QueryStatus::Failed;
      return r;
    }
    if (!(d.lower > tol) || it >= options.max_iterations) break;
    if (mu == 0.0) return r;  // nothing moves and the pair is apart: Miss
    const double next = t + d.lower / mu;
    if (next > in.t1) return r;  // Miss: no contact in [t0, t1]
    t = next;
    d = distance_at(m, a, b, t, 0.25 * tol);
  }
  r.status = QueryStatus::Hit;
  r.toi = t;
  r.signed_distance = d.upper;
  r.toi_error = inf;
  if (d.status == ConvexDistance::Status::Overlapping) {
    r.toi_error = 0.0;
    return r;
  }
  if (!(d.lower <= tol)) return r;  // iteration limit: conservative, unbracketed
  // The bracket's far end: the first probe with a certified overlap, then halved.
  double h = mu > 0.0 ? tol / mu : in.t1 - t;
  double hi = inf;
  while (t + h <= in.t1 && h > 0.0) {
    if (distance_at(m, a, b, t + h, 0.25 * tol).status == ConvexDistance::Status::Overlapping) {
      hi = t + h;
      break;
    }
    h *= 2.0;
  }
  if (hi == inf && t < in.t1 &&
      distance_at(m, a, b, in.t1, 0.25 * tol).status == ConvexDistance::Status::Overlapping)
    hi = in.t1;
  if (hi == inf) return r;  // a near miss within the tolerance (or a contact not certified)
  for (int k = 0; k < 60 && hi > t; ++k) {
    const double mid = t + 0.5 * (hi - t);
    if (mid <= t || mid >= hi) break;
    if (distance_at(m, a, b, mid, 0.25 * tol).status != ConvexDistance::Status::Overlapping) break;
    hi = mid;
  }
  r.toi_error = hi - t;
  return r;
}

}  // namespace ccd
