#pragma once
// The kinds of body shape (ccd/shape/shape.hpp) the narrow phase dispatches on
// (ccd/narrow/narrow_table.hpp). A body is a shape plus a motion; bounds and broad phases
// never see the kind, only a centre and the radius of the sphere that encloses the body.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace ccd {

enum class ShapeKind : std::uint8_t {
  Sphere,   ///< a ball: radius
  Capsule,  ///< a segment along the body x axis (half_length) swept by a ball (radius)
  Box,      ///< half_extents along the body axes
  Hull,     ///< the convex hull of points in the body frame
};

/// Number of kinds (the narrow table is kShapeKinds x kShapeKinds).
inline constexpr std::size_t kShapeKinds = 4;

/// "sphere", "capsule", "box", "hull": the names scene files use.
constexpr std::string_view to_string(ShapeKind k) {
  switch (k) {
    case ShapeKind::Sphere: return "sphere";
    case ShapeKind::Capsule: return "capsule";
    case ShapeKind::Box: return "box";
    case ShapeKind::Hull: return "hull";
  }
  return "unknown";
}

/// The kind named `name`, or nothing.
constexpr std::optional<ShapeKind> shape_kind_from_string(std::string_view name) {
  for (std::size_t k = 0; k < kShapeKinds; ++k)
    if (to_string(static_cast<ShapeKind>(k)) == name) return static_cast<ShapeKind>(k);
  return std::nullopt;
}

}  // namespace ccd
