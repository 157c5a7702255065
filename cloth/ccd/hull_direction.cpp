#include "hull_direction.hpp"

#include <cmath>

namespace ccd::cloth::detail {
namespace hull {  // named: unity batches put several files in one compile
namespace {

double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The nearest point to the origin of the hull of s[0..n-1] (n <= 4): the best, over the
// subsets whose affine nearest point has positive barycentric weights, of that point.
// Keeps in s only the subset that gives it.
bool nearest_on_simplex(double (&s)[4][3], int& n, double (&v)[3]) {
  double best = INFINITY, best_point[3] = {0, 0, 0};
  int best_mask = 0;
  for (int mask = 1; mask < (1 << n); ++mask) {
    int idx[4], k = 0;
    for (int i = 0; i < n; ++i)
      if (mask & (1 << i)) idx[k++] = i;
    const double* o = s[idx[0]];
    double e[3][3], g[3][3], r[3], mu[3] = {0, 0, 0};
    for (int i = 1; i < k; ++i)
      for (int c = 0; c < 3; ++c) e[i - 1][c] = s[idx[i]][c] - o[c];
    const int m = k - 1;
    for (int i = 0; i < m; ++i) {
      r[i] = -dot(e[i], o);
      for (int j = 0; j < m; ++j) g[i][j] = dot(e[i], e[j]);
    }
    if (m == 1) {
      if (!(g[0][0] > 0)) continue;
      mu[0] = r[0] / g[0][0];
    } else if (m == 2) {
      const double det = g[0][0] * g[1][1] - g[0][1] * g[1][0];
      if (!(std::abs(det) > 1e-30 * g[0][0] * g[1][1])) continue;
      mu[0] = (r[0] * g[1][1] - g[0][1] * r[1]) / det;
      mu[1] = (g[0][0] * r[1] - r[0] * g[1][0]) / det;
    } else if (m == 3) {
      double c[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
          c[i][j] = g[i1][j1] * g[i2][j2] - g[i1][j2] * g[i2][j1];
        }
      const double det = g[0][0] * c[0][0] + g[0][1] * c[0][1] + g[0][2] * c[0][2];
      if (!(std::abs(det) > 1e-30 * g[0][0] * g[1][1] * g[2][2])) continue;
      for (int i = 0; i < 3; ++i) mu[i] = (c[0][i] * r[0] + c[1][i] * r[1] + c[2][i] * r[2]) / det;
    }
    double w0 = 1.0;
    bool inside = true;
    for (int i = 0; i < m; ++i) {
      w0 -= mu[i];
      inside = inside && mu[i] > 0;
    }
    if (!inside || !(w0 > 0 || m == 0)) continue;
    double point[3];
    for (int c = 0; c < 3; ++c) {
      point[c] = o[c];
      for (int i = 0; i < m; ++i) point[c] += mu[i] * e[i][c];
    }
    const double d = dot(point, point);
    if (d < best) {
      best = d;
      best_mask = mask;
      for (int c = 0; c < 3; ++c) best_point[c] = point[c];
    }
  }
  if (best_mask == 0) return false;
  int k = 0;
  for (int i = 0; i < n; ++i)
    if (best_mask & (1 << i)) {
      for (int c = 0; c < 3; ++c) s[k][c] = s[i][c];
      ++k;
    }
  n = k;
  for (int c = 0; c < 3; ++c) v[c] = best_point[c];
  return true;
}

// a d - b c with one rounding's relative error (Kahan's algorithm with fma).
double det2(double a, double b, double c, double d) {
  const double w = b * c;
  const double e = std::fma(-b, c, w);
  const double f = std::fma(a, d, -w);
  return f + e;
}

// For a nearest point inside the segment s0 s1: the direction e x (s0 x s1), e = s1 - s0,
// which is s0 minus its projection on e, scaled by |e|^2. The cross product s0 x s1 is
// formed with relative accuracy (det2), so the direction is accurate to a few eps even when
// the segment passes the origin at a distance far below |s0| (a plain projection loses it
// to cancellation: about eps |s0| of error, which decides nothing on a box much larger than
// the gap).
void segment_direction(const double* s0, const double* s1, double (&v)[3]) {
  const double c[3] = {det2(s0[1], s0[2], s1[1], s1[2]), det2(s0[2], s0[0], s1[2], s1[0]),
                       det2(s0[0], s0[1], s1[0], s1[1])};
  const double e[3] = {s1[0] - s0[0], s1[1] - s0[1], s1[2] - s0[2]};
  const double n[3] = {e[1] * c[2] - e[2] * c[1], e[2] * c[0] - e[0] * c[2], e[0] * c[1] - e[1] * c[0]};
  if (dot(n, v) > 0) v[0] = n[0], v[1] = n[1], v[2] = n[2];
}

}  // namespace
}  // namespace hull

bool hull_nearest_point(const double (*p)[3], int n, double (&out)[3]) {
  int first = 0;
  double scale = 0.0;
  for (int i = 0; i < n; ++i) {
    scale = std::max(scale, hull::dot(p[i], p[i]));
    if (hull::dot(p[i], p[i]) < hull::dot(p[first], p[first])) first = i;
  }
  double s[4][3], v[3];
  int m = 1;
  for (int c = 0; c < 3; ++c) s[0][c] = v[c] = p[first][c];
  for (int iter = 0; iter < 24; ++iter) {
    const double vv = hull::dot(v, v);
    if (!(vv > 1e-30 * scale)) return false;  // the origin is in the hull, or nearly
    int w = 0;
    for (int i = 1; i < n; ++i)
      if (hull::dot(v, p[i]) < hull::dot(v, p[w])) w = i;
    if (vv - hull::dot(v, p[w]) <= 1e-15 * vv || m == 4) break;  // converged (or stuck: a full simplex)
    for (int c = 0; c < 3; ++c) s[m][c] = p[w][c];
    ++m;
    if (!hull::nearest_on_simplex(s, m, v)) return false;
  }
  const bool apart = hull::dot(v, v) > 1e-30 * scale;
  if (apart && m == 2) hull::segment_direction(s[0], s[1], v);
  for (int c = 0; c < 3; ++c) out[c] = v[c];
  return apart;
}

}  // namespace ccd::cloth::detail
