#pragma once
// The narrow phase behind one table keyed by the pair of shape kinds (Box2D's
// s_registers[type][type] with b2AddType; Jolt's CollisionDispatch). An entry answers one
// pair (a, b) for one step (ccd/narrow/narrow_query.hpp) with a ContactResult. Adding
// (A, B) registers (B, A) too, with the pair's roles swapped on the call, so an entry
// only handles its own order. The default table binds every pair of kinds to
// conservative advancement (ccd/narrow/conservative_advancement.hpp) and overrides
// sphere x sphere with the exact solver (ccd/narrow/sphere_sphere_narrow.hpp).
//
// Dispatch is decided once per step: a caller looks the entry up for the kinds present
// (find) and calls it per pair. A missing entry is a programming error (find throws
// std::logic_error naming the two kinds).
#include <ccd/narrow/contact_result.hpp>
#include <ccd/narrow/narrow_query.hpp>
#include <ccd/shape/shape_kind.hpp>

#include <array>
#include <cstdint>

namespace ccd {

using NarrowFn = ContactResult (*)(const NarrowInput& in, std::uint32_t a, std::uint32_t b);

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

 private:
  const NarrowEntry& at(ShapeKind ka, ShapeKind kb) const {
    return entries_[static_cast<std::size_t>(ka) * kShapeKinds + static_cast<std::size_t>(kb)];
  }
  std::array<NarrowEntry, kShapeKinds * kShapeKinds> entries_{};
};

/// The default table: sphere x sphere -> sphere_sphere_narrow; every other pair ->
/// conservative_advancement.
const NarrowTable& narrow_table();

}  // namespace ccd
