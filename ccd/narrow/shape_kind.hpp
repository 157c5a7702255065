#pragma once
// The kinds of body shape the narrow phase dispatches on (ccd/narrow/narrow_table.hpp).
// A body is a shape plus a motion; bounds and broad phases never see the kind, only a
// centre and the radius of the sphere that encloses the body. Scenes hold spheres only.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace ccd {

enum class ShapeKind : std::uint8_t {
  Sphere,
};

/// Number of kinds (the narrow table is kShapeKinds x kShapeKinds).
inline constexpr std::size_t kShapeKinds = 1;

/// "sphere".
constexpr std::string_view to_string(ShapeKind k) {
  switch (k) {
    case ShapeKind::Sphere: return "sphere";
  }
  return "unknown";
}

}  // namespace ccd
