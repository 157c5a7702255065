#pragma once
// Static scenery: planar, convex, two-sided polygons that never move (floors, ramps,
// obstacles). A sphere touches a polygon when the distance from its centre to the polygon
// (the closed convex set, face and boundary) is at most its radius. The scene field
// `scenery` lists polygons, and an optional mesh adds triangles numbered after them
// (docs/scenery.md); scene_io validates them (planar within a tolerance, convex, no
// repeated or collinear vertices) and fills the derived plane.
#include <ccd/geometry/vec3.hpp>
#include <ccd/shape/convex_proxy.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ccd {

struct StaticPolygon {
  /// Vertices in order around the polygon (3 or more), counter-clockwise seen from
  /// `normal`'s side.
  std::vector<Vec3> vertices;
  /// Unit normal of the polygon's plane (derived from the vertices by scene_io).
  Vec3 normal{Vec3::Zero()};
  /// The plane is { x : normal . x == offset }.
  double offset = 0.0;
};

/// The polygon as a convex shape at rest for the rigid-body solvers (convex_distance,
/// conservative advancement): its vertices as they are (the polygon must outlive the
/// proxy), radius 0, posed with the identity at the origin.
inline ConvexProxy polygon_proxy(const StaticPolygon& polygon) { return ConvexProxy{polygon.vertices, 0.0}; }

/// Many triangles at once (the scene field `scenery_mesh`): shared vertices and index
/// triples. The reader appends one StaticPolygon per triangle to Scene::scenery, after the
/// `scenery` polygons, and keeps the mesh so that the scene is written back as it was read.
struct SceneryMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

/// Largest distance of a vertex from the polygon's plane, relative to the polygon's size
/// (its largest vertex-to-vertex distance), that is still accepted as planar. Also the
/// relative distance under which a vertex counts as repeated or collinear with its
/// neighbours.
inline constexpr double kPolygonTolerance = 1e-9;

/// The polygon through `vertices` with its derived plane: the unit area normal
/// n = normalize(sum_i (v_i - v_0) x (v_{i+1} - v_0)) (so the vertices run
/// counter-clockwise seen from n) and offset = n . v_0. The normal is zero when the area
/// is zero (a degenerate polygon: polygon_defect says why).
StaticPolygon polygon_from_vertices(std::vector<Vec3> vertices);

/// What makes `vertices` unacceptable as a static polygon, or nullopt: fewer than 3
/// vertices, a non-finite coordinate, a repeated vertex, three consecutive collinear
/// vertices, a vertex farther than kPolygonTolerance x size from the plane, or a
/// non-convex outline (some vertex on the outer side of an edge). `vertex` is the index
/// the reason is about (-1 for the whole polygon).
struct PolygonDefect {
  std::ptrdiff_t vertex = -1;
  std::string reason;
};
std::optional<PolygonDefect> polygon_defect(const std::vector<Vec3>& vertices);

}  // namespace ccd
