#include <ccd/truth/rigid_static_truth.hpp>

#include <ccd/truth/bracket_search.hpp>
#include <ccd/truth/truth.hpp>

#include <algorithm>
#include <cmath>

namespace ccd {
namespace {

// The largest distance of a vertex from the first one: the band's size term.
double polygon_reach(const StaticPolygon& polygon) {
  double r = 0.0;
  for (const Vec3& v : polygon.vertices) r = std::max(r, (v - polygon.vertices.front()).norm());
  return r;
}

}  // namespace

std::size_t body_polygon_bracket_events(const RigidMotion& m, std::uint32_t body, const StaticPolygon& polygon,
                                        std::uint32_t polygon_index, double u0, double u1, double tol,
                                        std::size_t max_evaluations, std::vector<StaticEvent>& events,
                                        std::vector<EventError>& errors) {
  if (polygon.vertices.size() < 3 || !(u1 >= u0)) return 0;
  const double lipschitz = m.max_point_speed(body, u0, u1);
  const double band = std::max(lipschitz * tol, 1e-12 * (m.enclosing_radius(body) + polygon_reach(polygon)));
  const ConvexProxy fixed = polygon_proxy(polygon);
  const ConvexProxy shape = m.proxy(body);
  auto probe = [&](double t, const DistanceOptions& o) {
    const Pose p = m.pose(body, t);
    return BracketProbe{convex_distance(shape, {p.centre, p.rotation}, fixed, ProxyPose{}, o), m.pose_error(body, t)};
  };
  BracketSearch search(probe, lipschitz, tol, band, max_evaluations);
  search.run(u0, u1);
  std::vector<BracketEvent> found;
  search.events(m.centres().horizon(), found);
  for (const BracketEvent& e : found) {
    events.push_back({body, polygon_index, e.enter, e.exit});
    errors.push_back(e.error);
  }
  return search.evaluations();
}

RigidStaticTruthResult compute_rigid_static_truth(const RigidMotion& m, std::span<const StaticPolygon> scenery,
                                                  const RigidTruthOptions& options) {
  TruthOptions o;
  o.threads = options.threads;
  o.windows = options.windows;
  o.time_tolerance = options.time_tolerance;
  o.max_evaluations = options.max_evaluations;
  Truth t = compute_truth(m, scenery, o);
  RigidStaticTruthResult out;
  out.errors = t.static_errors.empty() ? std::vector<EventError>(t.static_events.size()) : std::move(t.static_errors);
  out.events = std::move(t.static_events);
  out.evaluations = t.stats.evaluations;
  out.grazing = t.stats.static_grazing;
  return out;
}

}  // namespace ccd
