#include <ccd/queries/sphere_pair_filter.hpp>
#include <ccd/geometry/numeric_limits.hpp>

#include <xsimd/xsimd.hpp>

#include <cmath>
#include <limits>

namespace ccd {
namespace {

using Batch = xsimd::batch<double>;

// The same element-wise operations on one double and on a SIMD batch, so that the
// vector loop and its scalar tail give identical verdicts (IEEE operations, no
// contraction: -ffp-contract=off).
double vabs(double x) { return std::fabs(x); }
Batch vabs(const Batch& x) { return xsimd::abs(x); }
double vselect(bool c, double a, double b) { return c ? a : b; }
Batch vselect(const Batch::batch_bool_type& c, const Batch& a, const Batch& b) { return xsimd::select(c, a, b); }
bool vand(bool a, bool b) { return a && b; }
Batch::batch_bool_type vand(const Batch::batch_bool_type& a, const Batch::batch_bool_type& b) { return a && b; }

// Verdicts as 0 (Apart), 1 (Contact), 2 (Solve); see the header for the bands.
template <class T>
T verdict(T dx, T dy, T dz, T vx, T vy, T vz, T R, T P, T E, T S) {
  const T a = (vx * vx + vy * vy) + vz * vz;
  const T b = (dx * vx + dy * vy) + dz * vz;
  const T c = (dx * dx + dy * dy) + dz * dz;
  const T R2 = R * R;
  const T f0 = c - R2;
  const T ex = dx + vx * S, ey = dy + vy * S, ez = dz + vz * S;
  const T f1 = ((ex * ex + ey * ey) + ez * ez) - R2;
  // The vertex -b/a lies inside (0, S) when b < 0 < b + a S (a == 0 gives b == 0).
  const auto interior = vand(b < T(0.0), b + a * S > T(0.0));
  const T fv = vselect(interior, (c - b * b / a) - R2, T(kInf));
  // |d0| and |v| bounded by their 1-norms (at most sqrt(3) larger: wider bands, no sqrt).
  const T dn = (vabs(dx) + vabs(dy)) + vabs(dz);
  const T Ra = vabs(R);
  const T M = dn + ((vabs(vx) + vabs(vy)) + vabs(vz)) * S;
  const T tiny = T(2048.0 * kEps * kEps) * P * P;
  const T band_apart = T(256.0 * kEps) * (M + Ra) * ((M + Ra) + P) + tiny + T(8.0) * (M + Ra) * E;
  const T band_contact = T(256.0 * kEps) * (dn + Ra) * ((dn + Ra) + P) + tiny + T(16.0) * (dn + Ra) * E;
  // Written as comparisons that are false for NaN, so that NaN anywhere gives Solve.
  const auto apart = vand(vand(f0 > band_apart, f1 > band_apart), fv > band_apart);
  const auto contact = f0 < -band_contact;
  return vselect(apart, T(0.0), vselect(contact, T(1.0), T(2.0)));
}

PairVerdict to_verdict(double v) {
  return v == 0.0 ? PairVerdict::Apart : v == 1.0 ? PairVerdict::Contact : PairVerdict::Solve;
}

}  // namespace

void classify_relative_motion(const RelativeMotionBlock& k, double duration, PairVerdict* out) {
  const std::size_t n = k.count < RelativeMotionBlock::capacity ? k.count : RelativeMotionBlock::capacity;
  if (!(duration >= 0.0) || !std::isfinite(duration)) {
    for (std::size_t i = 0; i < n; ++i) out[i] = PairVerdict::Solve;
    return;
  }
  constexpr std::size_t w = Batch::size;
  const Batch S(duration);
  std::size_t i = 0;
  for (; i + w <= n; i += w) {
    alignas(64) double v[w];
    verdict(Batch::load_aligned(k.dx + i), Batch::load_aligned(k.dy + i), Batch::load_aligned(k.dz + i),
            Batch::load_aligned(k.vx + i), Batch::load_aligned(k.vy + i), Batch::load_aligned(k.vz + i),
            Batch::load_aligned(k.radius_sum + i), Batch::load_aligned(k.magnitude + i),
            Batch::load_aligned(k.model + i), S)
        .store_aligned(v);
    for (std::size_t j = 0; j < w; ++j) out[i + j] = to_verdict(v[j]);
  }
  for (; i < n; ++i)
    out[i] = to_verdict(verdict(k.dx[i], k.dy[i], k.dz[i], k.vx[i], k.vy[i], k.vz[i], k.radius_sum[i], k.magnitude[i],
                                k.model[i], duration));
}

}  // namespace ccd
