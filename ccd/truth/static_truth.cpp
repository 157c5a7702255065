#include <ccd/truth/static_truth.hpp>

#include <ccd/broad_phase/static_index.hpp>  // polygon_box
#include <ccd/geometry/aabb.hpp>
#include <ccd/queries/sphere_polygon.hpp>
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/truth/pair_contact.hpp>
#include <ccd/truth/truth.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <tuple>

namespace ccd {
namespace {

// The piece's centre box over [u0, u1] grown by r and a margin that covers the rounding
// of the positions evaluated from different expansion points (relative 1e-9 of the
// magnitudes, far above it): the query's own rejection test is the sharp one.
Aabb piece_box(const Piece& q, double r, double u0, double u1) {
  Aabb box = q.centre_bounds(u0, u1);
  const double m = r * (1.0 + 1e-9) + 1e-9 * (box.lo.cwiseAbs().maxCoeff() + box.hi.cwiseAbs().maxCoeff() + r);
  box.lo.array() -= m;
  box.hi.array() += m;
  return box;
}

// Appends the merged contact intervals of `body` with `poly` (box `pbox`) within [u0, u1].
void append_intervals(const Trajectories& traj, std::uint32_t body, const StaticPolygon& poly, const Aabb& pbox,
                      double u0, double u1, std::vector<ContactInterval>& scratch, std::vector<ContactInterval>& out) {
  const std::size_t first = out.size();
  const double gap = merge_gap(traj.horizon());
  const auto ps = traj.pieces(body);
  const auto lows = traj.lows(body);
  const double r = traj.radius(body);
  auto it = std::lower_bound(ps.begin(), ps.end(), u0, [](const Piece& q, double x) { return q.t1 < x; });
  for (; it != ps.end() && it->t0 <= u1; ++it) {
    const Piece& q = *it;
    if (!piece_box(q, r, std::max(u0, q.t0), std::min(u1, q.t1)).overlaps(pbox)) continue;
    scratch.clear();
    sphere_polygon_contacts(q, lows[static_cast<std::size_t>(it - ps.begin())], r, poly, q.t0, q.t1, scratch);
    for (const ContactInterval& c : scratch) {
      if (c.exit < u0 || c.enter > u1) continue;
      const double enter = std::max(c.enter, u0), exit = std::min(c.exit, u1);
      if (out.size() > first && enter <= out.back().exit + gap) {
        out.back().exit = std::max(out.back().exit, exit);
      } else {
        out.push_back({enter, exit});
      }
    }
  }
}

}  // namespace

bool static_event_order(const StaticEvent& x, const StaticEvent& y) {
  return std::tie(x.enter, x.body, x.polygon) < std::tie(y.enter, y.body, y.polygon);
}

void body_polygon_intervals(const Trajectories& traj, std::uint32_t body, const StaticPolygon& poly, double u0,
                            double u1, std::vector<ContactInterval>& out) {
  assert(body < traj.size());
  if (!(u1 >= u0) || poly.vertices.size() < 3) return;
  std::vector<ContactInterval> scratch;
  append_intervals(traj, body, poly, polygon_box(poly), u0, u1, scratch, out);
}

std::vector<StaticEvent> compute_static_truth(const Trajectories& traj, std::span<const StaticPolygon> scenery,
                                              unsigned threads) {
  TruthOptions options;
  options.threads = threads;
  const RigidMotion balls(traj);
  return compute_truth(balls, scenery, options).static_events;
}

}  // namespace ccd
