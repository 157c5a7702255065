#include <ccd/narrow/sphere_polygon_narrow.hpp>
#include <ccd/queries/point_polygon.hpp>
#include <ccd/truth/static_truth.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ccd {
namespace {

double signed_distance_at(const Trajectories& motion, std::uint32_t body, const StaticPolygon& polygon, double t) {
  return std::sqrt(point_polygon_closest(motion.position(body, t), polygon).distance_squared) - motion.radius(body);
}

}  // namespace

ContactResult sphere_polygon_narrow(const NarrowInput& in, std::uint32_t body, const StaticPolygon& polygon) {
  ContactResult out;
  const Trajectories& motion = in.motion->centres();
  if (in.sample) {
    const double d = signed_distance_at(motion, body, polygon, in.t0);
    if (d <= 0.0) {
      out.status = QueryStatus::Overlapping;
      out.toi = in.t0;
      out.signed_distance = d;
    }
    return out;
  }
  thread_local std::vector<ContactInterval> intervals;
  intervals.clear();
  body_polygon_intervals(motion, body, polygon, in.t0, in.t1, intervals);
  if (intervals.empty()) return out;
  const double t = std::max(in.t0, intervals.front().enter);
  out.status = t <= in.t0 ? QueryStatus::Overlapping : QueryStatus::Hit;
  out.toi = t;
  out.signed_distance = signed_distance_at(motion, body, polygon, t);
  return out;
}

}  // namespace ccd
