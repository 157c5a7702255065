// mesh_sweep's layout (cloth/mesh_ccd/sweep_layout.hpp): slabs are monotone and within their
// caps, forced layouts give the widths asked for, and every layout chosen is within the
// limits (at most 2^16 cells and one per vertex, the slab axis not the sweep axis). That
// the candidates do not depend on the layout is checked in mesh_sweep_test.cpp.
#include <cloth/mesh_ccd/mesh_frames.hpp>
#include <cloth/mesh_ccd/mesh_topology.hpp>
#include <cloth/mesh_ccd/sweep_layout.hpp>
#include <cloth/cull/primitive_boxes.hpp>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

namespace cloth_mesh_ccd_sweep_layout_test {

using namespace ccd::cloth;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// of() is non-decreasing over dyadic points through [lo - 1, hi + 1] (slab boundaries
// included), 0 at lo and count - 1 at hi.
void check_monotone(const Slabs& s, double lo, double hi) {
  std::size_t last = 0;
  for (int k = -64; k <= 1088; ++k) {
    const double x = lo + (hi - lo) * std::ldexp(k, -10);
    const std::size_t slab = s.of(x);
    CHECK(slab < s.count);
    CHECK(slab >= last);
    last = slab;
  }
  CHECK(s.of(lo) == 0);
  CHECK(s.of(hi) == s.count - 1);
  CHECK(s.of(-kInf) == 0);
  CHECK(s.of(kInf) == s.count - 1);
}

}  // namespace

TEST_CASE("sweep layout: slabs are monotone, capped, one slab when degenerate", "[cloth][mesh_ccd]") {
  for (const double far : {0.0, 0x1p20, -0x1p40}) {
    INFO("offset " << far);
    const double lo = far - 0.5, hi = far + 0.75;
    const Slabs s = slabs_over(lo, hi, 0x1p-4, 1000);
    CHECK(s.count == 20);  // 1.25 / (1/16)
    CHECK(s.width == 0x1p-4);
    check_monotone(s, lo, hi);
    // Boundaries: lo + k w lies in slab k.
    for (int k = 0; k < 20; ++k) CHECK(s.of(lo + k * 0x1p-4) == static_cast<std::size_t>(k));
    const Slabs capped = slabs_over(lo, hi, 1e-300, 7);
    CHECK(capped.count == 7);
    check_monotone(capped, lo, hi);
    CHECK(slabs_over(lo, hi, 1e-300, std::size_t{1} << 40).count == kMaxCells);
    CHECK(slabs_over(lo, hi, kInf, 1000).count == 1);
    CHECK(slabs_over(lo, hi, std::numeric_limits<double>::quiet_NaN(), 1000).count == 1);
    CHECK(slabs_over(lo, hi, -1.0, 1000).count == 1);
    CHECK(slabs_over(lo, hi, 2.0, 1000).count == 1);  // wider than the span
    CHECK(slabs_over(far, far, 0x1p-4, 1000).count == 1);  // zero span
  }
  CHECK(Slabs{}.of(3.0) == 0);
}

TEST_CASE("sweep layout: forced and chosen layouts are within their limits", "[cloth][mesh_ccd]") {
  for (const std::string_view name : mesh_frame_generators())
    for (const std::size_t faces : {100, 3000}) {
      INFO(name << ", " << faces << " faces");
      const MeshFramePair m = generate_mesh_frames(name, faces);
      const ClothMesh mesh = mesh_topology(m.faces, m.x0.size());
      std::vector<ccd::Aabb> vb;
      vertex_boxes(m.x0, m.x1, 0.0, vb);
      const SweepLayout chosen = choose_sweep_layout(vb, mesh.edges, 0.0, 0.0);
      CHECK(chosen.axis != chosen.slab_axis);
      CHECK(chosen.cells() <= std::min(kMaxCells, vb.size()));
      if (chosen.slabs.count == 1) CHECK(chosen.slabs2.count == 1);  // slabs on one axis: the slab axis
      const SweepLayout one = choose_sweep_layout(vb, mesh.edges, kInf, kInf);
      CHECK(one.cells() == 1);
      CHECK(one.axis != one.slab_axis);
      const SweepLayout grid = choose_sweep_layout(vb, mesh.edges, 0x1p-3, 0x1p-3);
      CHECK(grid.slabs.count > 1);
      CHECK(grid.slabs2.count > 1);
      CHECK(grid.slabs.width == 0x1p-3);
      CHECK(grid.cells() <= vb.size());
      const SweepLayout most = choose_sweep_layout(vb, mesh.edges, 1e-300, 1e-300);
      CHECK(most.cells() <= vb.size());
      CHECK(most.cells() >= vb.size() / 2);
      CHECK(choose_sweep_layout(vb, {}, 0.0, 0.0).cells() == 1);  // no edges: one cell
    }
}

}  // namespace cloth_mesh_ccd_sweep_layout_test
