#include <ccd/broad_phase/cell_grid.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace ccd::detail {

namespace {

// LSD radix sort of v[0, n) by bits [32, 32 + bits) (the cell key above the body id), with
// digits of at most 11 bits (histograms stay in L1). Stable, so bodies keep index order
// within a cell. Skipped when already sorted (coherent frames often are). With t > 1
// threads each pass splits v into t contiguous chunks: every thread counts the digits of
// its chunk, the offsets are laid out by (digit, chunk), and every thread scatters its
// chunk; so the result is the serial one, element for element.
void radix_sort_by_key(std::uint64_t* v, std::size_t n, int bits, std::vector<std::uint64_t>& tmp,
                       unsigned t = 1) {
  if (n < 2 || bits <= 0) return;
  bool sorted = true;
  for (std::size_t i = 1; i < n && sorted; ++i) sorted = (v[i - 1] >> 32) <= (v[i] >> 32);
  if (sorted) return;
  if (n <= 64) {
    std::stable_sort(v, v + n, [](std::uint64_t a, std::uint64_t b) { return (a >> 32) < (b >> 32); });
    return;
  }
  if (tmp.size() < n) tmp.resize(n);
  const int passes = (bits + 10) / 11;
  const int width = (bits + passes - 1) / passes;
  const std::uint64_t mask = (std::uint64_t{1} << width) - 1;
  t = std::max(1u, t);
  std::vector<std::array<std::uint32_t, 2048>> count(t);  // 2^11 digits at most, per chunk
  std::uint64_t* src = v;
  std::uint64_t* dst = tmp.data();
  for (int p = 0; p < passes; ++p) {
    const int shift = 32 + p * width;
    parallel_for(t, t, [&](std::size_t i, unsigned) {
      std::array<std::uint32_t, 2048>& c = count[i];
      std::fill(c.begin(), c.begin() + (mask + 1), 0u);
      for (std::size_t k = n * i / t, e = n * (i + 1) / t; k < e; ++k) ++c[(src[k] >> shift) & mask];
    });
    std::uint32_t sum = 0;
    for (std::uint64_t d = 0; d <= mask; ++d)
      for (unsigned i = 0; i < t; ++i) {
        const std::uint32_t k = count[i][d];
        count[i][d] = sum;
        sum += k;
      }
    parallel_for(t, t, [&](std::size_t i, unsigned) {
      std::array<std::uint32_t, 2048>& c = count[i];
      for (std::size_t k = n * i / t, e = n * (i + 1) / t; k < e; ++k) dst[c[(src[k] >> shift) & mask]++] = src[k];
    });
    std::swap(src, dst);
  }
  if (src != v)  // an odd number of passes: copy back, on the same chunks
    parallel_for(t, t, [&](std::size_t i, unsigned) { std::copy(src + n * i / t, src + n * (i + 1) / t, v + n * i / t); });
}

inline bool overlap(const CellGrid::Item& a, const CellGrid::Item& b) {
  return (a.lo[0] <= b.hi[0]) & (b.lo[0] <= a.hi[0]) & (a.lo[1] <= b.hi[1]) & (b.lo[1] <= a.hi[1]) &
         (a.lo[2] <= b.hi[2]) & (b.lo[2] <= a.hi[2]);
}

inline void emit(const std::uint32_t* ids, std::uint32_t i, std::uint32_t j, std::vector<BodyPair>& out) {
  const std::uint32_t a = ids[i], b = ids[j];
  out.push_back(a < b ? BodyPair{a, b} : BodyPair{b, a});
}

}  // namespace

unsigned threads_for(std::size_t items, unsigned threads) {
  const std::size_t most = items / kMinBodiesPerThread;
  return static_cast<unsigned>(std::max<std::size_t>(1, std::min<std::size_t>(threads, most)));
}

std::uint64_t CellShape::cells() const {
  const double c = static_cast<double>(nx) * static_cast<double>(ny) * static_cast<double>(nz);
  return c > 0x1p40 ? (std::uint64_t{1} << 40) : nx * ny * nz;
}

CellShape cell_shape(double cell, const std::array<double, 3>& span) {
  const double inv = 1.0 / cell;
  auto count = [&](double s) {
    const double c = std::floor(s * inv);
    return c > 0x1p40 ? (std::uint64_t{1} << 40) : static_cast<std::uint64_t>(c);
  };
  CellShape sh;
  sh.nx = std::max<std::uint64_t>(count(span[0]) + 2, 3);
  sh.ny = std::max<std::uint64_t>(count(span[1]) + 2, 3);
  sh.nz = count(span[2]) + 1;
  return sh;
}

