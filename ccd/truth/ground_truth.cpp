#include <ccd/truth/ground_truth.hpp>

#include <ccd/util/parallel_for.hpp>

#include <ccd/truth/pair_contact.hpp>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <thread>
#include <tuple>

namespace ccd {
namespace {

// Margin added to every box on top of the radius. The narrow phase reports contact when
// the squared distance exceeds R^2 by at most its rounding band
// tol = 16 eps (M + R)(M + R + P) (ccd/queries/sphere_sphere_contact.hpp), i.e. a
// distance up to sqrt(tol) <= 6e-8 (M + R + P) beyond R, and positions are evaluated
// from different expansion points (rounding ~ eps P). M, R and P are bounded by the two
// bodies' radii, largest coordinates and travel bounds, so 1e-6 times their sum per body
// is a generous conservative margin (boxes a millionth larger cost nothing measurable).
double body_margin(const Trajectories& traj, std::size_t i) {
  double travel = 0.0;
  double coord = 0.0;
  for (const Piece& q : traj.pieces(i)) {
    const double dt = q.t1 - q.t0;
    travel += (q.v.norm() + q.a.norm() * dt) * dt + 0.5 * q.a.norm() * dt * dt;
    coord = std::max(coord, q.p.cwiseAbs().maxCoeff());
  }
  coord += travel;
  return 1e-6 * (coord + 4.0 * travel + 2.0 * traj.radius(i));
}

// Box of the centre's path over [w0, w1] (pieces found by binary search).
Aabb centre_box(const Trajectories& traj, std::size_t i, double w0, double w1) {
  const auto ps = traj.pieces(i);
  auto it = std::lower_bound(ps.begin(), ps.end(), w0, [](const Piece& q, double x) { return q.t1 < x; });
  if (it == ps.end()) --it;
  Aabb box = it->centre_bounds(std::max(w0, it->t0), std::min(w1, it->t1));
  for (++it; it != ps.end() && it->t0 <= w1; ++it) box.merge(it->centre_bounds(std::max(w0, it->t0), std::min(w1, it->t1)));
  return box;
}

struct Box {
  double lo[3];
  double hi[3];
};

// One box in one grid column, ordered by (column, lo on the sweep axis, id).
struct ColumnEntry {
  std::uint64_t column;
  double lo;
  std::uint32_t id;
  bool operator<(const ColumnEntry& o) const {
    return column < o.column || (column == o.column && (lo < o.lo || (lo == o.lo && id < o.id)));
  }
};

struct WindowScratch {
  std::vector<Box> boxes;
  std::vector<ColumnEntry> entries;
  std::vector<std::uint32_t> big;
  std::vector<std::uint32_t> owner;  ///< periodic scenes: the body of each box (images after the bodies)
};

bool overlap(const Box& x, const Box& y) {
  return x.lo[0] <= y.hi[0] && y.lo[0] <= x.hi[0] && x.lo[1] <= y.hi[1] && y.lo[1] <= x.hi[1] &&
         x.lo[2] <= y.hi[2] && y.lo[2] <= x.hi[2];
}

// Broad phase of one window: appends keys (a << 32 | b), a < b, sorted and unique.
// Boxes go into the columns of a uniform grid on the two axes of largest spread (cell
// size twice the mean box extent there) and are swept along the third axis within each
// column. A pair is reported only in the column that holds the corner (max lo, max lo) of
// the two boxes' overlap, which both boxes cover: once, and never missed. Boxes covering
// more than kMaxCells columns are checked against every box instead.
void window_candidates(const Trajectories& traj, const std::vector<double>& margin, double w0, double w1,
                       WindowScratch& sc, std::vector<std::uint64_t>& keys) {
  constexpr std::int64_t kMaxCells = 64;
  const std::size_t n = traj.size();
  std::vector<Box>& boxes = sc.boxes;
  boxes.resize(n);
  double mean[3] = {0, 0, 0}, extent[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const Aabb c = centre_box(traj, i, w0, w1);
    const double grow = traj.radius(i) + margin[i];
    Box& b = boxes[i];
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = c.lo[k] - grow;
      b.hi[k] = c.hi[k] + grow;
      mean[k] += 0.5 * (c.lo[k] + c.hi[k]);
      extent[k] += b.hi[k] - b.lo[k];
    }
  }
  // Periodic scenes: every image of a box that meets the cell joins the grid as a box of
  // its own (ccd/scene/periodic.hpp, for_each_image), owned by its body.
  std::vector<std::uint32_t>& owner = sc.owner;
  owner.clear();
  if (const PeriodicBox* pb = traj.periodic()) {
    for (std::uint32_t i = 0; i < n; ++i) owner.push_back(i);
    for (std::uint32_t i = 0; i < n; ++i) {
      const Box b = boxes[i];
      const Aabb box{{b.lo[0], b.lo[1], b.lo[2]}, {b.hi[0], b.hi[1], b.hi[2]}};
      pb->for_each_image(box, [&](const ImageShift& s) {
        if (s == ImageShift{0, 0, 0}) return;
        const Vec3 o = pb->offset(s);
        Box c = b;
        for (int k = 0; k < 3; ++k) {
          c.lo[k] += o[k];
          c.hi[k] += o[k];
        }
        boxes.push_back(c);
        owner.push_back(i);
      });
    }
  }
  const std::size_t count = boxes.size();
  // Spread of the box centres per axis (variance about the mean: no cancellation).
  double var[3] = {0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    mean[k] /= static_cast<double>(n);
    extent[k] /= static_cast<double>(n);
    for (const Box& b : boxes) {
      const double d = 0.5 * (b.lo[k] + b.hi[k]) - mean[k];
      var[k] += d * d;
    }
  }
  int sweep = 0;
  for (int k = 1; k < 3; ++k)
    if (var[k] < var[sweep]) sweep = k;
  const int gy = (sweep + 1) % 3, gz = (sweep + 2) % 3;
  double origin[3] = {0, 0, 0}, top[3] = {0, 0, 0};
  for (int k : {gy, gz}) {
    origin[k] = boxes[0].lo[k];
    top[k] = boxes[0].hi[k];
    for (const Box& b : boxes) {
      origin[k] = std::min(origin[k], b.lo[k]);
      top[k] = std::max(top[k], b.hi[k]);
    }
  }
  // Cell size: twice the mean extent, but at most 2^20 cells per axis.
  double h = 2.0 * std::max(extent[gy], extent[gz]);
  h = std::max({h, (top[gy] - origin[gy]) / 1048576.0, (top[gz] - origin[gz]) / 1048576.0});
  if (!(h > 0.0)) h = 1.0;
  auto cell = [&](double x, int k) { return static_cast<std::int64_t>(std::floor((x - origin[k]) / h)); };
  constexpr std::uint64_t kStride = std::uint64_t{1} << 21;
  sc.entries.clear();
  sc.big.clear();
  for (std::size_t i = 0; i < count; ++i) {
    const Box& b = boxes[i];
    const std::int64_t y0 = cell(b.lo[gy], gy), y1 = cell(b.hi[gy], gy);
    const std::int64_t z0 = cell(b.lo[gz], gz), z1 = cell(b.hi[gz], gz);
    if ((y1 - y0 + 1) * (z1 - z0 + 1) > kMaxCells) {
      sc.big.push_back(static_cast<std::uint32_t>(i));
      continue;
    }
    for (std::int64_t y = y0; y <= y1; ++y)
      for (std::int64_t z = z0; z <= z1; ++z)
        sc.entries.push_back({static_cast<std::uint64_t>(y) * kStride + static_cast<std::uint64_t>(z), b.lo[sweep],
                              static_cast<std::uint32_t>(i)});
  }
  std::sort(sc.entries.begin(), sc.entries.end());
  const std::size_t start = keys.size();
  auto emit = [&keys, &owner](std::uint32_t x, std::uint32_t y) {
    if (!owner.empty()) {  // images: their bodies, never a body with itself
      x = owner[x];
      y = owner[y];
      if (x == y) return;
    }
    const std::uint64_t a = std::min(x, y), b = std::max(x, y);
    keys.push_back(a << 32 | b);
  };
  const auto& e = sc.entries;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const Box& x = boxes[e[i].id];
    for (std::size_t j = i + 1; j < e.size() && e[j].column == e[i].column && e[j].lo <= x.hi[sweep]; ++j) {
      const Box& y = boxes[e[j].id];
      if (!overlap(x, y)) continue;
      const std::uint64_t owner = static_cast<std::uint64_t>(cell(std::max(x.lo[gy], y.lo[gy]), gy)) * kStride +
                                  static_cast<std::uint64_t>(cell(std::max(x.lo[gz], y.lo[gz]), gz));
      if (owner == e[i].column) emit(e[i].id, e[j].id);
    }
  }
  // Big boxes against everything (each pair once: a big box meets a smaller index big
  // box only from that one's side).
  for (std::size_t k = 0; k < sc.big.size(); ++k) {
    const std::uint32_t g = sc.big[k];
    for (std::size_t i = 0; i < count; ++i) {
      const bool other_big = std::binary_search(sc.big.begin(), sc.big.end(), static_cast<std::uint32_t>(i));
      if (i == g || (other_big && i < g)) continue;
      if (overlap(boxes[g], boxes[i])) emit(g, static_cast<std::uint32_t>(i));
    }
  }
  std::sort(keys.begin() + static_cast<std::ptrdiff_t>(start), keys.end());
  if (!owner.empty()) keys.erase(std::unique(keys.begin() + static_cast<std::ptrdiff_t>(start), keys.end()), keys.end());
}

