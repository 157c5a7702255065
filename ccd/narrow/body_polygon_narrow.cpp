#include <ccd/narrow/body_polygon_narrow.hpp>

#include <ccd/motion/rigid_motion.hpp>
#include <ccd/narrow/conservative_advancement.hpp>

namespace ccd {

ContactResult polygon_advancement(const NarrowInput& in, std::uint32_t body, const StaticPolygon& polygon) {
  return conservative_advancement_fixed(in, body, polygon_proxy(polygon));
}

}  // namespace ccd
