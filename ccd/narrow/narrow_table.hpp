#pragma once
// The narrow phase behind one table keyed by the pair of shape kinds (Box2D's
// s_registers[type][type] with b2AddType; Jolt's CollisionDispatch). An entry answers one
// pair (a, b) for one step (ccd/narrow/narrow_query.hpp) with a ContactResult. Adding
// (A, B) registers (B, A) too, with the pair's roles swapped on the call, so an entry
// only handles its own order. The default table binds every pair of kinds to
// conservative advancement (ccd/narrow/conservative_advancement.hpp) and overrides
// sphere x sphere with the exact solver (ccd/narrow/sphere_sphere_narrow.hpp).
//
// One more column, a static polygon (ccd/scene/scenery.hpp), holds the body x polygon
// entries, keyed by the body's kind: the default table binds every kind to conservative
// advancement against the polygon at rest (ccd/narrow/body_polygon_narrow.hpp) and
// overrides sphere x polygon with the exact solver (ccd/narrow/sphere_polygon_narrow.hpp).
//
// Dispatch is decided once per step: a caller looks the entry up for the kinds present
// (find) and calls it per pair. A missing entry is a programming error (find throws
// std::logic_error naming the two kinds).
#include <ccd/narrow/contact_result.hpp>
#include <ccd/narrow/narrow_query.hpp>
#include <ccd/scene/scenery.hpp>
#include <ccd/shape/shape_kind.hpp>

#include <array>
#include <cstdint>

namespace ccd {

using NarrowFn = ContactResult (*)(const NarrowInput& in, std::uint32_t a, std::uint32_t b);

/// A body x polygon entry: `body` against the static polygon over the step.
using PolygonNarrowFn = ContactResult (*)(const NarrowInput& in, std::uint32_t body, const StaticPolygon& polygon);

struct NarrowEntry {
  NarrowFn fn = nullptr;
  bool swapped = false;  ///< registered for (B, A): called with b and a exchanged
  ContactResult operator()(const NarrowInput& in, std::uint32_t a, std::uint32_t b) const {
    return swapped ? fn(in, b, a) : fn(in, a, b);
  }
};

class NarrowTable {
 public:
  /// Registers fn for (ka, kb) and, when ka != kb, for (kb, ka) with the roles swapped.
  /// Replaces an existing entry (an exact override of a generic one).
  void add(ShapeKind ka, ShapeKind kb, NarrowFn fn);
  /// The entry for (ka, kb); throws std::logic_error when there is none.
  NarrowEntry find(ShapeKind ka, ShapeKind kb) const;
  bool contains(ShapeKind ka, ShapeKind kb) const { return at(ka, kb).fn != nullptr; }

  /// The polygon column: registers fn for a body of kind `kind` against a static polygon,
  /// replacing an existing entry.
  void add_polygon(ShapeKind kind, PolygonNarrowFn fn) { polygon_[static_cast<std::size_t>(kind)] = fn; }
  /// The entry for (kind, polygon); throws std::logic_error when there is none.
  PolygonNarrowFn find_polygon(ShapeKind kind) const;
  bool contains_polygon(ShapeKind kind) const { return polygon_[static_cast<std::size_t>(kind)] != nullptr; }

 private:
  const NarrowEntry& at(ShapeKind ka, ShapeKind kb) const {
    return entries_[static_cast<std::size_t>(ka) * kShapeKinds + static_cast<std::size_t>(kb)];
  }
  std::array<NarrowEntry, kShapeKinds * kShapeKinds> entries_{};
  std::array<PolygonNarrowFn, kShapeKinds> polygon_{};
};

/// The default table: sphere x sphere -> sphere_sphere_narrow; every other pair ->
/// conservative_advancement; sphere x polygon -> sphere_polygon_narrow; every other kind x
/// polygon -> polygon_advancement.
const NarrowTable& narrow_table();

}  // namespace ccd
