#include <ccd/truth/rigid_truth.hpp>

#include <ccd/queries/convex_distance.hpp>
#include <ccd/truth/bracket_search.hpp>
#include <ccd/truth/pair_contact.hpp>
#include <ccd/util/parallel_for.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <thread>
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

std::size_t auto_windows(const RigidMotion& m) {
  const Trajectories& traj = m.centres();
  if (traj.size() == 0) return 1;
  double path = 0.0, diameter = 0.0;
  for (std::size_t i = 0; i < traj.size(); ++i) {
    const Aabb box = traj.swept_bounds(i, 0.0, traj.horizon());
    path += (box.hi - box.lo).maxCoeff() - 2.0 * traj.radius(i);
    diameter += 2.0 * traj.radius(i);
  }
  const double w = std::ceil(0.5 * path / std::max(diameter, 1e-300));
  return static_cast<std::size_t>(std::clamp(w, 1.0, static_cast<double>(TruthOptions::max_auto_windows)));
}

struct Candidate {
  std::uint32_t a, b, window;
};

}  // namespace

namespace {

// The events of one finished search (ccd/truth/bracket_search.hpp), appended to events
// and errors as events of the pair (a, b).
void search_events(BracketSearch& search, std::uint32_t a, std::uint32_t b, double horizon,
                   std::vector<ContactEvent>& events, std::vector<EventError>& errors) {
  std::vector<BracketEvent> found;
  search.events(horizon, found);
  for (const BracketEvent& e : found) {
    events.push_back({a, b, e.enter, e.exit});
    errors.push_back(e.error);
  }
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
  const double horizon = m.centres().horizon();
  const double lipschitz = m.max_point_speed(a, u0, u1) + m.max_point_speed(b, u0, u1);
  BracketSearch search = pair_search(m, a, b, lipschitz, tol, max_evaluations);
  search.run(u0, u1);
  search_events(search, a, b, horizon, events, errors);
  return search.evaluations();
}

std::size_t periodic_pair_bracket_events(const RigidMotion& m, std::uint32_t a, std::uint32_t b, double u0, double u1,
                                         double tol, std::size_t max_evaluations, std::vector<ContactEvent>& events,
                                         std::vector<EventError>& errors) {
  const Trajectories& traj = m.centres();
  const PeriodicBox& box = *traj.periodic();
  const double horizon = traj.horizon();
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
            search_events(search, a, b, horizon, found, found_errors);
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

std::size_t rigid_truth_windows(const RigidMotion& m, const RigidTruthOptions& options) {
  return options.windows ? options.windows : auto_windows(m);
}

RigidTruthResult compute_rigid_truth(const RigidMotion& m, const RigidTruthOptions& options) {
  RigidTruthResult out;
  const Trajectories& traj = m.centres();
  const double T = traj.horizon();
  const double tol = options.time_tolerance > 0.0 ? options.time_tolerance : std::ldexp(T, -30);
  const std::size_t W = rigid_truth_windows(m, options);
  const unsigned threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  out.stats.windows = W;
  out.stats.threads = threads;
  const auto n = static_cast<std::uint32_t>(traj.size());
  auto window_start = [&](std::size_t w) { return w == W ? T : T * static_cast<double>(w) / static_cast<double>(W); };

  // 1. Candidate (pair, window) entries: sort and sweep of swept boxes along x per window.
  std::vector<std::vector<Candidate>> per_window(W);
  parallel_for(W, threads, [&](std::size_t w, unsigned) {
    const double u0 = window_start(w), u1 = window_start(w + 1);
    std::vector<Aabb> boxes(n);
    std::vector<std::uint32_t> owner(n);
    for (std::uint32_t i = 0; i < n; ++i) {
      boxes[i] = traj.swept_bounds(i, u0, u1);
      // Rounding margin: the swept box is computed in doubles.
      const double margin = 1e-9 * (1.0 + boxes[i].lo.cwiseAbs().maxCoeff() + boxes[i].hi.cwiseAbs().maxCoeff());
      boxes[i].lo.array() -= margin;
      boxes[i].hi.array() += margin;
      owner[i] = i;
    }
    // A box that wraps around: every image of a box that meets the cell joins the sweep,
    // owned by its body (ccd/scene/periodic.hpp, for_each_image); two bodies that can touch
    // through some image shift have two such images that overlap.
    if (const PeriodicBox* pb = traj.periodic())
      for (std::uint32_t i = 0; i < n; ++i)
        pb->for_each_image(Aabb(boxes[i]), [&](const ImageShift& s) {
          if (s == ImageShift{0, 0, 0}) return;
          const Vec3 o = pb->offset(s);
          const Aabb image{boxes[i].lo + o, boxes[i].hi + o};
          boxes.push_back(image);
          owner.push_back(i);
        });
    std::vector<std::uint32_t> order(boxes.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) { return boxes[x].lo.x() < boxes[y].lo.x(); });
    auto& cands = per_window[w];
    for (std::size_t p = 0; p < order.size(); ++p) {
      const Aabb& bp = boxes[order[p]];
      for (std::size_t q = p + 1; q < order.size() && boxes[order[q]].lo.x() <= bp.hi.x(); ++q) {
        if (!bp.overlaps(boxes[order[q]])) continue;
        const std::uint32_t x = owner[order[p]], y = owner[order[q]];
        if (x == y) continue;
        cands.push_back({std::min(x, y), std::max(x, y), static_cast<std::uint32_t>(w)});
      }
    }
    if (traj.periodic()) {  // a pair may overlap through several images
      std::sort(cands.begin(), cands.end(), [](const Candidate& c, const Candidate& d) { return std::tie(c.a, c.b) < std::tie(d.a, d.b); });
      cands.erase(std::unique(cands.begin(), cands.end(), [](const Candidate& c, const Candidate& d) { return c.a == d.a && c.b == d.b; }),
                  cands.end());
    }
  });
  std::vector<Candidate> all;
  for (auto& c : per_window) all.insert(all.end(), c.begin(), c.end());
  std::sort(all.begin(), all.end(), [](const Candidate& x, const Candidate& y) {
    return std::tie(x.a, x.b, x.window) < std::tie(y.a, y.b, y.window);
  });
  // 2. Runs of consecutive windows per pair.
  struct Run {
    std::uint32_t a, b;
    double u0, u1;
  };
  std::vector<Run> runs;
  for (std::size_t i = 0; i < all.size();) {
    std::size_t k = i + 1;
    while (k < all.size() && all[k].a == all[i].a && all[k].b == all[i].b && all[k].window == all[k - 1].window + 1) ++k;
    runs.push_back({all[i].a, all[i].b, window_start(all[i].window), window_start(all[k - 1].window + 1)});
    i = k;
  }
  out.stats.candidate_runs = runs.size();
  // 3. Solve each run.
  std::vector<std::vector<ContactEvent>> ev(runs.size());
  std::vector<std::vector<EventError>> er(runs.size());
  std::vector<std::size_t> evals(runs.size(), 0);
  parallel_for(runs.size(), threads, [&](std::size_t r, unsigned) {
    if (options.cancel && options.cancel->load(std::memory_order_relaxed)) return;  // cancelled: skip the rest
    const Run& run = runs[r];
    if (!options.generic_spheres && m.kind(run.a) == ShapeKind::Sphere && m.kind(run.b) == ShapeKind::Sphere) {
      std::vector<ContactInterval> iv;
      pair_contact_intervals(traj, run.a, run.b, run.u0, run.u1, iv);
      for (const ContactInterval& x : iv) {
        ev[r].push_back({run.a, run.b, x.enter, x.exit});
        er[r].push_back({});
      }
      return;
    }
    evals[r] = traj.periodic()
                   ? periodic_pair_bracket_events(m, run.a, run.b, run.u0, run.u1, tol, options.max_evaluations, ev[r], er[r])
                   : pair_bracket_events(m, run.a, run.b, run.u0, run.u1, tol, options.max_evaluations, ev[r], er[r]);
  });
  for (std::size_t r = 0; r < runs.size(); ++r) {
    out.stats.evaluations += evals[r];
    for (std::size_t k = 0; k < ev[r].size(); ++k) {
      out.events.push_back(ev[r][k]);
      out.errors.push_back(er[r][k]);
    }
  }
  // 4. Sort by (enter, a, b), errors alongside.
  std::vector<std::size_t> order(out.events.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t x, std::size_t y) { return event_order(out.events[x], out.events[y]); });
  std::vector<ContactEvent> events;
  std::vector<EventError> errors;
  for (std::size_t i : order) {
    events.push_back(out.events[i]);
    errors.push_back(out.errors[i]);
    out.stats.grazing += out.errors[i].grazing;
  }
  out.events = std::move(events);
  out.errors = std::move(errors);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (const ContactEvent& e : out.events) pairs.push_back({e.a, e.b});
  std::sort(pairs.begin(), pairs.end());
  out.stats.pairs_in_contact = static_cast<std::size_t>(std::unique(pairs.begin(), pairs.end()) - pairs.begin());
  return out;
}

}  // namespace ccd
