// The mesh CCD pipeline: zero false negatives against the exact reference on every pair of
// a small crumpled scene and on adversarial dyadic frames (a vertex arriving on a face at
// t = 1, leaving it at t = 0, edges sliding along each other, a vertex grazing an edge,
// coplanar motion, each also 2^20 from the origin), the candidates of every culler against
// brute force, adjacency never a candidate, and results independent of the thread count.
#include <cloth/cull/cullers.hpp>
#include <cloth/exact/exact_ccd.hpp>
#include <cloth/mesh_ccd/mesh_ccd.hpp>
#include <cloth/mesh_ccd/mesh_frames.hpp>
#include <cloth/mesh_ccd/mesh_sweep.hpp>
#include <cloth/mesh_ccd/mesh_topology.hpp>

#include <algorithm>
#include <catch2/catch.hpp>
#include <set>

namespace cloth_mesh_ccd_mesh_ccd_test {

using namespace ccd::cloth;
using ccd::Vec3;

namespace {

using VfList = std::vector<std::array<std::uint32_t, 2>>;
using EeList = std::vector<std::array<std::uint32_t, 4>>;

// Every non-adjacent pair decided exactly, as the pipeline lists collisions. A pair whose
// swept boxes (widened by half the separation, rounded outwards, compared exactly) are
// apart has no contact; every other pair is decided by the exact reference. The kernel
// takes no part.
void exact_truth(const MeshFramePair& m, double separation, VfList& vf, EeList& ee) {
  const ClothMesh mesh = mesh_topology(m.faces, m.x0.size());
  const mpq_class d(separation);
  for (const Candidate& c : find_culler("boxes:brute")->cull(mesh, m.x0, m.x1, separation)) {
    if (!exact_contact(c.kind, to_rational(candidate_query(mesh, c, m.x0, m.x1)), d * d)) continue;
    if (c.kind == PrimitivePair::VertexFace)
      vf.push_back({c.a, c.b});
    else
      ee.push_back({mesh.edges[c.a][0], mesh.edges[c.a][1], mesh.edges[c.b][0], mesh.edges[c.b][1]});
  }
}

template <class List>
bool includes(const List& big, const List& small) {
  return std::includes(big.begin(), big.end(), small.begin(), small.end());
}

// Two triangles: face 0 (0, 1, 2) still in the plane z = 0, face 1 (3, 4, 5) moving.
MeshFramePair two_triangles(const std::array<Vec3, 3>& b0, const std::array<Vec3, 3>& b1, const Vec3& shift) {
  MeshFramePair m;
  const std::array<Vec3, 3> a{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  for (const Vec3& p : a) m.x0.push_back(p + shift);
  for (const Vec3& p : b0) m.x0.push_back(p + shift);
  for (const Vec3& p : a) m.x1.push_back(p + shift);
  for (const Vec3& p : b1) m.x1.push_back(p + shift);
  m.faces = {{0, 1, 2}, {3, 4, 5}};
  return m;
}

}  // namespace

TEST_CASE("mesh ccd misses no pair of a small crumpled scene", "[cloth][mesh_ccd]") {
  const MeshFramePair m = generate_mesh_frames("crumpled", 50, 7);
  // Separation 0: the exact reference on thousands of pairs at a separation takes minutes
  // (mesh_sweep_test.cpp checks separations against it on fewer pairs).
  for (const double separation : {0.0}) {
    INFO("separation " << separation);
    VfList vf;
    EeList ee;
    exact_truth(m, separation, vf, ee);
    CHECK(vf.size() + ee.size() > 10);  // the fold goes through the sheet
    MeshCcdOptions o;
    o.separation = separation;
    const MeshCcdResult kernel = mesh_ccd(m.x0, m.x1, m.faces, o);
    CHECK(includes(kernel.vf, vf));  // zero false negatives
    CHECK(includes(kernel.ee, ee));
    o.exact = true;
    const MeshCcdResult exact = mesh_ccd(m.x0, m.x1, m.faces, o);
    CHECK(exact.vf == vf);
    CHECK(exact.ee == ee);
    CHECK(exact.false_vf.size() + exact.vf.size() == kernel.vf.size());
    CHECK(exact.false_ee.size() + exact.ee.size() == kernel.ee.size());
    REQUIRE(exact.toi);
    CHECK(exact.toi->time >= 0);
    CHECK(exact.toi->time <= 1);
    CHECK(exact.toi->error >= 0);
  }
}

TEST_CASE("every culler's candidates against brute force, the same collisions", "[cloth][mesh_ccd]") {
  const MeshFramePair m = generate_mesh_frames("tori", 200);
  const ClothMesh mesh = mesh_topology(m.faces, m.x0.size());
  const double separation = 0.0;
  const auto all = brute_force_candidates(mesh, m.x0.size());
  const auto boxes = find_culler("boxes:brute")->cull(mesh, m.x0, m.x1, separation);
  MeshSweep sweep;
  sweep.prepare(mesh, m.x0, m.x1, {separation, true, 1});
  const auto swept = sweep.brute_force();
  MeshCcdOptions o;
  o.separation = separation;
  o.exact = true;
  o.keep_candidates = true;
  o.culler = "brute";
  const MeshCcdResult reference = mesh_ccd(m.x0, m.x1, m.faces, o);
  CHECK(reference.candidates == all);
  CHECK(!reference.vf.empty());
  CHECK(!reference.ee.empty());
  for (const CullerEntry& c : cullers()) {
    INFO(c.name);
    o.culler = c.name;
    o.threads = 2;
    const MeshCcdResult r = mesh_ccd(m.x0, m.x1, m.faces, o);
    CHECK(r.candidates_vf + r.candidates_ee == r.candidates.size());
    for (const Candidate& cand : r.candidates) CHECK_FALSE(adjacent(mesh, cand));
    if (c.name == "brute")
      CHECK(r.candidates == all);
    else if (c.name == "mesh_sweep")
      CHECK(r.candidates == swept);
    else if (c.name == "bvh_cones" || c.may_drop)
      CHECK(includes(boxes, r.candidates));
    else
      CHECK(r.candidates == boxes);
    if (!c.may_drop) {  // conservative: every contact found, and decided the same
      CHECK(r.vf == reference.vf);
      CHECK(r.ee == reference.ee);
    }
  }
}

TEST_CASE("adversarial dyadic frames: touching at t = 0 and 1, sliding, grazing, coplanar, far away", "[cloth][mesh_ccd]") {
  struct Case {
    const char* name;
    std::array<Vec3, 3> b0, b1;
    bool contact;  // at separation 0
  };
  const double tiny = 0x1p-30;
  const Case cases[] = {
      // Vertex 3 arrives exactly on face 0's interior at t = 1.
      {"arrives at t = 1", {Vec3(0.25, 0.25, 1), Vec3(2, 2, 1), Vec3(2, 3, 1)},
       {Vec3(0.25, 0.25, 0), Vec3(2, 2, 1), Vec3(2, 3, 1)}, true},
      // The same, stopping 2^-30 short.
      {"stops short", {Vec3(0.25, 0.25, 1), Vec3(2, 2, 1), Vec3(2, 3, 1)},
       {Vec3(0.25, 0.25, tiny), Vec3(2, 2, 1), Vec3(2, 3, 1)}, false},
      // Vertex 3 starts on face 0's edge (y = 0) and leaves.
      {"leaves at t = 0", {Vec3(0.5, 0, 0), Vec3(2, 2, 1), Vec3(2, 3, 1)},
       {Vec3(0.5, 0, 1), Vec3(2, 2, 1), Vec3(2, 3, 1)}, true},
      // Edge 3-4 slides along the line of edge 0-1 and reaches it at t = 4/5.
      {"collinear edges sliding", {Vec3(3, 0, 0), Vec3(4, 0, 0), Vec3(4, 1, 1)},
       {Vec3(0.5, 0, 0), Vec3(1.5, 0, 0), Vec3(1.5, 1, 1)}, true},
      // Parallel edges sliding 2^-30 apart (never touching).
      {"parallel edges apart", {Vec3(3, -tiny, 0), Vec3(4, -tiny, 0), Vec3(4, -1, 1)},
       {Vec3(-2, -tiny, 0), Vec3(-1, -tiny, 0), Vec3(-1, -1, 1)}, false},
      // Triangle 1 (in the plane x = 1/2, y + z <= 0 with equality at vertex 3 only) moves
      // by (0, 2, -2): vertex 3 crosses face 0's edge y = 0 at (1/2, 0, 0) at t = 1/2, and
      // nothing else of it reaches face 0: grazing. Then the same 2^-30 further from it.
      {"grazes an edge", {Vec3(0.5, -1, 1), Vec3(0.5, -2, 1), Vec3(0.5, -1.5, 0.5)},
       {Vec3(0.5, 1, -1), Vec3(0.5, 0, -1), Vec3(0.5, 0.5, -1.5)}, true},
      {"passes beside an edge", {Vec3(0.5, -1 - tiny, 1), Vec3(0.5, -2 - tiny, 1), Vec3(0.5, -1.5 - tiny, 0.5)},
       {Vec3(0.5, 1 - tiny, -1), Vec3(0.5, -tiny, -1), Vec3(0.5, 0.5 - tiny, -1.5)}, false},
      // Coplanar: triangle 1 moves in the plane z = 0 into face 0.
      {"coplanar entering", {Vec3(2, 2, 0), Vec3(3, 2, 0), Vec3(2, 3, 0)},
       {Vec3(0.25, 0.25, 0), Vec3(1.25, 0.25, 0), Vec3(0.25, 1.25, 0)}, true},
      {"coplanar passing", {Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(2, 1, 0)},
       {Vec3(1 + tiny, 1, 0), Vec3(2, 1, 0), Vec3(1 + tiny, 2, 0)}, false},
  };
  for (const Case& c : cases)
    for (const Vec3& shift : {Vec3(0, 0, 0), Vec3(0x1p20, -0x1p20, 0x1p20)}) {
      INFO(c.name << ", shifted by " << shift.transpose());
      const MeshFramePair m = two_triangles(c.b0, c.b1, shift);
      VfList vf;
      EeList ee;
      exact_truth(m, 0.0, vf, ee);
      CHECK((vf.size() + ee.size() > 0) == c.contact);
      for (const char* culler : {"mesh_sweep", "brute", "bvh", "boxes:sap"}) {
        INFO(culler);
        MeshCcdOptions o;
        o.culler = culler;
        const MeshCcdResult r = mesh_ccd(m.x0, m.x1, m.faces, o);
        CHECK(includes(r.vf, vf));
        CHECK(includes(r.ee, ee));
        o.exact = true;
        const MeshCcdResult e = mesh_ccd(m.x0, m.x1, m.faces, o);
        CHECK(e.vf == vf);
        CHECK(e.ee == ee);
        CHECK(e.toi.has_value() == c.contact);
      }
    }
}

TEST_CASE("mesh ccd: the time of impact bounds the first contact", "[cloth][mesh_ccd]") {
  // Vertex 3 falls from z = 1 to z = -1 through face 0: first contact at t = 1/2 exactly.
  const MeshFramePair m = two_triangles({Vec3(0.25, 0.25, 1), Vec3(2, 2, 1), Vec3(2, 3, 1)},
                                        {Vec3(0.25, 0.25, -1), Vec3(2, 2, -1), Vec3(2, 3, -1)}, Vec3::Zero());
  const MeshCcdResult r = mesh_ccd(m.x0, m.x1, m.faces, {});
  REQUIRE(r.toi);
  // A lower bound (the kernel's first open time: possibly well before the contact), and a
  // certified time at or after the contact.
  CHECK(r.toi->time <= 0.5);
  CHECK(r.toi->time >= 0);
  CHECK(r.toi->time + r.toi->error >= 0.5);
  CHECK(r.toi->time + r.toi->error <= 1);
  CHECK(r.vf == VfList{{3, 0}});
  // Leaving a face at t = 0: toi 0.
  const MeshFramePair leave = two_triangles({Vec3(0.25, 0.25, 0), Vec3(2, 2, 1), Vec3(2, 3, 1)},
                                            {Vec3(0.25, 0.25, 1), Vec3(2, 2, 1), Vec3(2, 3, 1)}, Vec3::Zero());
  const MeshCcdResult l = mesh_ccd(leave.x0, leave.x1, leave.faces, {});
  REQUIRE(l.toi);
  CHECK(l.toi->time == 0);
  // Apart: no toi.
  const MeshFramePair apart = two_triangles({Vec3(0.25, 0.25, 1), Vec3(2, 2, 1), Vec3(2, 3, 1)},
                                            {Vec3(0.25, 0.25, 2), Vec3(2, 2, 2), Vec3(2, 3, 2)}, Vec3::Zero());
  CHECK_FALSE(mesh_ccd(apart.x0, apart.x1, apart.faces, {}).toi);
}

TEST_CASE("mesh ccd results do not depend on the thread count", "[cloth][mesh_ccd]") {
  for (const std::string_view name : mesh_frame_generators()) {
    INFO(name);
#ifdef CCDLAB_SANITIZED
    const MeshFramePair m = generate_mesh_frames(name, 2500);  // still several blocks
#else
    const MeshFramePair m = generate_mesh_frames(name, 6000);
#endif
    MeshCcdOptions o;
    o.separation = 0.001;
    o.keep_candidates = true;
    o.threads = 1;
    const MeshCcdResult one = mesh_ccd(m.x0, m.x1, m.faces, o);
    o.threads = 7;
    const MeshCcdResult seven = mesh_ccd(m.x0, m.x1, m.faces, o);
    CHECK(!one.vf.empty());
    CHECK(one.candidates.size() > 4096);  // several blocks
    CHECK(one.candidates == seven.candidates);
    CHECK(one.vf == seven.vf);
    CHECK(one.ee == seven.ee);
    CHECK(one.candidates_vf == seven.candidates_vf);
    CHECK(one.candidates_ee == seven.candidates_ee);
    REQUIRE(one.toi);
    REQUIRE(seven.toi);
    CHECK(one.toi->time == seven.toi->time);
    CHECK(one.toi->error == seven.toi->error);
  }
}

TEST_CASE("mesh ccd refuses bad input, naming the element", "[cloth][mesh_ccd]") {
  MeshFramePair m = generate_mesh_frames("crumpled", 8);
  auto message = [](const MeshFramePair& f, const MeshCcdOptions& o = {}) -> std::string {
    try {
      mesh_ccd(f.x0, f.x1, f.faces, o);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no error";
  };
  MeshFramePair bad = m;
  bad.x1[7].y() = std::nan("");
  CHECK(message(bad) == "frame 1: vertex 7: coordinate not finite");
  bad = m;
  bad.x1.pop_back();
  CHECK(message(bad) == "the frames have different vertex counts (" + std::to_string(m.x0.size()) + " and " +
                            std::to_string(m.x0.size() - 1) + ")");
  bad = m;
  bad.faces[3][1] = 9001;
  CHECK(message(bad) == "face 3: vertex index 9001 out of range (" + std::to_string(m.x0.size()) + " vertices)");
  bad = m;
  bad.faces[2] = {4, 5, 4};
  CHECK(message(bad) == "face 2: vertex 4 repeated");
  MeshCcdOptions o;
  o.culler = "nope";
  CHECK(message(m, o) == "unknown culler 'nope'");
  o.culler = "mesh_sweep";
  o.separation = -1;
  CHECK(message(m, o) == "separation must be a finite number >= 0");
}

}  // namespace cloth_mesh_ccd_mesh_ccd_test
