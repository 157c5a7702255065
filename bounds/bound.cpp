#include <bounds/bound.hpp>

#include <stdexcept>

namespace ccd {

void Bound::refresh(const StepContext&, std::span<const std::uint32_t>, std::span<Aabb>) {
  throw std::logic_error("this bound has no window to refresh (an instant bound cannot be scheduled)");
}

void Bound::test_pairs(std::span<const BodyPair> pairs, std::vector<BodyPair>& passed,
                       std::vector<double>& earliest) const {
  for (const BodyPair& p : pairs) {
    const PairTest t = test(p.a, p.b);
    if (t.possible()) {
      passed.push_back(p);
      earliest.push_back(t.earliest);
    }
  }
}

PairTest Bound::test_static(std::uint32_t body, const Aabb& body_box, const StaticPolygon&,
                            const Aabb& polygon_box) const {
  if (!body_box.overlaps(polygon_box)) return PairTest::disjoint();
  return PairTest::possible_from(window(body).t0);
}

}  // namespace ccd
