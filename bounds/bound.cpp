#include <bounds/bound.hpp>

#include <stdexcept>

namespace ccd {

void Bound::refresh(const StepContext&, std::span<const std::uint32_t>, std::span<Aabb>) {
  throw std::logic_error("this bound has no window to refresh (an instant bound cannot be scheduled)");
}

PairTest Bound::test_static(std::uint32_t body, const Aabb& body_box, const StaticPolygon&,
                            const Aabb& polygon_box) const {
  if (!body_box.overlaps(polygon_box)) return PairTest::disjoint();
  return PairTest::possible_from(window(body).t0);
}

}  // namespace ccd
