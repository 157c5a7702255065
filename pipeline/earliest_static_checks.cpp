// The earliest scheduler against static scenery: each freshly built body bound queried in
// the static index and tested against the polygons it reports, a due static check decided
// as a pair check with one moving body, and the body-polygon narrow phase.
#include <pipeline/earliest_run.hpp>

#include <bounds/rounding.hpp>
#include <bounds/speed_earliest.hpp>
#include <ccd/queries/point_polygon.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ccd::earliest {

// The static index's polygons for the boxes of `bodies` (bounds just built, from `now`),
// each tested over the body's own window; a pair that may touch gets a check. Two passes
// (index, then tests), so that each stage reads the clock once per refresh.
void EarliestRun::test_static_pairs(double now, std::span<const std::uint32_t> bodies) {
  if (s_.scenery.empty()) return;
  watch_.start();
  static_pairs_.clear();
  for (const std::uint32_t i : bodies) {
    polygons_.clear();
    s_.static_index.query(boxes_[i], polygons_);
    for (const std::uint32_t p : polygons_) static_pairs_.push_back({i, p});
  }
  watch_.stop(local_.broad);
  stats_.scenery.candidates += static_pairs_.size();
  watch_.start();
  for (const StaticPair& q : static_pairs_) {
    const std::uint32_t i = q.body, p = q.polygon;
    ++stats_.scenery.checks;
    const PairTest r = s_.bound.test_static(i, boxes_[i], s_.scenery[p], s_.static_index.box(p));
    if (!r.possible()) continue;
    ++stats_.scenery.passed;
    const Window w = s_.bound.window(i);
    const double t = std::max(r.earliest, now);
    if (inline_checks_) pending_.push_back({t, i, static_b(p), w.t0, w.t1});
    else queue_.push({t, Kind::Check, i, static_b(p), version_[i], version_[i], w.t0});
  }
  watch_.stop(local_.bound);
}

// A due static check at c.t (inline mode): body c.a against polygon_of(c.b) over the
// rest of the body's window, as a pair check with one moving body.
void EarliestRun::decide_static(const Check& c) {
  const double to = c.to;
  const std::uint32_t i = c.a;
  const std::uint32_t p = polygon_of(c.b);
  const StaticPolygon& polygon = s_.scenery[p];
  if (s_.options.recheck) {
    // From the body's state now: its distance to the polygon (a static convex set) and
    // its speed bound give the earliest possible contact (bounds/speed_earliest.hpp).
    state_at(i, c.t);
    const Vec3& x = states_[i].position;
    const SpeedBall ball{x, c.t, speed_bound(i, c.t, to), states_[i].radius};
    const double d = std::sqrt(point_polygon_closest(x, polygon).distance_squared);
    const double from = std::max(c.t, speed_earliest_static(ball, d, static_rounding_slack(x, polygon)));
    ++stats_.scenery.checks;
    if (from > to) return;
    ++stats_.scenery.passed;
    // The chunk: the time in which the distance may change by `chunk` x the radius.
    const double h = s_.options.chunk > 0.0 && ball.speed > 0.0 ? s_.options.chunk * ball.radius / ball.speed
                                                                : std::numeric_limits<double>::infinity();
    if (from < to && from >= c.t + h) {
      next_.push_back({from, i, c.b, c.since, to});
      return;
    }
    jobs_.push_back({i, c.b, from, from + h < to ? from + h : to, to});
    return;
  }
  if (refine_ && c.t - c.since > stale_age_) {
    // The body's own bound from now to the end of its window, in the scratch instance.
    state_at(i, c.t);
    pair_bodies_[0] = i;
    ctx_.t0 = c.t;
    ctx_.t1 = to;
    ctx_.start = states_;
    if (scratch_boxes_.size() != n_) scratch_boxes_.resize(n_);
    s_.scratch.refresh(ctx_, std::span<const std::uint32_t>(pair_bodies_, 1), scratch_boxes_);
    const PairTest r = s_.scratch.test_static(i, scratch_boxes_[i], polygon, s_.static_index.box(p));
    ++stats_.refreshes;
    ++stats_.scenery.checks;
    if (r.possible()) {
      ++stats_.scenery.passed;
      next_.push_back({std::max(r.earliest, c.t), i, c.b, c.t, to});
    }
    return;
  }
  jobs_.push_back({i, c.b, c.t, to, to});
}

// A body's narrow phase against a polygon over [from, until] (exact for a sphere,
// conservative advancement for another shape).
ContactResult EarliestRun::narrow_static(std::uint32_t i, std::uint32_t polygon, double from, double until) {
  ++stats_.scenery.narrow_calls;
  const NarrowInput in{in_.motion, states_, {}, from, until, false};
  return s_.table.find_polygon(in_.motion->kind(i))(in, i, s_.scenery[polygon]);
}

}  // namespace ccd::earliest
