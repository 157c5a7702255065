#pragma once
// A certified filter for blocks of sphere pairs on a common piece of linear relative
// motion, structure of arrays, evaluated with SIMD (xsimd): for each pair it decides, in
// double precision with an error bound, "certainly no contact on the whole window",
// "certainly in contact at the window's start" or "solve it exactly". It never answers
// a question itself; it only lets the batched queries skip the exact solver
// (ccd/queries/pair_motion.hpp) when the solver's answer is already known:
//   - Apart: f(u) = |d(u)|^2 - R^2 > band_apart for every u in [0, S], so the exact
//     contact set is empty on the window (the exact solver only reports times with
//     f <= its double-double error bound, about 1e-32 relative, far inside the band);
//   - Contact: f(0) < -band_contact, so the pair is in contact at u = 0 with a wide
//     margin: the exact solver's first interval starts at 0, and the double-precision
//     test of ccd/truth/contact_function.hpp (certain_contact, band 64 eps (|d| + R)
//     (|d| + R + P) + 4 (|d| + R) E) answers Contact as well;
//   - Solve: everything else (near tangency, a contact inside the window, non-finite or
//     degenerate data).
//
// Relative motion of one pair: d(u) = d0 + v u for u in [0, S] (units: length, seconds),
// R = r_a + r_b (rounded), P >= every coordinate magnitude |p| + |v| s + |a| s^2 / 2 the
// caller evaluated to form d0 and v (the error of a double evaluation is a few eps P per
// coordinate), E >= the model error of the caller's positions (the trajectory's edge,
// start and velocity errors; 0 for exact data). With M = |d0| + |v| S and the bands
//   band_apart   = 256 eps (M + R)(M + R + P) + 2048 eps^2 P^2 + 8 (M + R) E
//   band_contact = 256 eps (|d0| + R)(|d0| + R + P) + 2048 eps^2 P^2 + 16 (|d0| + R) E
// (|R| in place of R), the bound of the computed minimum of f against the exact one is
// 2 (M + R) e + e^2 + 10 eps (M + R)^2 with e <= sqrt(3) (20 eps P + E) the error of d:
// at most 70 eps (M + R) P + 1225 eps^2 P^2 + 3.5 (M + R) E + 10 eps (M + R)^2, so each
// verdict keeps a margin of more than 150 eps (M + R)(M + R + P) after the error. The
// minimum of the quadratic f on [0, S] is taken at 0, at S, or at the vertex -b/a when it
// lies inside (f(0) - b^2 / a, which loses no more than a few eps |d0|^2 to
// cancellation because b^2 / a <= |d0|^2).
//
// Guarantee: Apart and Contact are never wrong for the exact real-number motion described
// by the inputs (within P and E); Solve is always allowed. |d0| and |v| are taken as
// their 1-norms in the bands (upper bounds of the lengths: the bands only widen). NaN or infinite input gives
// Solve. Pairs whose relative acceleration is not exactly zero must not be given to the
// filter (the caller solves them).
#include <cstddef>
#include <cstdint>

namespace ccd {

enum class PairVerdict : std::uint8_t { Apart, Contact, Solve };

/// Up to `capacity` pairs' relative motion, structure of arrays (the filter's input).
struct RelativeMotionBlock {
  static constexpr std::size_t capacity = 256;
  alignas(64) double dx[capacity];         ///< d0 = c_b - c_a at the window start, length
  alignas(64) double dy[capacity];
  alignas(64) double dz[capacity];
  alignas(64) double vx[capacity];         ///< relative velocity, length per second
  alignas(64) double vy[capacity];
  alignas(64) double vz[capacity];
  alignas(64) double radius_sum[capacity]; ///< r_a + r_b, length
  alignas(64) double magnitude[capacity];  ///< P (see above), length
  alignas(64) double model[capacity];      ///< E (see above), length
  std::size_t count = 0;
};

/// One verdict per pair of the block (out[0 .. block.count)); window [0, duration],
/// duration >= 0 and finite (otherwise every verdict is Solve).
void classify_relative_motion(const RelativeMotionBlock& block, double duration, PairVerdict* out);

}  // namespace ccd
