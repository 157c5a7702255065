#include <ccd/scene/periodic.hpp>

namespace ccd {

std::optional<PeriodicBox> PeriodicBox::of(const Scene& scene) {
  if (!scene.wraps()) return std::nullopt;
  PeriodicBox p;
  p.min = scene.box->min;
  p.max = scene.box->max;
  for (int k = 0; k < 3; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    p.wrap[uk] = scene.box->wraps(k);
    if (!p.wrap[uk]) continue;
    const Dd L = two_sum(p.max[k], -p.min[k]);
    p.period[k] = L.hi;
    p.period_low[k] = L.lo;
  }
  return p;
}

}  // namespace ccd
