#include <bounds/rounding.hpp>
#include <bounds/trapezoid.hpp>
#include <bounds/wall_fold.hpp>

#include <cmath>

namespace ccd {

bool horn_trapezoids(const BodyState& s, double t0, double t1, double A, const std::optional<WallBox>& walls,
                     int m, Trapezoid* out) {
  const double h = t1 - t0;
  const double r = s.radius;
  const double magnitude = s.position.cwiseAbs().maxCoeff() + r + s.velocity.cwiseAbs().maxCoeff() * h + A * h * h;
  const double slack = rounding_slack(magnitude);
  bool folded = false;
  // Node j: time t0 + h j / m, free centre p + v s_j, centre half-width A s_j^2 / 2.
  double s_prev = 0.0;
  Vec3 c_prev = s.position;
  double w_prev = slack;
  for (int j = 0; j < m; ++j) {
    const double s_next = j + 1 == m ? h : h * (j + 1) / m;
    const Vec3 c_next = s.position + s.velocity * s_next;
    const double w_next = 0.5 * A * s_next * s_next + slack;
    Trapezoid& z = out[j];
    z.t0 = t0 + s_prev;
    z.t1 = j + 1 == m ? t1 : t0 + s_next;
    for (int k = 0; k < 3; ++k) {
      const double lo0 = c_prev[k] - w_prev, hi0 = c_prev[k] + w_prev;
      const double lo1 = c_next[k] - w_next, hi1 = c_next[k] + w_next;
      if (walls) {
        const double L = walls->min[k] + r;
        const double H = walls->max[k] - r;
        if (L <= H && (std::min(lo0, lo1) < L || std::max(hi0, hi1) > H)) {
          folded = true;
          const Interval f = fold_interval(std::min(lo0, lo1), std::max(hi0, hi1), L, H);
          z.lo0[k] = z.lo1[k] = f.lo - r - slack;
          z.hi0[k] = z.hi1[k] = f.hi + r + slack;
          continue;
        }
      }
      z.lo0[k] = lo0 - r;
      z.hi0[k] = hi0 + r;
      z.lo1[k] = lo1 - r;
      z.hi1[k] = hi1 + r;
    }
    s_prev = s_next;
    c_prev = c_next;
    w_prev = w_next;
  }
  return folded;
}

}  // namespace ccd
