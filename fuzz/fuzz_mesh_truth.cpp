// The cloth truth reader (`ccdlab-cloth-truth/1`, cloth/truth/mesh_truth_file.hpp), checked
// against a 4 x 4 grid mesh (16 vertices, 18 triangles, 33 edges) and a fixed motion digest,
// kDigest (the seeds and the dictionary carry it).
//
// Invariants: every accepted pair is a pair of this mesh, not adjacent, and the lists are
// sorted and unique; an accepted file is written and read back to the same lists.
#include "fuzz_support.hpp"

#include <ccd/io/json_reader.hpp>
#include <ccd/io/input_error.hpp>
#include <cloth/cull/candidate.hpp>
#include <cloth/sim/cloth_mesh.hpp>
#include <cloth/sim/cloth_scene.hpp>
#include <cloth/truth/mesh_truth_file.hpp>

namespace {

constexpr const char* kDigest = "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855";

const ccd::cloth::ClothMesh& grid_mesh() {
  static const ccd::cloth::ClothMesh mesh = [] {
    ccd::cloth::ClothScene scene;
    scene.nx = scene.ny = 4;
    return ccd::cloth::make_grid_mesh(scene);
  }();
  return mesh;
}

void check_lists(const std::vector<std::vector<ccd::cloth::Candidate>>& lists) {
  const ccd::cloth::ClothMesh& mesh = grid_mesh();
  for (const auto& list : lists)
    for (std::size_t i = 0; i < list.size(); ++i) {
      const ccd::cloth::Candidate& c = list[i];
      if (c.kind == ccd::cloth::PrimitivePair::VertexFace)
        FUZZ_CHECK(c.a < 16 && c.b < mesh.triangles.size());
      else
        FUZZ_CHECK(c.a < c.b && c.b < mesh.edges.size());
      FUZZ_CHECK(!ccd::cloth::adjacent(mesh, c));
      if (i > 0) FUZZ_CHECK(list[i - 1] < c);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  ccd::cloth::MeshTruth truth;
  try {
    truth = ccd::cloth::mesh_truth_from_json(ccd::parse_json_text(ccdfuzz::as_text(data, size), "fuzz.json"),
                                             "fuzz.json", grid_mesh(), 16, kDigest);
  } catch (const ccd::InputError&) {
    return 0;
  }
  FUZZ_CHECK(truth.state_contacts.size() == truth.step_contacts.size() + 1);
  check_lists(truth.step_contacts);
  check_lists(truth.state_contacts);
  const ccd::cloth::MeshTruth again = ccd::cloth::mesh_truth_from_json(
      ccd::parse_json_text(ccd::cloth::mesh_truth_to_json(truth, kDigest).dump(), "again"), "again", grid_mesh(), 16,
      kDigest);
  FUZZ_CHECK(again.thickness == truth.thickness);
  FUZZ_CHECK(again.step_contacts == truth.step_contacts && again.state_contacts == truth.state_contacts);
  return 0;
}
