#include <ccd/truth/rigid_truth.hpp>

#include <ccd/queries/convex_distance.hpp>
#include <ccd/truth/bracket_search.hpp>
#include <ccd/truth/sphere_refinement.hpp>
#include <ccd/truth/truth.hpp>
#include <ccd/truth/truth_table.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>

namespace ccd {
namespace {

// The bracket search of a and b over pieces of the centres' paths: `qa`, `qb` when given
// (pieces that cover the searched interval; b's may be a periodic image), else the
// trajectories'.
BracketSearch pair_search(const RigidMotion& m, std::uint32_t a, std::uint32_t b, double lipschitz, double tol,
                          std::size_t max_evaluations, const Piece* qa = nullptr, const Piece* qb = nullptr) {
  const double band = std::max(lipschitz * tol, 1e-12 * (m.enclosing_radius(a) + m.enclosing_radius(b)));
  auto probe = [&m, a, b, qa, qb](double t, const DistanceOptions& o) {
    Pose pa = m.pose(a, t), pb = m.pose(b, t);
    if (qa) pa.centre = qa->position(t);
    if (qb) pb.centre = qb->position(t);
    // The poses' evaluation error (free spin; 0 otherwise) moves every point by at most
    // the slack: the distance of the exact poses is within it of the evaluated one.
    return BracketProbe{convex_distance(m.proxy(a), {pa.centre, pa.rotation}, m.proxy(b), {pb.centre, pb.rotation}, o),
                        m.pose_error(a, t) + m.pose_error(b, t)};
  };
  return BracketSearch(probe, lipschitz, tol, band, max_evaluations);
}


// The events of one finished search (ccd/truth/bracket_search.hpp) over [u0, u1],
// appended to events and errors as events of the pair (a, b). Where one of the two is a
// ball, each grazing event's bracket is searched again by refine_sphere_pair
// (ccd/truth/sphere_refinement.hpp), whose events replace it. Returns the evaluations of
// those searches.
std::size_t search_events(const RigidMotion& m, BracketSearch& search, std::uint32_t a, std::uint32_t b, double u0,
                          double u1, double tol, std::size_t max_evaluations, const Piece* qa, const Piece* qb,
                          std::vector<ContactEvent>& events, std::vector<EventError>& errors) {
  const double horizon = m.centres().horizon();
  std::vector<BracketEvent> found;
  search.events(horizon, found);
  const bool ball_a = m.kind(a) == ShapeKind::Sphere;
  const bool ball = ball_a || m.kind(b) == ShapeKind::Sphere;
  std::size_t evaluations = 0;
  for (const BracketEvent& e : found) {
    if (!ball || !e.error.grazing) {
      events.push_back({a, b, e.enter, e.exit});
      errors.push_back(e.error);
      continue;
    }
    std::vector<BracketEvent> refined;
    const double lo = std::max(u0, e.enter - e.error.enter_error), hi = std::min(u1, e.exit + e.error.exit_error);
    evaluations += ball_a ? refine_sphere_pair(m, a, b, lo, hi, tol, max_evaluations, qa, qb, refined)
                          : refine_sphere_pair(m, b, a, lo, hi, tol, max_evaluations, qb, qa, refined);
    for (const BracketEvent& r : refined) {
      events.push_back({a, b, r.enter, r.exit});
      errors.push_back(r.error);
    }
  }
  return evaluations;
}

// Merges the events of one pair found on adjacent common pieces and image shifts into
// maximal events (a contact that continues through the seam, or across a break, is one
// event): events whose brackets meet, or leave a gap of at most `tol`, are one event
// whose enter bracket runs from the first one's start to the first certified overlap,
// and whose exit bracket from the last certified overlap to the last one's end; grazing
// when none of them has a certified overlap. A lone event is kept as it is.
void merge_events(std::vector<ContactEvent>& events, std::vector<EventError>& errors, double tol,
                  std::vector<ContactEvent>& out_events, std::vector<EventError>& out_errors) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<std::size_t> order(events.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  auto lo = [&](std::size_t i) { return events[i].enter - errors[i].enter_error; };
  auto hi = [&](std::size_t i) { return events[i].exit + errors[i].exit_error; };
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return lo(x) < lo(y) || (lo(x) == lo(y) && x < y); });
  for (std::size_t g = 0; g < order.size();) {
    std::size_t k = g + 1;
    double run_hi = hi(order[g]);
    while (k < order.size() && lo(order[k]) <= run_hi + tol) run_hi = std::max(run_hi, hi(order[k++]));
    if (k == g + 1) {
      out_events.push_back(events[order[g]]);
      out_errors.push_back(errors[order[g]]);
      g = k;
      continue;
    }
    const double run_lo = lo(order[g]);
    double first_overlap = inf, last_overlap = -inf;
    for (std::size_t j = g; j < k; ++j) {
      const std::size_t i = order[j];
      if (errors[i].grazing) continue;
      first_overlap = std::min(first_overlap, events[i].enter + errors[i].enter_error);
      last_overlap = std::max(last_overlap, events[i].exit - errors[i].exit_error);
    }
    ContactEvent ev = events[order[g]];
    EventError err;
    auto middle = [](double x0, double x1, double& at, double& half) {
      at = x0 + 0.5 * (x1 - x0);
      half = std::max(at - x0, x1 - at);
    };
    if (first_overlap < inf) {
      middle(run_lo, first_overlap, ev.enter, err.enter_error);
      middle(last_overlap, run_hi, ev.exit, err.exit_error);
    } else {
      middle(run_lo, run_hi, ev.enter, err.enter_error);
      ev.exit = ev.enter;
      err.exit_error = err.enter_error;
      err.grazing = true;
      err.undecided = true;
    }
    out_events.push_back(ev);
    out_errors.push_back(err);
    g = k;
  }
}

}  // namespace

