#include <ccd/narrow/narrow_table.hpp>

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

const NarrowTable& narrow_table() {
  static const NarrowTable table = [] {
    NarrowTable t;
    t.add(ShapeKind::Sphere, ShapeKind::Sphere, &sphere_sphere_narrow);
    return t;
  }();
  return table;
}

}  // namespace ccd
