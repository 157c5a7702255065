#pragma once
// `sensors`: particle sensors that flag where the hierarchy must look (after the idea of
// Sugihara and Savchenko 2007: sensors on the particles detect approaching, non-neighbouring
// parts of the cloth, and only what they flag goes to polygon-polygon tests). The rule
// implemented here is our own:
//
// Reach. Every point of a triangle is within 2/3 of its longest edge of one of its corners
// (the corner of largest barycentric weight b >= 1/3 is at most (1 - b) L away), every
// point of an edge within half its length of an end, and a vertex is its own point. Edge
// lengths are convex in t under linear motion, so their largest value over the interval is
// at one end. A vertex's sensor radius r is the largest reach of the triangles around it.
//
// Sensors. A vertex's sensor box holds its path over the interval (its swept box), widened
// by r + separation / 2 (rounded outwards). If a point p of primitive A and a point q of B
// come within the separation at time t, their nearest corners u of A and w of B satisfy
// |u(t) - w(t)| <= separation + r_u + r_w, so the sensor boxes of u and w overlap. The
// sensor boxes go through the `grid` broad phase (kept between calls). A pair of sensors
// fires when the boxes overlap and the two vertices are more than two edges apart in the
// mesh; both vertices are then flagged.
//
// Hierarchy. The bvh (cloth/cull/bvh_culler.hpp, refitted between calls) keeps only pairs of
// primitives that both have a flagged vertex, and skips subtrees with none.
//
// Guarantee: NOT conservative. A pair is dropped only when all its pairs of corners whose
// sensors meet are within two edges of each other in the mesh: the cloth must fold back
// onto itself within about two edge lengths (or a long sliver triangle must reach
// far from its corners' rings). Its tests prove every dropped pair contact-free on the
// cloth scenes with exact CCD at separation 0.
#include <cloth/cull/bvh_culler.hpp>
#include <ccd/broad_phase/broad_phase.hpp>

#include <memory>

namespace ccd::cloth {

class SensorCuller final : public Culler {
 public:
  SensorCuller();
  std::vector<Candidate> cull(const ClothMesh& mesh, std::span<const Vec3> x0, std::span<const Vec3> x1,
                              double separation) override;
  /// "flagged": vertices flagged by a sensor; "sensor_pairs": overlapping sensor boxes;
  /// then the bvh's counters.
  std::vector<CullerCounter> counters() const override;

 private:
  BvhCuller bvh_{false};
  std::unique_ptr<BroadPhase> grid_;
  std::vector<std::array<std::uint32_t, 2>> edges_;  // the mesh the rings below are for
  std::vector<std::vector<std::uint32_t>> ring2_;    // per vertex: sorted, within two edges
  std::vector<Aabb> boxes_;
  std::vector<BodyPair> pairs_;
  std::vector<std::uint8_t> flagged_;
  std::uint64_t flagged_count_ = 0, sensor_pairs_ = 0;
};

}  // namespace ccd::cloth
