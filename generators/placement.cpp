#include <generators/placement.hpp>

#include <cmath>

namespace ccdlab {

Placement::Key Placement::key(const ccd::Vec3& x) const {
  return {static_cast<std::int64_t>(std::floor(x.x() / cell_)), static_cast<std::int64_t>(std::floor(x.y() / cell_)),
          static_cast<std::int64_t>(std::floor(x.z() / cell_))};
}

bool Placement::is_free(const ccd::Vec3& x, double r) const {
  // Two bodies of radius <= r_max that touch have centres within 2 r_max = one cell.
  const Key k = key(x);
  for (std::int64_t dx = -1; dx <= 1; ++dx)
    for (std::int64_t dy = -1; dy <= 1; ++dy)
      for (std::int64_t dz = -1; dz <= 1; ++dz) {
        const auto it = cells_.find({k.x + dx, k.y + dy, k.z + dz});
        if (it == cells_.end()) continue;
        for (const std::uint32_t j : it->second) {
          const double R = r + radii_[j];
          if ((centres_[j] - x).squaredNorm() <= R * R) return false;
        }
      }
  return true;
}

void Placement::add(const ccd::Vec3& x, double r) {
  cells_[key(x)].push_back(static_cast<std::uint32_t>(centres_.size()));
  centres_.push_back(x);
  radii_.push_back(r);
}

}  // namespace ccdlab
