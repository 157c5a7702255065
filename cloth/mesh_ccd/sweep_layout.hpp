#pragma once
// The layout of `mesh_sweep` (cloth/mesh_ccd/mesh_sweep.hpp): the sweep axis, and a grid
// of cells across it, slabs along the slab axis times slabs along the third axis.
//
// Slabs along an axis: slab(x) = clamp(floor((x - origin) / width), 0, count - 1), monotone
// in x as computed (a rounded difference and a rounded quotient by a positive number are
// monotone), so for two intervals that overlap, slab(max(lo_a, lo_b)) = max(slab(lo_a),
// slab(lo_b)) lies in both intervals' slab ranges. A box goes into every cell its two
// intervals across the sweep axis overlap; two boxes that overlap share the cell of their
// larger first slabs on both axes.
//
// The layout is chosen by the estimated cost of the edge-edge sweep (the largest of the
// three) on a sample of the edges; only the speed depends on it.
#include <ccd/geometry/aabb.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace ccd::cloth {

/// Slabs of equal width along one axis (count 1: one slab, the whole axis).
struct Slabs {
  double origin = 0.0;
  double width = 0.0;
  std::size_t count = 1;
  /// The slab of x: clamp(floor((x - origin) / width), 0, count - 1); 0 with one slab.
  std::size_t of(double x) const {
    if (count == 1) return 0;
    const double q = (x - origin) / width;
    if (!(q > 0)) return 0;
    if (!(q < static_cast<double>(count))) return count - 1;
    return std::min(count - 1, static_cast<std::size_t>(q));
  }
};

/// The most cells of a layout (and at most one per vertex).
constexpr std::size_t kMaxCells = std::size_t{1} << 16;

/// Slabs of `width` over [lo, hi]: at most min(kMaxCells, cap) (wider when there would be
/// more); one slab when the width or the span is not > 0 and finite.
Slabs slabs_over(double lo, double hi, double width, std::size_t cap);

struct SweepLayout {
  int axis = 0;       ///< the sweep axis
  int slab_axis = 1;  ///< != axis; the third axis is 3 - axis - slab_axis
  Slabs slabs;        ///< along the slab axis
  Slabs slabs2;       ///< along the third axis
  std::size_t cells() const { return slabs.count * slabs2.count; }
};

/// The layout for the swept vertex boxes `vb` and the mesh's edges (pairs of vertex
/// indices). width == 0: chosen by the sampled cost estimate (at most min(kMaxCells,
/// vb.size()) cells). Otherwise forced: the axes of largest and second-largest variance of
/// the boxes' centres, slabs of `width` along the slab axis (one slab unless > 0 and
/// finite) and of `width2` along the third (likewise), at most min(kMaxCells, vb.size())
/// cells in all. No edges: one cell.
SweepLayout choose_sweep_layout(std::span<const Aabb> vb, std::span<const std::array<std::uint32_t, 2>> edges,
                                double width, double width2);

}  // namespace ccd::cloth
