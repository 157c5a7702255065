#include <ccd/truth/rigid_static_truth.hpp>

#include <ccd/broad_phase/static_index.hpp>
#include <ccd/truth/bracket_search.hpp>
#include <ccd/util/parallel_for.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

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
  RigidStaticTruthResult out;
  const Trajectories& traj = m.centres();
  if (scenery.empty() || traj.size() == 0) return out;
  const double T = traj.horizon();
  const double tol = options.time_tolerance > 0.0 ? options.time_tolerance : std::ldexp(T, -30);
  const std::size_t W = rigid_truth_windows(m, options);
  auto window_start = [&](std::size_t w) { return w == W ? T : T * static_cast<double>(w) / static_cast<double>(W); };
  std::vector<Aabb> boxes;
  boxes.reserve(scenery.size());
  for (const StaticPolygon& p : scenery) boxes.push_back(polygon_box(p));

  struct PerBody {
    std::vector<StaticEvent> events;
    std::vector<EventError> errors;
    std::size_t evaluations = 0;
  };
  std::vector<PerBody> per_body(traj.size());
  parallel_for(traj.size(), resolve_threads(options.threads), [&](std::size_t b, unsigned) {
    const auto body = static_cast<std::uint32_t>(b);
    PerBody& r = per_body[b];
    if (m.kind(body) == ShapeKind::Sphere) {  // exact, as in a scene of spheres
      append_body_static_events(traj, body, scenery, boxes, r.events);
      r.errors.resize(r.events.size());
      return;
    }
    // Per window, the enclosing sphere's swept box with a rounding margin.
    std::vector<Aabb> swept(W);
    for (std::size_t w = 0; w < W; ++w) {
      Aabb box = traj.swept_bounds(body, window_start(w), window_start(w + 1));
      const double margin = 1e-9 * (1.0 + box.lo.cwiseAbs().maxCoeff() + box.hi.cwiseAbs().maxCoeff());
      box.lo.array() -= margin;
      box.hi.array() += margin;
      swept[w] = box;
    }
    for (std::size_t j = 0; j < scenery.size(); ++j) {
      for (std::size_t w = 0; w < W;) {
        if (!swept[w].overlaps(boxes[j])) {
          ++w;
          continue;
        }
        std::size_t k = w + 1;
        while (k < W && swept[k].overlaps(boxes[j])) ++k;
        r.evaluations += body_polygon_bracket_events(m, body, scenery[j], static_cast<std::uint32_t>(j), window_start(w),
                                                     window_start(k), tol, options.max_evaluations, r.events, r.errors);
        w = k;
      }
    }
  });
  std::vector<StaticEvent> events;
  std::vector<EventError> errors;
  for (PerBody& r : per_body) {
    events.insert(events.end(), r.events.begin(), r.events.end());
    errors.insert(errors.end(), r.errors.begin(), r.errors.end());
    out.evaluations += r.evaluations;
  }
  std::vector<std::size_t> order(events.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t x, std::size_t y) { return static_event_order(events[x], events[y]); });
  for (std::size_t i : order) {
    out.events.push_back(events[i]);
    out.errors.push_back(errors[i]);
    out.grazing += errors[i].grazing;
  }
  return out;
}

}  // namespace ccd