double admissible_cell(double wanted, const std::array<double, 3>& span) {
  const double widest = std::max({span[0], span[1], span[2]});
  double s = std::max(wanted, widest / kMaxCellsPerAxis);
  if (!(s > 0)) return 1.0;
  s = std::max(s, 4 * std::numeric_limits<double>::min());
  while (cell_shape(s, span).cells() > kMaxCellsPerLevel) s *= 2;
  return s;
}

std::uint64_t CellGrid::key_of(const Level& lv, const double lo[3]) const {
  const auto ix = static_cast<std::uint64_t>((lo[0] - origin_[0]) * lv.inv);
  const auto iy = static_cast<std::uint64_t>((lo[1] - origin_[1]) * lv.inv);
  const auto iz = static_cast<std::uint64_t>((lo[2] - origin_[2]) * lv.inv);
  // lo >= origin, so the products are >= 0 and truncation is floor.
  return ix + lv.shape.nx * (iy + lv.shape.ny * iz);
}

void CellGrid::build(std::span<const Aabb> boxes, std::span<const std::uint8_t> level,
                     std::span<const double> cell, const std::array<double, 3>& origin,
                     const std::array<double, 3>& span) {
  const std::size_t n = boxes.size();
  origin_ = origin;
  levels_.resize(cell.size());
  for (std::size_t l = 0; l < cell.size(); ++l) {
    Level& lv = levels_[l];
    lv.inv = 1.0 / cell[l];
    lv.shape = cell_shape(cell[l], span);
    lv.key_bits = std::bit_width(lv.shape.cells() - 1);
    lv.begin = lv.end = 0;
  }
  // Bucket bodies by level (counting sort), then key them.
  if (level.empty()) {
    levels_[0].end = static_cast<std::uint32_t>(n);
  } else {
    for (std::size_t i = 0; i < n; ++i) ++levels_[level[i]].end;
    std::uint32_t sum = 0;
    for (Level& lv : levels_) {
      lv.begin = sum;
      sum += lv.end;
      lv.end = lv.begin;  // used as the fill cursor below
    }
  }
  packed_.resize(n);
  if (level.empty()) {
    const unsigned t = threads_for(n, threads_);
    parallel_for(t, t, [&](std::size_t i, unsigned) {
      const std::size_t b = n * i / t, e = n * (i + 1) / t;
      for (std::size_t k = b; k < e; ++k) {
        const Aabb& box = boxes[k];
        const double lo[3] = {box.lo.x(), box.lo.y(), box.lo.z()};
        packed_[k] = (key_of(levels_[0], lo) << 32) | k;
      }
    });
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      const Aabb& b = boxes[i];
      const double lo[3] = {b.lo.x(), b.lo.y(), b.lo.z()};
      Level& lv = levels_[level[i]];
      packed_[lv.end++] = (key_of(lv, lo) << 32) | i;
    }
  }
  items_.resize(n);
  ids_.resize(n);
  cell_key_.clear();
  cell_start_.clear();
  for (Level& lv : levels_) {
    radix_sort_by_key(packed_.data() + lv.begin, lv.end - lv.begin, lv.key_bits, tmp_,
                      threads_for(lv.end - lv.begin, threads_));
    lv.cell_begin = static_cast<std::uint32_t>(cell_key_.size());
    const std::uint32_t m = lv.end - lv.begin;
    const unsigned t = threads_for(m, threads_);
    if (thread_.size() < t) thread_.resize(t);
    parallel_for(t, t, [&](std::size_t i, unsigned) {
      std::vector<std::uint32_t>& keys = i == 0 ? cell_key_ : thread_[i].cell_key;
      std::vector<std::uint32_t>& starts = i == 0 ? cell_start_ : thread_[i].cell_start;
      if (i > 0) keys.clear(), starts.clear();
      const std::uint32_t b = lv.begin + static_cast<std::uint32_t>(std::uint64_t{m} * i / t);
      const std::uint32_t e = lv.begin + static_cast<std::uint32_t>(std::uint64_t{m} * (i + 1) / t);
      for (std::uint32_t k = b; k < e; ++k) {
        // The gather reads boxes in random order: prefetch a few bodies ahead.
        // A 48-byte box may straddle two cache lines: prefetch its first and last byte.
        if (k + 16 < lv.end) {
          const char* ahead = reinterpret_cast<const char*>(&boxes[static_cast<std::uint32_t>(packed_[k + 16])]);
          __builtin_prefetch(ahead);
          __builtin_prefetch(ahead + sizeof(Aabb) - 1);
        }
        const std::uint64_t p = packed_[k];
        const auto id = static_cast<std::uint32_t>(p);
        const auto key = static_cast<std::uint32_t>(p >> 32);
        const Aabb& box = boxes[id];
        items_[k] = {{box.lo.x(), box.lo.y(), box.lo.z()}, {box.hi.x(), box.hi.y(), box.hi.z()}};
        ids_[k] = id;
        if (k == lv.begin || key != static_cast<std::uint32_t>(packed_[k - 1] >> 32)) {
          keys.push_back(key);
          starts.push_back(k);
        }
      }
    });
    for (unsigned i = 1; i < t; ++i) {
      cell_key_.insert(cell_key_.end(), thread_[i].cell_key.begin(), thread_[i].cell_key.end());
      cell_start_.insert(cell_start_.end(), thread_[i].cell_start.begin(), thread_[i].cell_start.end());
    }
    lv.cell_end = static_cast<std::uint32_t>(cell_key_.size());
  }
  cell_start_.push_back(static_cast<std::uint32_t>(n));
}

