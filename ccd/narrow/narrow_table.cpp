#include <ccd/narrow/narrow_table.hpp>

#include <ccd/narrow/body_polygon_narrow.hpp>
#include <ccd/narrow/conservative_advancement.hpp>
#include <ccd/narrow/sphere_polygon_narrow.hpp>
#include <ccd/narrow/sphere_sphere_narrow.hpp>

#include <stdexcept>
#include <string>

namespace ccd {

void NarrowTable::add(ShapeKind ka, ShapeKind kb, NarrowFn fn) {
  const auto ia = static_cast<std::size_t>(ka), ib = static_cast<std::size_t>(kb);
  entries_[ia * kShapeKinds + ib] = {fn, false};
  if (ia != ib) entries_[ib * kShapeKinds + ia] = {fn, true};
}

NarrowEntry NarrowTable::find(ShapeKind ka, ShapeKind kb) const {
  const NarrowEntry& e = at(ka, kb);
  if (!e.fn)
    throw std::logic_error("no narrow phase for " + std::string(to_string(ka)) + " x " + std::string(to_string(kb)));
  return e;
}

PolygonNarrowFn NarrowTable::find_polygon(ShapeKind kind) const {
  const PolygonNarrowFn fn = polygon_[static_cast<std::size_t>(kind)];
  if (!fn) throw std::logic_error("no narrow phase for " + std::string(to_string(kind)) + " x polygon");
  return fn;
}

const NarrowTable& narrow_table() {
  static const NarrowTable table = [] {
    NarrowTable t;
    // Every convex pair by conservative advancement, then the exact override.
    for (std::size_t i = 0; i < kShapeKinds; ++i)
      for (std::size_t k = i; k < kShapeKinds; ++k)
        t.add(static_cast<ShapeKind>(i), static_cast<ShapeKind>(k), &conservative_advancement);
    t.add(ShapeKind::Sphere, ShapeKind::Sphere, &sphere_sphere_narrow);
    // The polygon column likewise: every kind by conservative advancement, spheres exact.
    for (std::size_t i = 0; i < kShapeKinds; ++i) t.add_polygon(static_cast<ShapeKind>(i), &polygon_advancement);
    t.add_polygon(ShapeKind::Sphere, &sphere_polygon_narrow);
    return t;
  }();
  return table;
}

}  // namespace ccd
