#include "sensor_culler.hpp"

#include <cloth/cull/primitive_boxes.hpp>
#include <ccd/broad_phase/registry.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ccd::cloth {

SensorCuller::SensorCuller() : grid_(find_broad_phase("grid").make()) {}

std::vector<Candidate> SensorCuller::cull(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1,
                                          double separation) {
  if (x0.size() != x1.size()) throw std::invalid_argument("sensors culler: x0 and x1 differ in size");
  for (std::size_t i = 0; i < x0.size(); ++i)
    if (!x0[i].allFinite() || !x1[i].allFinite())
      throw std::invalid_argument("sensors culler: positions must be finite");
  const std::size_t n = x0.size();
  if (ring2_.size() != n || edges_ != mesh.edges) {
    edges_ = mesh.edges;
    std::vector<std::vector<std::uint32_t>> ring1(n);
    for (const auto& e : mesh.edges) {
      ring1[e[0]].push_back(e[1]);
      ring1[e[1]].push_back(e[0]);
    }
    ring2_.assign(n, {});
    for (std::size_t v = 0; v < n; ++v) {
      auto& r = ring2_[v];
      for (std::uint32_t w : ring1[v]) {
        r.push_back(w);
        r.insert(r.end(), ring1[w].begin(), ring1[w].end());
      }
      std::sort(r.begin(), r.end());
      r.erase(std::unique(r.begin(), r.end()), r.end());
    }
  }

  // Sensor radii: the largest reach of the triangles around each vertex, rounded up.
  std::vector<double> radius(n, 0.0);
  for (const auto& t : mesh.triangles) {
    double longest = 0;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      longest = std::max({longest, (x0[a] - x0[b]).norm(), (x1[a] - x1[b]).norm()});
    }
    // A relative margin of 2^-40 covers the rounding of the norms and of the product.
    const double reach = longest * (2.0 / 3.0) * (1 + 0x1p-40);
    for (std::uint32_t v : t) radius[v] = std::max(radius[v], reach);
  }
  constexpr double inf = std::numeric_limits<double>::infinity();
  vertex_boxes(x0, x1, 0.0, boxes_);
  for (std::size_t v = 0; v < n; ++v) {
    const double widen = radius[v] + separation / 2;
    for (int k = 0; k < 3; ++k) {
      boxes_[v].lo[k] = std::nextafter(boxes_[v].lo[k] - widen, -inf);
      boxes_[v].hi[k] = std::nextafter(boxes_[v].hi[k] + widen, inf);
    }
  }
  grid_->find_pairs(boxes_, pairs_);
  sensor_pairs_ = pairs_.size();
  flagged_.assign(n, 0);
  for (const BodyPair& p : pairs_) {
    const auto& r = ring2_[p.a];
    if (std::binary_search(r.begin(), r.end(), p.b)) continue;  // neighbours: not a fold
    flagged_[p.a] = flagged_[p.b] = 1;
  }
  flagged_count_ = static_cast<std::uint64_t>(std::count(flagged_.begin(), flagged_.end(), 1));
  return bvh_.cull_active(mesh, x0, x1, separation, flagged_);
}

std::vector<CullerCounter> SensorCuller::counters() const {
  std::vector<CullerCounter> c = {{"flagged", flagged_count_}, {"sensor_pairs", sensor_pairs_}};
  for (const CullerCounter& b : bvh_.counters()) c.push_back(b);
  return c;
}

}  // namespace ccd::cloth
