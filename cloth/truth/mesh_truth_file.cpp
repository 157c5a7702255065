#include "mesh_truth_file.hpp"

#include <ccd/io/json_reader.hpp>
#include <ccd/util/sha256.hpp>

#include <cstring>

namespace ccd::cloth {

namespace {

template <class T>
void append_bytes(std::string& out, const T& value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

nlohmann::json flat(const std::vector<Candidate>& list) {
  nlohmann::json out = nlohmann::json::array();
  for (const Candidate& c : list) {
    out.push_back(c.kind == PrimitivePair::VertexFace ? 0 : 1);
    out.push_back(c.a);
    out.push_back(c.b);
  }
  return out;
}

std::vector<Candidate> read_list(const JsonReader& r, const nlohmann::json& v, const std::string& field,
                                 const ClothMesh& mesh, std::size_t vertex_count) {
  if (!v.is_array()) r.fail(field, "must be an array");
  if (v.size() % 3 != 0) r.fail(field, "must hold triples (kind, a, b)");
  std::vector<Candidate> out;
  for (std::size_t i = 0; i < v.size(); i += 3) {
    const std::string at = field + "[" + std::to_string(i) + "]";
    const auto kind = r.integer(v[i], at, 0, 1);
    const std::uint32_t a = r.index(v[i + 1], field + "[" + std::to_string(i + 1) + "]");
    const std::uint32_t b = r.index(v[i + 2], field + "[" + std::to_string(i + 2) + "]");
    const Candidate c{kind == 0 ? PrimitivePair::VertexFace : PrimitivePair::EdgeEdge, a, b};
    const bool in_range = kind == 0 ? a < vertex_count && b < mesh.triangles.size()
                                    : a < b && b < mesh.edges.size();
    if (!in_range) r.fail(at, "not a vertex-face or edge-edge pair of this mesh");
    if (adjacent(mesh, c)) r.fail(at, "adjacent primitives are never contacts");
    if (!out.empty() && !(out.back() < c)) r.fail(at, "pairs must be sorted and unique");
    out.push_back(c);
  }
  return out;
}

}  // namespace

std::string motion_digest(const ClothMesh& mesh, std::span<const std::vector<Vec3>> frames, double thickness) {
  std::string bytes = kMeshTruthFormat;
  append_bytes(bytes, mesh.triangles.size());
  for (const auto& t : mesh.triangles) append_bytes(bytes, t);
  append_bytes(bytes, mesh.edges.size());
  for (const auto& e : mesh.edges) append_bytes(bytes, e);
  append_bytes(bytes, frames.size());
  for (const auto& f : frames) {
    append_bytes(bytes, f.size());
    for (const Vec3& x : f)
      for (int i = 0; i < 3; ++i) append_bytes(bytes, x[i]);
  }
  append_bytes(bytes, thickness);
  return sha256_hex(bytes);
}

nlohmann::json mesh_truth_to_json(const MeshTruth& truth, const std::string& digest) {
  nlohmann::json j;
  j["format"] = kMeshTruthFormat;
  j["digest"] = digest;
  j["thickness"] = truth.thickness;
  j["steps"] = truth.step_contacts.size();
  j["step_contacts"] = nlohmann::json::array();
  for (const auto& l : truth.step_contacts) j["step_contacts"].push_back(flat(l));
  j["state_contacts"] = nlohmann::json::array();
  for (const auto& l : truth.state_contacts) j["state_contacts"].push_back(flat(l));
  return j;
}

MeshTruth mesh_truth_from_json(const nlohmann::json& j, const std::string& file, const ClothMesh& mesh,
                               std::size_t vertex_count, const std::string& digest) {
  const JsonReader r{file};
  if (!j.is_object()) r.fail("", "must be a JSON object");
  r.only_fields(j, "", {"format", "digest", "thickness", "steps", "step_contacts", "state_contacts"});
  if (r.string(r.require(j, "format", ""), "format") != kMeshTruthFormat)
    r.fail("format", std::string("must be \"") + kMeshTruthFormat + "\"");
  if (r.string(r.require(j, "digest", ""), "digest") != digest)
    r.fail("digest", "is not the digest of this motion (another scene, step count or thickness)");
  MeshTruth t;
  t.thickness = r.number(r.require(j, "thickness", ""), "thickness");
  const auto steps = r.count(r.require(j, "steps", ""), "steps", 1000000);
  const auto& step = r.require(j, "step_contacts", "");
  const auto& state = r.require(j, "state_contacts", "");
  if (!step.is_array() || step.size() != steps) r.fail("step_contacts", "must be an array of `steps` lists");
  if (!state.is_array() || state.size() != steps + 1) r.fail("state_contacts", "must be an array of `steps` + 1 lists");
  for (std::size_t s = 0; s < step.size(); ++s)
    t.step_contacts.push_back(read_list(r, step[s], "step_contacts[" + std::to_string(s) + "]", mesh, vertex_count));
  for (std::size_t s = 0; s < state.size(); ++s)
    t.state_contacts.push_back(read_list(r, state[s], "state_contacts[" + std::to_string(s) + "]", mesh, vertex_count));
  return t;
}

}  // namespace ccd::cloth
