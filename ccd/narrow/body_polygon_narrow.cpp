#include <ccd/narrow/body_polygon_narrow.hpp>

#include <ccd/motion/rigid_motion.hpp>
#include <ccd/narrow/conservative_advancement.hpp>
#include <ccd/narrow/sphere_polygon_narrow.hpp>

namespace ccd {

ContactResult body_polygon_narrow(const NarrowInput& in, std::uint32_t body, const StaticPolygon& polygon) {
  if (in.motion->kind(body) == ShapeKind::Sphere) return sphere_polygon_narrow(in, body, polygon);
  return conservative_advancement_fixed(in, body, polygon_proxy(polygon));
}

}  // namespace ccd