std::size_t pair_bracket_events(const RigidMotion& m, std::uint32_t a, std::uint32_t b, double u0, double u1,
                                double tol, std::size_t max_evaluations, std::vector<ContactEvent>& events,
                                std::vector<EventError>& errors) {
  const double lipschitz = m.max_point_speed(a, u0, u1) + m.max_point_speed(b, u0, u1);
  BracketSearch search = pair_search(m, a, b, lipschitz, tol, max_evaluations);
  search.run(u0, u1);
  return search.evaluations() + search_events(m, search, a, b, u0, u1, tol, max_evaluations, nullptr, nullptr,
                                              events, errors);
}

std::size_t periodic_pair_bracket_events(const RigidMotion& m, std::uint32_t a, std::uint32_t b, double u0, double u1,
                                         double tol, std::size_t max_evaluations, std::vector<ContactEvent>& events,
                                         std::vector<EventError>& errors) {
  const Trajectories& traj = m.centres();
  const PeriodicBox& box = *traj.periodic();
  const double reach = m.enclosing_radius(a) + m.enclosing_radius(b);
  const auto pa = traj.pieces(a), pb = traj.pieces(b);
  const auto lb = traj.lows(b);
  auto first_ending_after = [u0](std::span<const Piece> ps) {
    auto it = std::lower_bound(ps.begin(), ps.end(), u0, [](const Piece& q, double x) { return q.t1 < x; });
    return static_cast<std::size_t>(it - ps.begin());
  };
  std::size_t ia = first_ending_after(pa), ib = first_ending_after(pb);
  std::vector<ContactEvent> found;
  std::vector<EventError> found_errors;
  std::size_t evaluations = 0;
  for (; ia < pa.size() && ib < pb.size();) {
    const Piece& qa = pa[ia];
    const Piece& qb = pb[ib];
    if (std::max(qa.t0, qb.t0) > u1) break;
    // The common piece, inside [u0, u1]: both centres move on one piece each, inside the
    // cell on the wrapped axes. Pieces of zero length (a centre on a face re-entering at
    // once) hold one instant that the neighbouring piece holds too.
    const double c0 = std::max({qa.t0, qb.t0, u0}), c1 = std::min({qa.t1, qb.t1, u1});
    std::array<std::array<std::int32_t, 3>, 3> shifts{};
    std::array<int, 3> count{};
    bool possible = c1 > c0;
    if (possible) {
      const Aabb ba = qa.centre_bounds(c0, c1), bb = qb.centre_bounds(c0, c1);
      for (int k = 0; k < 3 && possible; ++k) {
        count[static_cast<std::size_t>(k)] = box.contact_shifts(ba, bb, reach, k, shifts[static_cast<std::size_t>(k)]);
        possible = count[static_cast<std::size_t>(k)] > 0;
      }
    }
    if (possible) {
      const double lipschitz = m.max_point_speed(a, c0, c1) + m.max_point_speed(b, c0, c1);
      for (int x = 0; x < count[0]; ++x)
        for (int y = 0; y < count[1]; ++y)
          for (int z = 0; z < count[2]; ++z) {
            const ImageShift s{shifts[0][static_cast<std::size_t>(x)], shifts[1][static_cast<std::size_t>(y)],
                               shifts[2][static_cast<std::size_t>(z)]};
            Piece image = qb;
            PieceLow low = lb[ib];
            shift_piece(image, low, image_offset(box, s));
            BracketSearch search = pair_search(m, a, b, lipschitz, tol,
                                               max_evaluations - std::min(max_evaluations, evaluations), &qa, &image);
            search.run(c0, c1);
            evaluations += search.evaluations();
            evaluations += search_events(m, search, a, b, c0, c1, tol, max_evaluations, &qa, &image, found,
                                         found_errors);
          }
    }
    if (qa.t1 < qb.t1) {
      ++ia;
    } else if (qb.t1 < qa.t1) {
      ++ib;
    } else {
      ++ia;
      ++ib;
    }
  }
  merge_events(found, found_errors, tol, events, errors);
  return evaluations;
}

RigidTruthResult compute_rigid_truth(const RigidMotion& m, const RigidTruthOptions& options) {
  TruthOptions o;
  o.threads = options.threads;
  o.windows = options.windows;
  o.time_tolerance = options.time_tolerance;
  o.max_evaluations = options.max_evaluations;
  o.cancel = options.cancel;
  if (options.generic_spheres) o.table = &bracket_truth_table();
  Truth t = compute_truth(m, {}, o);
  RigidTruthResult out;
  out.errors = t.errors.empty() ? std::vector<EventError>(t.events.size()) : std::move(t.errors);
  out.events = std::move(t.events);
  out.stats.windows = t.stats.windows;
  out.stats.threads = t.stats.threads;
  out.stats.candidate_runs = t.stats.candidate_runs;
  out.stats.evaluations = t.stats.evaluations;
  out.stats.grazing = t.stats.grazing;
  out.stats.pairs_in_contact = t.stats.pairs_in_contact;
  return out;
}

}  // namespace ccd
