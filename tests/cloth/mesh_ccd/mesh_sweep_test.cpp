// mesh_sweep against brute force, pair for pair: without its half-interval filter it
// returns exactly the non-adjacent pairs whose swept boxes overlap (what boxes:brute
// returns); with it, exactly the pairs its brute-force reference keeps, a subset, whatever
// the thread count and the buffer size. Pairs it drops are proved contact-free by the
// exact reference.
#include <cloth/ccd/triangle_ccd.hpp>
#include <cloth/cull/cullers.hpp>
#include <cloth/exact/exact_ccd.hpp>
#include <cloth/mesh_ccd/mesh_frames.hpp>
#include <cloth/mesh_ccd/mesh_sweep.hpp>
#include <cloth/mesh_ccd/mesh_topology.hpp>

#include <algorithm>
#include <catch2/catch.hpp>

using namespace ccd::cloth;

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
