#include "root_proof.hpp"

#include <cloth/ccd/parameter_box.hpp>

#include <cmath>

namespace ccd::cloth::detail {
namespace root_proof {  // named: unity batches put several files in one compile
namespace {

// F and its Jacobian (columns d/dt, d/da, d/db) at p = (t, a, b), in plain doubles: they
// only steer Newton's method.
void value_and_jacobian(PrimitivePair kind, const LinearQuery& q, const double (&p)[3], double (&f)[3],
                        double (&j)[3][3]) {
  const double t = p[0], a = p[1], b = p[2];
  for (int k = 0; k < 3; ++k) {
    double x[4], v[4];
    for (std::size_t i = 0; i < 4; ++i) {
      x[i] = lerp(q.x[i][k], q.x[i + 4][k], t);
      v[i] = q.x[i + 4][k] - q.x[i][k];
    }
    if (kind == PrimitivePair::VertexFace) {
      const double w0 = 1.0 - a - b;
      f[k] = x[0] - (w0 * x[1] + a * x[2] + b * x[3]);
      j[k][0] = v[0] - (w0 * v[1] + a * v[2] + b * v[3]);
      j[k][1] = x[1] - x[2];
      j[k][2] = x[1] - x[3];
    } else {
      f[k] = ((1.0 - a) * x[0] + a * x[1]) - ((1.0 - b) * x[2] + b * x[3]);
      j[k][0] = ((1.0 - a) * v[0] + a * v[1]) - ((1.0 - b) * v[2] + b * v[3]);
      j[k][1] = x[1] - x[0];
      j[k][2] = x[2] - x[3];
    }
  }
}

// The inverse of m (Cramer's rule); false when m is singular or nearly so.
bool invert(const double (&m)[3][3], double (&inv)[3][3]) {
  double c[3][3];
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s) {
      const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, s1 = (s + 1) % 3, s2 = (s + 2) % 3;
      c[r][s] = m[r1][s1] * m[r2][s2] - m[r1][s2] * m[r2][s1];  // cofactor (signs by the cyclic order)
    }
  const double det = m[0][0] * c[0][0] + m[0][1] * c[0][1] + m[0][2] * c[0][2];
  double scale = 0.0;
  for (const auto& row : m)
    for (double x : row) scale = std::max(scale, std::abs(x));
  if (!(std::abs(det) > 1e-200) || !(std::abs(det) > 1e-13 * scale * scale * scale)) return false;
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s) inv[r][s] = c[s][r] / det;
  return true;
}

// The Poincare-Miranda test on the box (header): corner values of F from
// evaluate_corners, whose corner order is (a, b) = lo lo, hi lo, then for edge-edge lo hi,
// hi hi, and for vertex-face (the rectangle's order, unclipped here) hi hi, lo hi.
template <PrimitivePair Kind>
bool miranda(const LinearQuery& q, const ParameterBox& box, const double (&A)[3][3], double err) {
  CornerValues c;
  evaluate_corners<Kind>(q, box, c);
  if (c.n != 4) return false;
  constexpr int a_hi[4] = {0, 1, Kind == PrimitivePair::VertexFace ? 1 : 0,
                           Kind == PrimitivePair::VertexFace ? 0 : 1};
  constexpr int b_hi[4] = {0, 0, 1, 1};
  for (int i = 0; i < 3; ++i) {
    const double n1 = std::abs(A[i][0]) + std::abs(A[i][1]) + std::abs(A[i][2]);
    int lo_sign = 0, hi_sign = 0;  // +1 / -1: every corner of the face proved positive / negative
    bool first_lo = true, first_hi = true;
    for (int it = 0; it < 2; ++it)
      for (int ci = 0; ci < 4; ++ci) {
        const double* f = c.f[it][ci];
        const double g = (A[i][0] * f[0] + A[i][1] * f[1]) + A[i][2] * f[2];
        const double s = std::abs(A[i][0] * f[0]) + std::abs(A[i][1] * f[1]) + std::abs(A[i][2] * f[2]);
        const double bound = (n1 * err + 4.0 * kEps * s) * (1 + 0x1p-40) + kUnderflowSlack;
        const int sign = g > bound ? 1 : g < -bound ? -1 : 0;
        const bool on_hi = i == 0 ? it == 1 : i == 1 ? a_hi[ci] == 1 : b_hi[ci] == 1;
        int& face = on_hi ? hi_sign : lo_sign;
        bool& first = on_hi ? first_hi : first_lo;
        if (sign == 0 || (!first && face != sign)) return false;
        face = sign;
        first = false;
      }
    if (lo_sign != -hi_sign) return false;
  }
  return true;
}

}  // namespace
}  // namespace root_proof

bool proves_root(PrimitivePair kind, const LinearQuery& q, double err, const double (&start)[3],
                 double& t_upper) {
  double p[3] = {start[0], start[1], start[2]}, f[3], j[3][3], A[3][3];
  for (int iter = 0; iter < 6; ++iter) {
    root_proof::value_and_jacobian(kind, q, p, f, j);
    if (!root_proof::invert(j, A)) return false;
    double step = 0.0;
    for (int r = 0; r < 3; ++r) {
      const double d = A[r][0] * f[0] + A[r][1] * f[1] + A[r][2] * f[2];
      p[r] -= d;
      step = std::max(step, std::abs(d));
    }
    if (!(std::abs(p[0]) <= 2 && std::abs(p[1]) <= 2 && std::abs(p[2]) <= 2)) return false;  // diverging
    if (step < 0x1p-50) break;
  }
  root_proof::value_and_jacobian(kind, q, p, f, j);
  if (!root_proof::invert(j, A)) return false;
  // The half-width: far above the error A carries into G (|A|_inf err), so that G_i is
  // about +-r on the faces; tried at two sizes (a larger box is needed when x* is rough).
  double norm_a = 0.0;
  for (const auto& row : A) norm_a = std::max(norm_a, std::abs(row[0]) + std::abs(row[1]) + std::abs(row[2]));
  double r = std::max(0x1p-44, std::exp2(std::ceil(std::log2(256.0 * norm_a * err))));
  for (int attempt = 0; attempt < 2 && r <= 0x1p-4; ++attempt, r *= 0x1p8) {
    ParameterBox box{};
    bool inside = true;
    for (int d = 0; d < 3; ++d) {
      const double centre = std::round(p[d] / r) * r;  // a multiple of r: exact
      box.lo[d] = centre - r;
      box.hi[d] = centre + r;
      inside = inside && box.lo[d] >= 0.0 && box.hi[d] <= 1.0;
    }
    if (!inside || (kind == PrimitivePair::VertexFace && box.hi[1] + box.hi[2] > 1.0)) continue;
    const bool proved = kind == PrimitivePair::VertexFace
                            ? root_proof::miranda<PrimitivePair::VertexFace>(q, box, A, err)
                            : root_proof::miranda<PrimitivePair::EdgeEdge>(q, box, A, err);
    if (proved) {
      t_upper = box.hi[0];
      return true;
    }
  }
  return false;
}

}  // namespace ccd::cloth::detail
