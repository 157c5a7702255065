#include "mesh_check.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace ccd::cloth {

void check_mesh_for_writing(const TriangleMesh& mesh, bool as_float, const char* writer) {
  const double largest = as_float ? static_cast<double>(std::numeric_limits<float>::max()) : std::numeric_limits<double>::max();
  if (mesh.vertices.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument(std::string(writer) + ": more than 4294967295 vertices");
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double v = mesh.vertices[i][k];
      if (!(std::fabs(v) <= largest))
        throw std::invalid_argument(std::string(writer) + ": vertex " + std::to_string(i) + ": " + "xyz"[k] +
                                    (std::isnan(v) ? " is NaN" : as_float ? " is beyond the float range" : " is infinite"));
    }
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    for (std::uint32_t v : mesh.faces[f])
      if (v >= mesh.vertices.size())
        throw std::invalid_argument(std::string(writer) + ": face " + std::to_string(f) + ": vertex index " + std::to_string(v) +
                                    " out of range (" + std::to_string(mesh.vertices.size()) + " vertices)");
}

}  // namespace ccd::cloth
