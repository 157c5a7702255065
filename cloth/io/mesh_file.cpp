#include "mesh_file.hpp"

#include <cloth/io/obj_reader.hpp>
#include <cloth/io/ply_header.hpp>
#include <cloth/io/ply_reader.hpp>
#include <cloth/io/regular_file.hpp>

#include <ccd/io/input_error.hpp>
#include <ccd/util/parallel_for.hpp>

#include <algorithm>
#include <cctype>
#include <exception>

namespace ccd::cloth {

namespace {

bool named_ply(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".ply";
}

std::string face_text(const std::array<std::uint32_t, 3>& f) {
  std::string out(1, '(');
  for (std::size_t k = 0; k < 3; ++k) {
    out += std::to_string(f[k]);
    out += k < 2 ? ", " : ")";
  }
  return out;
}

}  // namespace

TriangleMesh read_mesh(const std::string& path) {
  const std::string bytes = read_regular_file(path);
  if (has_ply_magic(bytes) || named_ply(path)) return parse_ply(bytes, path);
  return parse_obj(bytes, path);
}

MeshFrames mesh_frames(TriangleMesh frame0, TriangleMesh frame1, const std::string& name0, const std::string& name1) {
  if (frame0.vertices.size() != frame1.vertices.size())
    throw InputError(name1, "", "has " + std::to_string(frame1.vertices.size()) + " vertices, " + name0 + " has " +
                                    std::to_string(frame0.vertices.size()) + " (frames of one mesh have the same vertices)");
  if (frame0.faces.size() != frame1.faces.size())
    throw InputError(name1, "", "has " + std::to_string(frame1.faces.size()) + " faces, " + name0 + " has " +
                                    std::to_string(frame0.faces.size()) + " (frames of one mesh have the same faces)");
  const auto [a, b] = std::mismatch(frame0.faces.begin(), frame0.faces.end(), frame1.faces.begin());
  if (a != frame0.faces.end()) {
    const auto i = std::to_string(a - frame0.faces.begin());
    throw InputError(name1, "face " + i, face_text(*b) + " differs from " + name0 + "'s face " + i + " " + face_text(*a));
  }
  return MeshFrames{std::move(frame0.vertices), std::move(frame1.vertices), std::move(frame0.faces)};
}

MeshFrames read_mesh_frames(const std::string& path0, const std::string& path1, unsigned threads) {
  std::array<TriangleMesh, 2> frames;
  std::array<std::exception_ptr, 2> errors;
  const std::array<const std::string*, 2> paths{&path0, &path1};
  parallel_for(2, threads, [&](std::size_t k, unsigned) {
    try {
      frames[k] = read_mesh(*paths[k]);
    } catch (...) {
      errors[k] = std::current_exception();
    }
  });
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
  return mesh_frames(std::move(frames[0]), std::move(frames[1]), path0, path1);
}

}  // namespace ccd::cloth
