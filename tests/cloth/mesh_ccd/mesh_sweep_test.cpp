// mesh_sweep against brute force, pair for pair: without its half-interval filter it
// returns exactly the non-adjacent pairs whose swept boxes overlap (what boxes:brute
// returns); with it, exactly the pairs its brute-force reference keeps, a subset, whatever
// the thread count and the buffer size. Pairs it drops are proved contact-free by the
// exact reference. The layouts (a grid of cells across the sweep axis) are checked the same
// way on forced layouts: one cell, slabs along one axis or both, slabs as wide as the grid
// sheets' cells (boxes exactly on their boundaries), many thin slabs, frames 2^20 from the
// origin, a sheet of zero extent on one axis, long thin boxes, boxes spanning every slab,
// coincident boxes.
#include <cloth/ccd/triangle_ccd.hpp>
#include <cloth/cull/cullers.hpp>
#include <cloth/exact/exact_ccd.hpp>
#include <cloth/mesh_ccd/mesh_frames.hpp>
#include <cloth/mesh_ccd/mesh_sweep.hpp>
#include <cloth/mesh_ccd/mesh_topology.hpp>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

namespace cloth_mesh_ccd_mesh_sweep_test {

using namespace ccd::cloth;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Appends an n x n grid sheet (cells of side h, two triangles each) at `origin` at t = 0,
// moved by `motion` at t = 1 (dyadic numbers in, exact coordinates out).
void add_grid(MeshFramePair& m, int n, double h, const ccd::Vec3& origin, const ccd::Vec3& motion) {
  const auto base = static_cast<std::uint32_t>(m.x0.size());
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const ccd::Vec3 p = origin + ccd::Vec3(i * h, j * h, 0.0);
      m.x0.push_back(p);
      m.x1.push_back(p + motion);
    }
  auto at = [&](int i, int j) { return base + static_cast<std::uint32_t>(j * n + i); };
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      m.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
}

struct Widths {
  double slab = 0.0, third = 0.0;  // MeshSweepOptions::slab_width, slab_width2
};

// mesh_sweep with and without its half-interval filter, on every layout and thread count
// given, against boxes:brute and its own brute-force reference, pair for pair.
void check_layouts(const MeshFramePair& m, double separation, std::initializer_list<Widths> layouts,
                   std::size_t* most_cells = nullptr, std::size_t* most_grid = nullptr) {
  const ClothMesh mesh = mesh_topology(m.faces, m.x0.size());
  const std::vector<Candidate> boxes = find_culler("boxes:brute")->cull(mesh, m.x0, m.x1, separation);
  REQUIRE(!boxes.empty());
  for (const Widths w : layouts)
    for (const unsigned threads : {1u, 3u, 7u}) {
      INFO("slab widths " << w.slab << ", " << w.third << ", threads " << threads);
      MeshSweep plain;
      plain.prepare(mesh, m.x0, m.x1, {separation, false, threads, w.slab, w.third});
      if (std::isinf(w.slab)) CHECK(plain.slabs() == 1);
      if (w.slab != 0 && !(w.third > 0 && std::isfinite(w.third))) CHECK(plain.slabs2() == 1);
      CHECK(plain.cells() <= m.x0.size());
      if (most_cells) *most_cells = std::max(*most_cells, plain.cells());
      if (most_grid) *most_grid = std::max(*most_grid, std::min(plain.slabs(), plain.slabs2()));
      CHECK(plain.all(threads) == boxes);
      MeshSweep halves;
      halves.prepare(mesh, m.x0, m.x1, {separation, true, threads, w.slab, w.third});
      const std::vector<Candidate> got = halves.all(threads);
      CHECK(got == halves.brute_force());
      CHECK(std::includes(boxes.begin(), boxes.end(), got.begin(), got.end()));
    }
}

}  // namespace

