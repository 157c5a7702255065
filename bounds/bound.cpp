#include <bounds/bound.hpp>

#include <stdexcept>

namespace ccd {

void Bound::refresh(const StepContext&, std::span<const std::uint32_t>, std::span<Aabb>) {
  throw std::logic_error("this bound has no window to refresh (an instant bound cannot be scheduled)");
}

}  // namespace ccd
