// The exact mesh truth on hand-built dyadic meshes whose contacts are known, the box filter
// against brute force on a cloth, and the truth file.
#include <cloth/sim/cloth_simulator.hpp>
#include <cloth/truth/mesh_truth.hpp>
#include <cloth/truth/mesh_truth_file.hpp>
#include <ccd/io/input_error.hpp>

#include <catch2/catch.hpp>
#include <random>

namespace cloth_truth_mesh_truth_test {

using namespace ccd::cloth;
using ccd::Vec3;

namespace {

// Two separate triangles: A = (0, 1, 2), B = (3, 4, 5). Edges: 0 (0,1), 1 (0,2), 2 (1,2),
// 3 (3,4), 4 (3,5), 5 (4,5).
ClothMesh two_triangles() {
  ClothMesh m;
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  m.edges = {{0, 1}, {0, 2}, {1, 2}, {3, 4}, {3, 5}, {4, 5}};
  return m;
}

// A = (0,0,0), (1,0,0), (0,1,0) still. B in the plane y = 1/4: p = (1/4, 1/4, z) above A's
// interior, q = p + (0, 0, 8), r = (33/4, 1/4, z). When z = 0, p is in A's interior and the
// edge pr crosses A's hypotenuse (edge 2) at (3/4, 1/4, 0); no other pair comes near
// (q stays 7 above, r is outside A, the plane y = 1/4 is 1/4 from A's corners).
std::vector<Vec3> falling(double z, const Vec3& offset = Vec3::Zero()) {
  return {Vec3(0, 0, 0) + offset,         Vec3(1, 0, 0) + offset,          Vec3(0, 1, 0) + offset,
          Vec3(0.25, 0.25, z) + offset,   Vec3(0.25, 0.25, z + 8) + offset, Vec3(8.25, 0.25, z) + offset};
}

const Candidate kVertexFace{PrimitivePair::VertexFace, 3, 0};
const Candidate kEdgeEdge{PrimitivePair::EdgeEdge, 2, 4};

std::vector<std::vector<Vec3>> frames_at(std::initializer_list<double> zs, const Vec3& offset = Vec3::Zero()) {
  std::vector<std::vector<Vec3>> f;
  for (double z : zs) f.push_back(falling(z, offset));
  return f;
}

}  // namespace

TEST_CASE("mesh truth: a vertex through a face and an edge across an edge, in one step", "[cloth][truth]") {
  const ClothMesh mesh = two_triangles();
  for (const Vec3& offset : {Vec3(0, 0, 0), Vec3(0x1p20, -0x1p20, 0x1p21)}) {  // and far from the origin
    CAPTURE(offset.transpose());
    const auto frames = frames_at({1, 0.5, -0.5, -1}, offset);
    const MeshTruth t = compute_mesh_truth(mesh, frames, 0.0);
    REQUIRE(t.step_contacts.size() == 3);
    REQUIRE(t.state_contacts.size() == 4);
    CHECK(t.step_contacts[0].empty());
    CHECK(t.step_contacts[1] == std::vector<Candidate>{kVertexFace, kEdgeEdge});  // sorted: vf before ee
    CHECK(t.step_contacts[2].empty());
    for (const auto& s : t.state_contacts) CHECK(s.empty());  // z = 0 falls between states
    const auto events = contact_events(t);
    REQUIRE(events.size() == 2);
    CHECK(events[0].pair == kVertexFace);
    CHECK(events[0].first_step == 1);
    CHECK(events[0].last_step == 1);
    CHECK(events[1].pair == kEdgeEdge);
    // The box filter drops nothing brute force keeps.
    for (std::size_t s = 0; s + 1 < frames.size(); ++s)
      CHECK(interval_contacts(mesh, frames[s], frames[s + 1], 0.0) ==
            contacts_among(mesh, brute_force_candidates(mesh, 6), frames[s], frames[s + 1], 0.0));
  }
}

TEST_CASE("mesh truth: a contact exactly at a state counts in both steps, separate runs are separate events",
          "[cloth][truth]") {
  const ClothMesh mesh = two_triangles();
  // z: 1 -> 0 (touching exactly at state 1) -> 1 -> 1/2 -> -1/2 (through again in step 3).
  const MeshTruth t = compute_mesh_truth(mesh, frames_at({1, 0, 1, 0.5, -0.5}), 0.0);
  const std::vector<Candidate> both{kVertexFace, kEdgeEdge};
  CHECK(t.step_contacts[0] == both);
  CHECK(t.step_contacts[1] == both);
  CHECK(t.step_contacts[2].empty());
  CHECK(t.step_contacts[3] == both);
  CHECK(t.state_contacts[0].empty());
  CHECK(t.state_contacts[1] == both);
  CHECK(t.state_contacts[2].empty());
  CHECK(t.state_contacts[4].empty());
  const auto events = contact_events(t);
  REQUIRE(events.size() == 4);  // sorted by first step, then pair
  CHECK((events[0].pair == kVertexFace && events[0].first_step == 0 && events[0].last_step == 1));
  CHECK((events[1].pair == kEdgeEdge && events[1].first_step == 0 && events[1].last_step == 1));
  CHECK((events[2].pair == kVertexFace && events[2].first_step == 3 && events[2].last_step == 3));
  CHECK((events[3].pair == kEdgeEdge && events[3].first_step == 3 && events[3].last_step == 3));
}

TEST_CASE("mesh truth: distance exactly the thickness is a contact, 2^-30 less is not (still, far away)",
          "[cloth][truth]") {
  const ClothMesh mesh = two_triangles();
  // Still: p hovers 1/8 above A's interior. With r moved to (1/4, 33/4, 65/8), B lies in
  // the plane x = 1/4, at least 1/4 from A's corners; B's edges are at least 1/4 from A's
  // edges (pq stands over (1/4, 1/4); pr climbs away, 5 / (8 sqrt 3) from the hypotenuse's
  // line); q and r are 8 above A. Only the pair (p, A) comes within 1/4.
  for (const Vec3& offset : {Vec3(0, 0, 0), Vec3(0x1p20, -0x1p20, 0x1p21)}) {
    CAPTURE(offset.transpose());
    std::vector<Vec3> x = falling(0.125, offset);
    x[5] = Vec3(0.25, 8.25, 8.125) + offset;
    const std::vector<std::vector<Vec3>> frames(3, x);  // zero velocity
    const MeshTruth at = compute_mesh_truth(mesh, frames, 0.125);
    for (const auto& s : at.step_contacts) CHECK(s == std::vector<Candidate>{kVertexFace});
    for (const auto& s : at.state_contacts) CHECK(s == std::vector<Candidate>{kVertexFace});
    const auto events = contact_events(at);
    REQUIRE(events.size() == 1);  // one event over every step
    CHECK(events[0].first_step == 0);
    CHECK(events[0].last_step == 1);
    const MeshTruth below = compute_mesh_truth(mesh, frames, 0.125 - 0x1p-30);
    for (const auto& s : below.step_contacts) CHECK(s.empty());
    for (const auto& s : below.state_contacts) CHECK(s.empty());
    // How the pairs were decided: a touch at exactly the thickness is beyond any
    // floating-point proof, so it reaches the exact reference (2^-30 apart, the gap is
    // along z: the box filter skips the pair).
    for (const MeshTruth* t : {&at, &below})
      CHECK(t->counts.pairs == t->counts.within + t->counts.apart + t->counts.exact);
    CHECK(at.counts.exact > 0);
    CHECK(at.counts.within == 0);
    CHECK(below.counts.exact == 0);
    // 2^-10 nearer than the thickness: proved within, no exact reference.
    const MeshTruth within = compute_mesh_truth(mesh, frames, 0.125 + 0x1p-10);
    for (const auto& s : within.step_contacts) CHECK(s == std::vector<Candidate>{kVertexFace});
    CHECK(within.counts.within > 0);
    CHECK(within.counts.exact == 0);
  }
}

TEST_CASE("mesh truth: the box filter equals brute force on a crumpled grid, whatever the threads",
          "[cloth][truth]") {
  // A 4 x 4 grid's mesh with every vertex at a random dyadic point of the unit cube (k / 32),
  // then moved by up to 1/32 per coordinate in each of two steps: many pairs touch, many
  // pass near.
  const ClothScene s = builtin_cloth_scene("pile", 4);
  const ClothMesh mesh = make_grid_mesh(s);
  std::mt19937_64 rng(16);
  std::uniform_int_distribution<int> coord(0, 32), step(-1, 1);
  std::vector<std::vector<Vec3>> frames(3, std::vector<Vec3>(s.particle_count()));
  for (Vec3& x : frames[0]) x = Vec3(coord(rng), coord(rng), coord(rng)) / 32.0;
  for (std::size_t k = 1; k < frames.size(); ++k)
    for (std::size_t v = 0; v < frames[k].size(); ++v)
      frames[k][v] = frames[k - 1][v] + Vec3(step(rng), step(rng), step(rng)) / 32.0;
  const double d = 1.0 / 16;
  const auto all = brute_force_candidates(mesh, s.particle_count());
  std::size_t contacts = 0;
  for (std::size_t k = 0; k + 1 < frames.size(); ++k) {
    const auto fast = interval_contacts(mesh, frames[k], frames[k + 1], d);
    CHECK(fast == contacts_among(mesh, all, frames[k], frames[k + 1], d));
    contacts += fast.size();
  }
  CHECK(contacts > 0);  // the comparison is not vacuous
  CHECK(contacts < 3 * all.size());  // nor trivial
  const MeshTruth one = compute_mesh_truth(mesh, frames, d, 1);
  const MeshTruth two = compute_mesh_truth(mesh, frames, d, 2);
  CHECK(one.step_contacts == two.step_contacts);
  CHECK(one.state_contacts == two.state_contacts);
  for (std::size_t k = 0; k < frames.size(); ++k)  // a still pair within d is a contact of its state
    CHECK(one.state_contacts[k] == contacts_among(mesh, all, frames[k], frames[k], d));
}

TEST_CASE("mesh truth file: round trip, and a stale or malformed file is refused with its field",
          "[cloth][truth]") {
  const ClothMesh mesh = two_triangles();
  const auto frames = frames_at({1, 0, 1, 0.5, -0.5});
  const MeshTruth t = compute_mesh_truth(mesh, frames, 0.0);
  const std::string digest = motion_digest(mesh, frames, 0.0);
  CHECK(digest.size() == 64);
  CHECK(digest != motion_digest(mesh, frames, 0x1p-30));  // the thickness is part of the motion's truth
  auto moved = frames;
  moved[2][4].x() = std::nextafter(moved[2][4].x(), 1.0);
  CHECK(digest != motion_digest(mesh, moved, 0.0));
  const nlohmann::json j = mesh_truth_to_json(t, digest);
  const MeshTruth back = mesh_truth_from_json(j, "t.json", mesh, 6, digest);
  CHECK(back.step_contacts == t.step_contacts);
  CHECK(back.state_contacts == t.state_contacts);
  CHECK(back.thickness == t.thickness);
  auto refused = [&](nlohmann::json bad, const std::string& field) {
    try {
      mesh_truth_from_json(bad, "t.json", mesh, 6, digest);
      FAIL("accepted");
    } catch (const ccd::InputError& e) {
      CHECK(e.field() == field);
    }
  };
  refused(mesh_truth_to_json(t, std::string(64, '0')), "digest");
  nlohmann::json adjacent = j;
  adjacent["step_contacts"][0] = {0, 0, 0};  // vertex 0 of its own triangle
  refused(adjacent, "step_contacts[0][0]");
  nlohmann::json unsorted = j;
  unsorted["step_contacts"][0] = {1, 2, 4, 0, 3, 0};
  refused(unsorted, "step_contacts[0][3]");
  nlohmann::json out_of_range = j;
  out_of_range["state_contacts"][1] = {0, 6, 0};
  refused(out_of_range, "state_contacts[1][0]");
  nlohmann::json short_list = j;
  short_list["state_contacts"].erase(0);
  refused(short_list, "state_contacts");
  nlohmann::json unknown = j;
  unknown["extra"] = 1;
  refused(unknown, "extra");
}

}  // namespace cloth_truth_mesh_truth_test