TEST_CASE("mesh_sweep returns the box-overlapping pairs of brute force", "[cloth][mesh_ccd]") {
  std::size_t dropped = 0;
  for (const std::string_view name : mesh_frame_generators())
    for (const double separation : {0.0, 0.05}) {
      const MeshFramePair m = generate_mesh_frames(name, 300);
      const ClothMesh mesh = mesh_topology(m.faces, m.x0.size());
      INFO(name << ", separation " << separation);
      const std::vector<Candidate> boxes = find_culler("boxes:brute")->cull(mesh, m.x0, m.x1, separation);
      REQUIRE(!boxes.empty());

      MeshSweep plain;
      plain.prepare(mesh, m.x0, m.x1, {separation, false, 2});
      CHECK(plain.all(1) == boxes);
      CHECK(plain.brute_force() == boxes);

      MeshSweep halves;
      halves.prepare(mesh, m.x0, m.x1, {separation, true, 3});
      const std::vector<Candidate> got = halves.all(1);
      CHECK(got == halves.brute_force());
      CHECK(got == halves.all(7));
      CHECK(got == find_culler("mesh_sweep")->cull(mesh, m.x0, m.x1, separation));
      CHECK(std::includes(boxes.begin(), boxes.end(), got.begin(), got.end()));
      for (const Candidate& c : got) CHECK_FALSE(adjacent(mesh, c));

      // A block of one candidate streams the same pairs.
      std::vector<Candidate> streamed;
      Candidate one[1];
      for (std::size_t k = 0; k < halves.chunks(); ++k)
        halves.sweep(k, one, [&](std::span<const Candidate> b) {
          CHECK(b.size() == 1);
          streamed.insert(streamed.end(), b.begin(), b.end());
        });
      std::sort(streamed.begin(), streamed.end());
      CHECK(streamed == got);

      // What the halves drop has no contact within the separation: the kernel's Miss is a
      // proof; what it cannot exclude, the exact reference decides.
      const mpq_class d(separation);
      TriangleCcdOptions kernel;
      kernel.separation = separation;
      for (const Candidate& c : boxes) {
        if (std::binary_search(got.begin(), got.end(), c)) continue;
        ++dropped;
        const LinearQuery q = candidate_query(mesh, c, m.x0, m.x1);
        if (triangle_ccd(c.kind, q, kernel).status == ccd::QueryStatus::Miss) continue;
        CHECK_FALSE(exact_contact(c.kind, to_rational(q), d * d));
      }
    }
  CHECK(dropped > 0);  // the moving scenes lose pairs to the halves
}

TEST_CASE("mesh_sweep on chunks larger than one: many primitives, a still mesh", "[cloth][mesh_ccd]") {
  // More primitives than one chunk (kChunk) on each side; x1 = x0 (the halves equal the
  // whole boxes up to the rounding of the midpoint, which only widens them).
  const MeshFramePair m = generate_mesh_frames("tori", 5000);
  const ClothMesh mesh = mesh_topology(m.faces, m.x0.size());
  REQUIRE(mesh.edges.size() > 2 * MeshSweep::kChunk);
  MeshSweep s;
  s.prepare(mesh, m.x0, m.x0, {0.01, true, 2});
  CHECK(s.all(2) == find_culler("boxes:sweep")->cull(mesh, m.x0, m.x0, 0.01));
}

TEST_CASE("mesh_sweep's slabs: any layout gives brute force's pairs", "[cloth][mesh_ccd]") {
  for (const std::string_view name : mesh_frame_generators())
    for (const double separation : {0.0, 0.05}) {
      INFO(name << ", separation " << separation);
      std::size_t most = 0, grid = 0;
      // automatic, one cell, slabs on one axis, grids, and 1e-300: the most cells allowed
      // (one per vertex)
      check_layouts(generate_mesh_frames(name, 300), separation,
                    {{0.0, 0.0}, {kInf, kInf}, {0.25, kInf}, {0x1p-5, 0.0}, {kInf, 0.25}, {0.25, 0.25},
                     {0x1p-5, 0x1p-3}, {1e-300, kInf}, {1e-300, 1e-300}, {0x1p-3, 1e-300}},
                    &most, &grid);
      CHECK(most > 16);
      CHECK(grid >= 4);
    }
}