std::uint64_t CellGrid::same_level(const Level& lv, std::vector<BodyPair>& out) {
  const std::uint32_t m = lv.end - lv.begin;
  build_occupancy(lv);
  const unsigned t = threads_for(m, threads_);
  if (t == 1) return same_level_cells(lv, lv.cell_begin, lv.cell_end, out);
  // Cell ranges of about m / t bodies each; thread 0 appends to `out` directly, the others
  // to their buffers, appended afterwards in range order (the serial order).
  std::vector<std::uint32_t> bound(t + 1);
  bound[0] = lv.cell_begin;
  bound[t] = lv.cell_end;
  for (unsigned i = 1; i < t; ++i) {
    const std::uint32_t first = lv.begin + static_cast<std::uint32_t>(std::uint64_t{m} * i / t);
    bound[i] = static_cast<std::uint32_t>(
        std::lower_bound(cell_start_.begin() + lv.cell_begin, cell_start_.begin() + lv.cell_end, first) -
        cell_start_.begin());
  }
  if (thread_.size() < t) thread_.resize(t);
  std::vector<std::uint64_t> tests(t, 0);
  parallel_for(t, t, [&](std::size_t i, unsigned) {
    std::vector<BodyPair>& o = i == 0 ? out : thread_[i].pairs;
    if (i > 0) o.clear();
    tests[i] = same_level_cells(lv, bound[i], bound[i + 1], o);
  });
  std::uint64_t sum = tests[0];
  for (unsigned i = 1; i < t; ++i) {
    out.insert(out.end(), thread_[i].pairs.begin(), thread_[i].pairs.end());
    sum += tests[i];
  }
  return sum;
}

void CellGrid::build_occupancy(const Level& lv) {
  bitmap_ = false;
  const std::uint64_t cells = lv.shape.cells();
  const std::uint64_t m = lv.end - lv.begin;
  if (cells > kMaxOccupancyCells || cells > 64 * m + 4096) return;  // too sparse: cursors
  bitmap_ = true;
  // Padding: stencil keys reach k + nx * ny + nx + 1 beyond the last real key; one more word
  // for the two-word read.
  const std::uint64_t words = (cells + lv.shape.nx * lv.shape.ny + lv.shape.nx + 2) / 64 + 2;
  if (occupied_.size() < words) occupied_.resize(words), rank_.resize(words);  // every word is written below
  // Thread i owns the words [word[i], word[i + 1]) and the cells [cell[i], cell[i + 1]) whose
  // keys fall in them: the word of the key at about i / t of the level's cells. Its ranks
  // start at its first cell's index, so no thread waits for another, and no word is
  // written by two threads.
  const std::uint32_t cb = lv.cell_begin, ce = lv.cell_end;
  const std::uint32_t* key = cell_key_.data();
  const unsigned t = threads_for(m, threads_);
  std::vector<std::uint64_t> word(t + 1);
  std::vector<std::uint32_t> cell(t + 1);
  word[0] = 0, word[t] = words, cell[0] = cb, cell[t] = ce;
  for (unsigned i = 1; i < t; ++i) {
    word[i] = key[cb + static_cast<std::uint32_t>(std::uint64_t{ce - cb} * i / t)] >> 6;
    cell[i] = static_cast<std::uint32_t>(std::lower_bound(key + cb, key + ce, word[i] * 64) - key);
  }
  parallel_for(t, t, [&](std::size_t i, unsigned) {
    std::fill(occupied_.begin() + word[i], occupied_.begin() + word[i + 1], 0);
    for (std::uint32_t c = cell[i]; c < cell[i + 1]; ++c) occupied_[key[c] >> 6] |= std::uint64_t{1} << (key[c] & 63);
    std::uint32_t sum = cell[i] - cb;
    for (std::uint64_t w = word[i]; w < word[i + 1]; ++w) {
      rank_[w] = sum;
      sum += static_cast<std::uint32_t>(std::popcount(occupied_[w]));
    }
  });
}

