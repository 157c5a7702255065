#include <ccd/queries/sphere_sphere_batch.hpp>

#include <ccd/queries/sphere_pair_filter.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ccd {

void LinearSpherePairs::push_back(const MovingSphere& a, const MovingSphere& b) {
  if (!a.acceleration.isZero(0.0) || !b.acceleration.isZero(0.0))
    throw std::invalid_argument("LinearSpherePairs: the spheres' accelerations must be zero");
  for (int k = 0; k < 3; ++k) {
    const auto u = static_cast<std::size_t>(k);
    position_a[u].push_back(a.position[k]);
    velocity_a[u].push_back(a.velocity[k]);
    position_b[u].push_back(b.position[k]);
    velocity_b[u].push_back(b.velocity[k]);
  }
  radius_a.push_back(a.radius);
  radius_b.push_back(b.radius);
}

MovingSphere LinearSpherePairs::a(std::size_t i) const {
  MovingSphere s;
  s.position = Vec3(position_a[0][i], position_a[1][i], position_a[2][i]);
  s.velocity = Vec3(velocity_a[0][i], velocity_a[1][i], velocity_a[2][i]);
  s.radius = radius_a[i];
  return s;
}

MovingSphere LinearSpherePairs::b(std::size_t i) const {
  MovingSphere s;
  s.position = Vec3(position_b[0][i], position_b[1][i], position_b[2][i]);
  s.velocity = Vec3(velocity_b[0][i], velocity_b[1][i], velocity_b[2][i]);
  s.radius = radius_b[i];
  return s;
}

void sphere_sphere_first_contact_batch(const LinearSpherePairs& pairs, double duration,
                                       std::span<SphereSphereContact> out) {
  const std::size_t n = pairs.size();
  if (out.size() != n) throw std::invalid_argument("sphere_sphere_first_contact_batch: out.size() != pairs.size()");
  RelativeMotionBlock block;
  PairVerdict verdicts[RelativeMotionBlock::capacity];
  const double S = duration;
  for (std::size_t first = 0; first < n; first += RelativeMotionBlock::capacity) {
    const std::size_t count = std::min(RelativeMotionBlock::capacity, n - first);
    block.count = count;
    const double* pa[3] = {pairs.position_a[0].data() + first, pairs.position_a[1].data() + first,
                           pairs.position_a[2].data() + first};
    const double* va[3] = {pairs.velocity_a[0].data() + first, pairs.velocity_a[1].data() + first,
                           pairs.velocity_a[2].data() + first};
    const double* pb[3] = {pairs.position_b[0].data() + first, pairs.position_b[1].data() + first,
                           pairs.position_b[2].data() + first};
    const double* vb[3] = {pairs.velocity_b[0].data() + first, pairs.velocity_b[1].data() + first,
                           pairs.velocity_b[2].data() + first};
    const double* ra = pairs.radius_a.data() + first;
    const double* rb = pairs.radius_b.data() + first;
    // Relative motion; P = the largest |p| + |v| S of either sphere's coordinates (the
    // exact query evaluates the data exactly, so P only has to cover this rounding).
    double* d[3] = {block.dx, block.dy, block.dz};
    double* v[3] = {block.vx, block.vy, block.vz};
    double finite[RelativeMotionBlock::capacity];  // a sum of every input's magnitude
    for (std::size_t i = 0; i < count; ++i) {
      block.magnitude[i] = 0.0;
      finite[i] = std::fabs(ra[i]) + std::fabs(rb[i]);
    }
    for (std::size_t k = 0; k < 3; ++k) {
      for (std::size_t i = 0; i < count; ++i) {
        d[k][i] = pb[k][i] - pa[k][i];
        v[k][i] = vb[k][i] - va[k][i];
        const double ma = std::fabs(pa[k][i]) + std::fabs(va[k][i]) * S;
        const double mb = std::fabs(pb[k][i]) + std::fabs(vb[k][i]) * S;
        block.magnitude[i] = std::max(block.magnitude[i], std::max(ma, mb));
        finite[i] += (ma + mb) + (std::fabs(va[k][i]) + std::fabs(vb[k][i]));
      }
    }
    for (std::size_t i = 0; i < count; ++i) {
      block.radius_sum[i] = ra[i] + rb[i];
      block.model[i] = 0.0;
      // Non-finite data (which the exact query refuses with a Miss) go to the exact
      // query: a NaN magnitude makes the filter answer Solve.
      if (!std::isfinite(finite[i])) block.magnitude[i] = std::numeric_limits<double>::quiet_NaN();
    }
    classify_relative_motion(block, S, verdicts);
    for (std::size_t i = 0; i < count; ++i) {
      switch (verdicts[i]) {
        case PairVerdict::Apart: out[first + i] = SphereSphereContact{}; break;
        case PairVerdict::Contact: out[first + i] = {ContactStatus::Overlapping, 0.0}; break;
        case PairVerdict::Solve:
          out[first + i] = sphere_sphere_first_contact(pairs.a(first + i), pairs.b(first + i), S);
          break;
      }
    }
  }
}

}  // namespace ccd