TEST_CASE("mesh_sweep's slabs: boxes on slab boundaries, far from the origin, zero extent", "[cloth][mesh_ccd]") {
  const double h = 0x1p-4;
  for (const double far : {0.0, 0x1p20}) {
    INFO("offset " << far);
    const ccd::Vec3 offset(far, far, far);
    // Two sheets of dyadic coordinates, one falling through the other: with slabs of width
    // h (or h/2) every slab boundary lies on vertices' coordinates, and the boxes of the
    // still sheet end exactly on them.
    MeshFramePair two;
    add_grid(two, 9, h, offset, ccd::Vec3(0, 0, 0));
    add_grid(two, 9, h, offset + ccd::Vec3(h / 2, h / 4, h), ccd::Vec3(0, 0, -2 * h));
    std::size_t most = 0, grid = 0;
    check_layouts(two, 0.0, {{0.0}, {kInf}, {h}, {h / 2}, {3 * h}, {h, h}, {h / 2, h / 4}, {kInf, h}}, &most, &grid);
    check_layouts(two, h / 8, {{0.0}, {h}, {h, h}}, &most);
    CHECK(most >= 8);
    CHECK(grid >= 2);
    // A flat sheet sliding in its plane: zero extent on z, at both frames.
    MeshFramePair flat;
    add_grid(flat, 9, h, offset, ccd::Vec3(h / 2, 0, 0));
    check_layouts(flat, 0.0, {{0.0}, {kInf}, {h}, {1e-300}, {h, h}, {1e-300, 1e-300}});
    // All on one line of slabs: a sheet narrower than one slab of the width asked for.
    check_layouts(flat, 0.0, {{64 * h}, {64 * h, 64 * h}});
  }
}

TEST_CASE("mesh_sweep's grid: long thin boxes, boxes across every slab, coincident boxes", "[cloth][mesh_ccd]") {
  const double h = 0x1p-4;
  for (const double far : {0.0, 0x1p20}) {
    INFO("offset " << far);
    const ccd::Vec3 o(far, far, far);
    MeshFramePair m;
    add_grid(m, 9, h, o, ccd::Vec3(0, 0, 0));  // still: boxes of zero extent on z
    add_grid(m, 9, h, o, ccd::Vec3(0, 0, 0));  // the same sheet again: every box coincides with its twin
    // Long thin boxes: small strips crossing the whole sheet in the step, along x, along y
    // and diagonally, just above the sheet and through it.
    add_grid(m, 2, h / 4, o + ccd::Vec3(-h, 3 * h + h / 8, h / 32), ccd::Vec3(10 * h, 0, 0));
    add_grid(m, 2, h / 4, o + ccd::Vec3(5 * h + h / 8, -h, -h / 32), ccd::Vec3(0, 10 * h, 0));
    add_grid(m, 2, h / 4, o + ccd::Vec3(0, 0, h), ccd::Vec3(8 * h, 8 * h, -2 * h));
    // One triangle larger than the sheet falling through it: its box spans every slab on
    // both axes.
    const auto big = static_cast<std::uint32_t>(m.x0.size());
    for (const ccd::Vec3& p : {ccd::Vec3(-h, -h, h / 2), ccd::Vec3(10 * h, -h, h / 2), ccd::Vec3(-h, 10 * h, h / 2)}) {
      m.x0.push_back(o + p);
      m.x1.push_back(o + p - ccd::Vec3(0, 0, h));
    }
    m.faces.push_back({big, big + 1, big + 2});
    std::size_t most = 0, grid = 0;
    check_layouts(m, 0.0,
                  {{0.0}, {kInf, kInf}, {h, h}, {h / 2, h / 2}, {h, kInf}, {kInf, h}, {h / 4, 3 * h}, {1e-300, 1e-300}},
                  &most, &grid);
    check_layouts(m, h / 8, {{0.0}, {h, h}, {1e-300, 1e-300}}, &most, &grid);
    CHECK(grid >= 4);  // a grid of at least 4 x 4 cells (z spans 2h: 4 slabs of h/2)
  }
}

}  // namespace cloth_mesh_ccd_mesh_sweep_test