std::uint64_t CellGrid::same_level_cells(const Level& lv, std::uint32_t c_begin, std::uint32_t c_end,
                                         std::vector<BodyPair>& out) const {
  const std::uint32_t* key = cell_key_.data();
  const std::uint32_t* start = cell_start_.data();
  const Item* it = items_.data();
  const std::uint32_t* ids = ids_.data();
  const std::uint32_t cb = lv.cell_begin, ce = lv.cell_end;
  const std::uint64_t nx = lv.shape.nx, nxy = lv.shape.nx * lv.shape.ny;
  // Half stencil rows, as the key of their dx = -1 cell minus the cell's own key.
  const std::uint64_t row[4] = {nx - 1, nxy - nx - 1, nxy - 1, nxy + nx - 1};
  std::uint64_t tests = 0;
  auto cell_pair = [&](std::uint32_t c, std::uint32_t q) {
    for (std::uint32_t i = start[c]; i < start[c + 1]; ++i)
      for (std::uint32_t j = start[q]; j < start[q + 1]; ++j)
        if (overlap(it[i], it[j])) emit(ids, i, j, out);
    tests += std::uint64_t{start[c + 1] - start[c]} * (start[q + 1] - start[q]);
  };
  auto own_cell = [&](std::uint32_t c) {
    for (std::uint32_t i = start[c]; i < start[c + 1]; ++i)
      for (std::uint32_t j = i + 1; j < start[c + 1]; ++j) {
        ++tests;
        if (overlap(it[i], it[j])) emit(ids, i, j, out);
      }
  };
  if (bitmap_) {
    // Occupancy bitmap: the 3 cells of a stencil row are 3 bits at key t; the index of the
    // first occupied cell at or after t is its rank (occupied keys below t).
    const std::uint64_t* bits = occupied_.data();
    const std::uint32_t* rank = rank_.data();
    constexpr std::uint32_t kAhead = 16;
    // Prefetch only when the level's items outgrow the cache: below that the two rank
    // lookups per cell cost more than the misses they hide (a tenth of the scan at 2,000 bodies).
    const bool prefetch = std::uint64_t{lv.end - lv.begin} * sizeof(Item) > kPrefetchItemBytes;
    for (std::uint32_t c = c_begin; c < c_end; ++c) {
      const std::uint64_t k = key[c];
      if (prefetch && c + kAhead < ce) {
        // The next plane's rows are ~n / nz items ahead in memory: prefetch the boxes
        // a later cell will test there (rows y-1 and y+1 of plane z+1).
        const std::uint64_t ka = key[c + kAhead];
        for (int r : {1, 3}) {
          const std::uint64_t t = ka + row[r];
          const std::uint32_t q = cb + rank[t >> 6];
          if (q < ce) {
            const char* item = reinterpret_cast<const char*>(&it[start[q]]);
            __builtin_prefetch(item);
            __builtin_prefetch(item + sizeof(Item) - 1);
          }
        }
      }
      own_cell(c);
      if (c + 1 < ce && key[c + 1] == k + 1) cell_pair(c, c + 1);
      for (int r = 0; r < 4; ++r) {
        const std::uint64_t t = k + row[r];
        const std::uint64_t w = t >> 6;
        const unsigned sh = static_cast<unsigned>(t & 63);
        const std::uint64_t lo = bits[w] >> sh;
        const std::uint64_t hi = sh == 0 ? 0 : bits[w + 1] << (64 - sh);
        const unsigned mask = static_cast<unsigned>((lo | hi) & 7);
        if (mask == 0) continue;
        const std::uint64_t below = sh == 0 ? 0 : bits[w] & ((std::uint64_t{1} << sh) - 1);
        std::uint32_t q = cb + rank[w] + static_cast<std::uint32_t>(std::popcount(below));
        for (unsigned b = 0; b < 3; ++b)
          if (mask >> b & 1) cell_pair(c, q++);
      }
    }
    return tests;
  }
  // Cursor r: first cell whose key is >= (current cell's key + row[r]); neighbours may lie
  // beyond c_end, so cursors run to the level's end ce.
  std::uint32_t cur[4] = {cb, cb, cb, cb};
  if (c_begin > cb && c_begin < ce)
    for (int r = 0; r < 4; ++r)
      cur[r] = static_cast<std::uint32_t>(std::lower_bound(key + cb, key + ce, key[c_begin] + row[r]) - key);
  for (std::uint32_t c = c_begin; c < c_end; ++c) {
    const std::uint64_t k = key[c];
    own_cell(c);
    if (c + 1 < ce && key[c + 1] == k + 1) cell_pair(c, c + 1);
    for (int r = 0; r < 4; ++r) {
      const std::uint64_t t = k + row[r];
      std::uint32_t p = cur[r];
      while (p < ce && key[p] < t) ++p;
      cur[r] = p;
      for (; p < ce && key[p] <= t + 2; ++p) cell_pair(c, p);
    }
  }
  return tests;
}