std::size_t automatic_windows(const Trajectories& traj) {
  const std::size_t n = traj.size();
  if (n == 0) return 1;
  double path = 0.0, diameter = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Aabb c = centre_box(traj, i, 0.0, traj.horizon());
    path += (c.hi - c.lo).maxCoeff();
    diameter += 2.0 * traj.radius(i);
  }
  const double w = std::ceil(0.5 * path / diameter);
  if (!(w >= 1.0)) return 1;
  return static_cast<std::size_t>(std::min<double>(w, TruthOptions::max_auto_windows));
}

struct Run {
  std::uint32_t a, b;
  std::uint32_t w_first, w_last;
};

}  // namespace

bool event_order(const ContactEvent& x, const ContactEvent& y) {
  return std::tie(x.enter, x.a, x.b) < std::tie(y.enter, y.a, y.b);
}

TruthResult compute_truth_detailed(const Trajectories& traj, const TruthOptions& options) {
  TruthResult result;
  const std::size_t n = traj.size();
  const double horizon = traj.horizon();
  const unsigned threads = resolve_threads(options.threads);
  const std::size_t windows = options.windows != 0 ? options.windows : automatic_windows(traj);
  result.stats.windows = windows;
  result.stats.threads = threads;
  if (n < 2) return result;

  std::vector<double> margin(n);
  for (std::size_t i = 0; i < n; ++i) margin[i] = body_margin(traj, i);
  auto window_start = [&](std::size_t k) {
    return k == windows ? horizon : horizon * (static_cast<double>(k) / static_cast<double>(windows));
  };

  // 1. Candidates per window.
  std::vector<std::vector<std::uint64_t>> per_window(windows);
  std::vector<WindowScratch> scratch(threads);
  parallel_for(windows, threads, [&](std::size_t k, unsigned t) {
    window_candidates(traj, margin, window_start(k), window_start(k + 1), scratch[t], per_window[k]);
  });
  scratch.clear();

  // 2. Runs of consecutive windows per pair.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> entries;
  std::size_t total = 0;
  for (const auto& w : per_window) total += w.size();
  entries.reserve(total);
  for (std::size_t k = 0; k < windows; ++k) {
    for (std::uint64_t key : per_window[k]) entries.emplace_back(key, static_cast<std::uint32_t>(k));
    std::vector<std::uint64_t>().swap(per_window[k]);
  }
  result.stats.candidate_pair_windows = entries.size();
  std::sort(entries.begin(), entries.end());
  std::vector<Run> runs;
  for (std::size_t i = 0; i < entries.size();) {
    std::size_t j = i;
    while (j + 1 < entries.size() && entries[j + 1].first == entries[i].first &&
           entries[j + 1].second == entries[j].second + 1)
      ++j;
    const std::uint64_t key = entries[i].first;
    runs.push_back({static_cast<std::uint32_t>(key >> 32), static_cast<std::uint32_t>(key & 0xffffffffu),
                    entries[i].second, entries[j].second});
    i = j + 1;
  }
  std::vector<std::pair<std::uint64_t, std::uint32_t>>().swap(entries);
  result.stats.candidate_runs = runs.size();

  // 3. Exact intervals per run, in chunks.
  const std::size_t chunk = 4096;
  const std::size_t chunks = (runs.size() + chunk - 1) / chunk;
  std::vector<std::vector<ContactEvent>> found(chunks);
  std::mutex progress_mutex;
  std::size_t solved = 0;
  parallel_for(chunks, threads, [&](std::size_t c, unsigned) {
    std::vector<ContactInterval> iv;
    const std::size_t end = std::min(runs.size(), (c + 1) * chunk);
    for (std::size_t r = c * chunk; r < end; ++r) {
      const Run& run = runs[r];
      iv.clear();
      pair_contact_intervals(traj, run.a, run.b, window_start(run.w_first), window_start(run.w_last + 1), iv);
      for (const ContactInterval& x : iv) found[c].push_back({run.a, run.b, x.enter, x.exit});
    }
    if (options.progress) {
      const std::lock_guard<std::mutex> lock(progress_mutex);
      solved += end - c * chunk;
      options.progress(solved, runs.size());
    }
  });
  for (auto& f : found) result.events.insert(result.events.end(), f.begin(), f.end());
  std::sort(result.events.begin(), result.events.end(), event_order);
  {
    std::vector<std::uint64_t> pairs;
    pairs.reserve(result.events.size());
    for (const ContactEvent& e : result.events) pairs.push_back(std::uint64_t{e.a} << 32 | e.b);
    std::sort(pairs.begin(), pairs.end());
    result.stats.pairs_in_contact = static_cast<std::size_t>(std::unique(pairs.begin(), pairs.end()) - pairs.begin());
  }
  return result;
}

std::vector<ContactEvent> compute_truth(const Trajectories& traj, const TruthOptions& options) {
  return compute_truth_detailed(traj, options).events;
}

std::vector<ContactEvent> compute_truth_all_pairs(const Trajectories& traj) {
  std::vector<ContactEvent> events;
  std::vector<ContactInterval> iv;
  const auto n = static_cast<std::uint32_t>(traj.size());
  for (std::uint32_t a = 0; a < n; ++a) {
    for (std::uint32_t b = a + 1; b < n; ++b) {
      iv.clear();
      pair_contact_intervals(traj, a, b, 0.0, traj.horizon(), iv);
      for (const ContactInterval& x : iv) events.push_back({a, b, x.enter, x.exit});
    }
  }
  std::sort(events.begin(), events.end(), event_order);
  return events;
}

}  // namespace ccd
