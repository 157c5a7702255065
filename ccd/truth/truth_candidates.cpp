#include <ccd/truth/truth_candidates.hpp>

#include <ccd/util/parallel_for.hpp>

#include <algorithm>
#include <cmath>

namespace ccd {
namespace {

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

// Box ids: the bodies 0..n-1, then the polygons, then the images of bodies (periodic).
struct WindowScratch {
  std::vector<Box> boxes;
  std::vector<ColumnEntry> entries;
  std::vector<std::uint32_t> big;
  std::vector<std::uint32_t> owner;  ///< images: the body of each box past the polygons
};

struct WindowKeys {
  std::vector<std::uint64_t> pairs;    ///< a << 32 | b, a < b bodies
  std::vector<std::uint64_t> statics;  ///< body << 32 | polygon
};

bool overlap(const Box& x, const Box& y) {
  return x.lo[0] <= y.hi[0] && y.lo[0] <= x.hi[0] && x.lo[1] <= y.hi[1] && y.lo[1] <= x.hi[1] &&
         x.lo[2] <= y.hi[2] && y.lo[2] <= x.hi[2];
}

Box to_box(const Aabb& a) { return {{a.lo[0], a.lo[1], a.lo[2]}, {a.hi[0], a.hi[1], a.hi[2]}}; }

// The boxes of one window: bodies, polygons, then images of bodies that meet the cell;
// mean and extent are summed over the bodies' boxes only.
void window_boxes(const Trajectories& traj, std::span<const double> grow, std::span<const Aabb> polygons, double w0,
                  double w1, WindowScratch& sc, double mean[3], double extent[3]) {
  const std::size_t n = traj.size();
  std::vector<Box>& boxes = sc.boxes;
  boxes.resize(n);
  for (int k = 0; k < 3; ++k) mean[k] = extent[k] = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Aabb c = centre_box(traj, i, w0, w1);
    Box& b = boxes[i];
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = c.lo[k] - grow[i];
      b.hi[k] = c.hi[k] + grow[i];
      mean[k] += 0.5 * (c.lo[k] + c.hi[k]);
      extent[k] += b.hi[k] - b.lo[k];
    }
  }
  for (const Aabb& p : polygons) boxes.push_back(to_box(p));
  sc.owner.clear();
  if (const PeriodicBox* pb = traj.periodic()) {
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
        sc.owner.push_back(i);
      });
    }
  }
}

// Broad phase of one window: appends the keys of every overlapping pair of boxes, sorted
// and unique. A pair is reported only in the column that holds the corner (max lo, max lo)
// of the two boxes' overlap, which both boxes cover: once, and never missed.
void window_candidates(const Trajectories& traj, std::span<const double> grow, std::span<const Aabb> polygons,
                       double w0, double w1, WindowScratch& sc, WindowKeys& keys) {
  constexpr std::int64_t kMaxCells = 64;
  const std::size_t n = traj.size();
  const std::size_t first_image = n + polygons.size();
  double mean[3], extent[3];
  window_boxes(traj, grow, polygons, w0, w1, sc, mean, extent);
  const std::vector<Box>& boxes = sc.boxes;
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
  const std::size_t pairs_start = keys.pairs.size(), statics_start = keys.statics.size();
  auto emit = [&](std::uint32_t x, std::uint32_t y) {
    if (x >= first_image) x = sc.owner[x - first_image];
    if (y >= first_image) y = sc.owner[y - first_image];
    const bool px = x >= n, py = y >= n;
    if (px && py) return;  // two polygons
    if (px || py) {
      const std::uint64_t body = px ? y : x, polygon = (px ? x : y) - n;
      keys.statics.push_back(body << 32 | polygon);
      return;
    }
    if (x == y) return;  // a body and its own image
    const std::uint64_t a = std::min(x, y), b = std::max(x, y);
    keys.pairs.push_back(a << 32 | b);
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
  for (auto* list : {&keys.pairs, &keys.statics}) {
    const std::size_t start = list == &keys.pairs ? pairs_start : statics_start;
    std::sort(list->begin() + static_cast<std::ptrdiff_t>(start), list->end());
    list->erase(std::unique(list->begin() + static_cast<std::ptrdiff_t>(start), list->end()), list->end());
  }
}

// Runs of consecutive windows per key, from the per-window key lists (emptied).
std::vector<CandidateRun> runs_of(std::vector<std::vector<std::uint64_t>>& per_window, std::size_t& entries_found) {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> entries;
  std::size_t total = 0;
  for (const auto& w : per_window) total += w.size();
  entries.reserve(total);
  for (std::size_t k = 0; k < per_window.size(); ++k) {
    for (std::uint64_t key : per_window[k]) entries.emplace_back(key, static_cast<std::uint32_t>(k));
    std::vector<std::uint64_t>().swap(per_window[k]);
  }
  entries_found = entries.size();
  std::sort(entries.begin(), entries.end());
  std::vector<CandidateRun> runs;
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
  return runs;
}

}  // namespace

std::size_t automatic_truth_windows(const Trajectories& traj, std::size_t max_windows) {
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
  return static_cast<std::size_t>(std::min<double>(w, static_cast<double>(max_windows)));
}

double truth_box_grow(const Trajectories& traj, std::size_t i) {
  double travel = 0.0;
  double coord = 0.0;
  for (const Piece& q : traj.pieces(i)) {
    const double dt = q.t1 - q.t0;
    travel += (q.v.norm() + q.a.norm() * dt) * dt + 0.5 * q.a.norm() * dt * dt;
    coord = std::max(coord, q.p.cwiseAbs().maxCoeff());
  }
  coord += travel;
  const double r = traj.radius(i);
  return r + std::max(1e-6 * (coord + 4.0 * travel + 2.0 * r), 1e-9 * (1.0 + 2.0 * (coord + r)));
}

Aabb truth_window_box(const Trajectories& traj, std::size_t body, double grow, double w0, double w1) {
  Aabb c = centre_box(traj, body, w0, w1);
  c.lo.array() -= grow;
  c.hi.array() += grow;
  return c;
}

TruthCandidates find_truth_candidates(const Trajectories& traj, std::span<const double> grow,
                                      std::span<const Aabb> polygons, std::size_t windows, unsigned threads) {
  TruthCandidates out;
  out.windows = std::max<std::size_t>(windows, 1);
  out.horizon = traj.horizon();
  if (traj.size() == 0 || (traj.size() < 2 && polygons.empty())) return out;
  const unsigned workers = resolve_threads(threads);
  std::vector<WindowKeys> per_window(out.windows);
  std::vector<WindowScratch> scratch(workers);
  parallel_for(out.windows, workers, [&](std::size_t k, unsigned t) {
    window_candidates(traj, grow, polygons, out.window_start(k), out.window_start(k + 1), scratch[t], per_window[k]);
  });
  scratch.clear();
  std::vector<std::vector<std::uint64_t>> pairs(out.windows), statics(out.windows);
  for (std::size_t k = 0; k < out.windows; ++k) {
    pairs[k] = std::move(per_window[k].pairs);
    statics[k] = std::move(per_window[k].statics);
  }
  out.pairs = runs_of(pairs, out.pair_windows);
  out.statics = runs_of(statics, out.static_windows);
  return out;
}

}  // namespace ccd