std::uint64_t CellGrid::cross_level(const Level& fine, const Level& coarse, std::vector<BodyPair>& out) {
  // Queries: each finer body keyed by its cell at the coarse level, sorted by that key.
  const std::uint32_t nq = fine.end - fine.begin;
  std::vector<std::uint64_t>& qs = query_;
  qs.resize(nq);
  for (std::uint32_t k = 0; k < nq; ++k) qs[k] = (key_of(coarse, items_[fine.begin + k].lo) << 32) | (fine.begin + k);
  radix_sort_by_key(qs.data(), nq, coarse.key_bits, tmp_);

  const std::uint32_t* key = cell_key_.data();
  const std::uint32_t* start = cell_start_.data();
  const Item* it = items_.data();
  const std::uint32_t* ids = ids_.data();
  const std::uint32_t cb = coarse.cell_begin, ce = coarse.cell_end;
  const auto nx = static_cast<std::int64_t>(coarse.shape.nx);
  const auto nxy = static_cast<std::int64_t>(coarse.shape.nx * coarse.shape.ny);
  std::int64_t row[9];
  for (int dz = -1, r = 0; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy, ++r) row[r] = dz * nxy + dy * nx - 1;
  std::uint32_t cur[9];
  std::fill(cur, cur + 9, cb);
  std::uint64_t tests = 0;
  for (std::uint32_t k = 0; k < nq; ++k) {
    const auto qk = static_cast<std::int64_t>(qs[k] >> 32);
    const auto ia = static_cast<std::uint32_t>(qs[k]);
    const Item& a = it[ia];
    for (int r = 0; r < 9; ++r) {
      const std::int64_t t = qk + row[r];
      std::uint32_t p = cur[r];
      while (p < ce && static_cast<std::int64_t>(key[p]) < t) ++p;
      cur[r] = p;
      for (; p < ce && static_cast<std::int64_t>(key[p]) <= t + 2; ++p) {
        for (std::uint32_t j = start[p]; j < start[p + 1]; ++j)
          if (overlap(a, it[j])) emit(ids, ia, j, out);
        tests += start[p + 1] - start[p];
      }
    }
  }
  return tests;
}

std::uint64_t CellGrid::find_pairs(std::vector<BodyPair>& out) {
  std::uint64_t tests = 0;
  for (std::size_t f = 0; f < levels_.size(); ++f) {
    if (levels_[f].begin == levels_[f].end) continue;
    tests += same_level(levels_[f], out);
    for (std::size_t c = f + 1; c < levels_.size(); ++c)
      if (levels_[c].begin != levels_[c].end) tests += cross_level(levels_[f], levels_[c], out);
  }
  return tests;
}

}  // namespace ccd::detail
