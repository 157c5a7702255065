#include "hard_queries.hpp"

#include <cmath>

namespace ccd::cloth {
namespace {

LinearQuery make(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& q0, const Vec3& q1,
                 const Vec3& q2, const Vec3& q3) {
  return LinearQuery{{p0, p1, p2, p3, q0, q1, q2, q3}};
}

// The same motion for all four points shifted by `d` (far from the origin).
LinearQuery shifted(LinearQuery q, const Vec3& d) {
  for (Vec3& p : q.x) p += d;
  return q;
}

const double kTiny = std::ldexp(1.0, -30);  // about 9.3e-10

std::vector<NamedQuery> vertex_face() {
  const Vec3 f0(0, 0, 0), f1(1, 0, 0), f2(0, 1, 0);
  // A static unit right triangle in z = 0 and a vertex moving from (x, y, z0) to (x, y, z1).
  auto through = [&](double x, double y, double z0, double z1) {
    return make(Vec3(x, y, z0), f0, f1, f2, Vec3(x, y, z1), f0, f1, f2);
  };
  std::vector<NamedQuery> v = {
      {"vf_through_interior", through(0.25, 0.25, 1, -1), true},
      {"vf_through_edge_midpoint", through(0.5, 0, 1, -1), true},  // vertex on an edge
      {"vf_through_hypotenuse", through(0.5, 0.5, 1, -1), true},
      {"vf_through_corner", through(0, 0, 1, -1), true},
      {"vf_beside_edge_by_2^-30", through(-kTiny, 0.5, 1, -1), false},
      {"vf_beside_hypotenuse_by_2^-30", through(0.5 + kTiny, 0.5, 1, -1), false},
      {"vf_beside_corner_by_2^-30", through(-kTiny, -kTiny, 1, -1), false},
      {"vf_contact_at_t1", through(0.25, 0.25, 1, 0), true},
      {"vf_stops_2^-30_short_at_t1", through(0.25, 0.25, 1, kTiny), false},
      {"vf_contact_at_t0_leaving", through(0.25, 0.25, 0, 1), true},
      {"vf_starts_2^-30_above_leaving", through(0.25, 0.25, kTiny, 1), false},
      {"vf_zero_motion_in_face", through(0.25, 0.25, 0, 0), true},
      {"vf_zero_motion_above", through(0.25, 0.25, 0.5, 0.5), false},
      {"vf_parallel_above", make(Vec3(-1, 0.25, kTiny), f0, f1, f2, Vec3(2, 0.25, kTiny), f0, f1, f2), false},
      {"vf_coplanar_across", make(Vec3(-1, 0.25, 0), f0, f1, f2, Vec3(2, 0.25, 0), f0, f1, f2), true},
      {"vf_coplanar_beside", make(Vec3(-1, -kTiny, 0), f0, f1, f2, Vec3(2, -kTiny, 0), f0, f1, f2), false},
      {"vf_coplanar_along_edge", make(Vec3(-1, 0, 0), f0, f1, f2, Vec3(2, 0, 0), f0, f1, f2), true},
      {"vf_coplanar_touch_corner", make(Vec3(-1, 1, 0), f0, f1, f2, Vec3(1, -1, 0), f0, f1, f2), true},  // passes f0
      // Triangle moving up, vertex moving down: they meet at t = 1/2.
      {"vf_both_moving", make(Vec3(0.25, 0.25, 1), Vec3(0, 0, -1), Vec3(1, 0, -1), Vec3(0, 1, -1), Vec3(0.25, 0.25, -1),
                              Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1)),
       true},
      // The triangle tilts (one corner rises) while the vertex stays: the plane sweeps the
      // vertex only beyond the triangle.
      {"vf_tilting_face_misses", make(Vec3(0.75, 0.75, 0.25), f0, f1, f2, Vec3(0.75, 0.75, 0.25), f0, Vec3(1, 0, 1), f2),
       false},
      {"vf_tilting_face_hits", make(Vec3(0.5, 0.25, 0.25), f0, f1, f2, Vec3(0.5, 0.25, 0.25), f0, Vec3(1, 0, 1), f2),
       true},
      // Degenerate triangles: collinear corners (a segment) and one point.
      {"vf_collinear_face_crossed", make(Vec3(0.5, 1, 0), f0, f1, Vec3(0.25, 0, 0), Vec3(0.5, -1, 0), f0, f1, Vec3(0.25, 0, 0)),
       true},
      {"vf_collinear_face_missed",
       make(Vec3(0.5, 1, kTiny), f0, f1, Vec3(0.25, 0, 0), Vec3(0.5, -1, kTiny), f0, f1, Vec3(0.25, 0, 0)), false},
      {"vf_point_face_hit", make(Vec3(0, 0, 1), f0, f0, f0, Vec3(0, 0, -1), f0, f0, f0), true},
      {"vf_point_face_missed", make(Vec3(kTiny, 0, 1), f0, f0, f0, Vec3(kTiny, 0, -1), f0, f0, f0), false},
      // Nearly degenerate: a sliver of height 2^-30.
      {"vf_sliver_hit", make(Vec3(0.5, kTiny / 2, 1), f0, f1, Vec3(0.5, kTiny, 0), Vec3(0.5, kTiny / 2, -1), f0, f1, Vec3(0.5, kTiny, 0)),
       true},
      {"vf_sliver_missed",
       make(Vec3(0.5, 2 * kTiny, 1), f0, f1, Vec3(0.5, kTiny, 0), Vec3(0.5, 2 * kTiny, -1), f0, f1, Vec3(0.5, kTiny, 0)), false},
      // A face collapsing to a segment at t = 1 while the vertex reaches that segment.
      {"vf_face_collapses_onto_vertex",
       make(Vec3(0.5, 0, 1), f0, f1, Vec3(0, 1, 0), Vec3(0.5, 0, 0), f0, f1, Vec3(0.5, 0, 0)), true},
  };
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)  // the same cases 2^20 from the origin
    v.push_back({v[i].name + "_far", shifted(v[i].query, Vec3(1048576, -1048576, 524288)), v[i].contact});
  return v;
}

std::vector<NamedQuery> edge_edge() {
  const Vec3 a0(0, 0, 0), a1(1, 0, 0);
  // A static edge a on the x axis and an edge b moving from (b0, b1) to (c0, c1).
  auto against = [&](const Vec3& b0, const Vec3& b1, const Vec3& c0, const Vec3& c1) {
    return make(a0, a1, b0, b1, a0, a1, c0, c1);
  };
  auto falling = [&](double x0, double y0, double x1, double y1, double z0, double z1) {
    return against(Vec3(x0, y0, z0), Vec3(x1, y1, z0), Vec3(x0, y0, z1), Vec3(x1, y1, z1));
  };
  std::vector<NamedQuery> v = {
      {"ee_crossing", falling(0.5, -1, 0.5, 1, 1, -1), true},
      {"ee_through_end_point", falling(1, -1, 1, 1, 1, -1), true},  // edge through a vertex
      {"ee_beside_end_point_by_2^-30", falling(1 + kTiny, -1, 1 + kTiny, 1, 1, -1), false},
      {"ee_end_point_on_edge", falling(0.5, 0, 0.5, 1, 1, -1), true},  // b's end point crosses a
      {"ee_end_point_short_by_2^-30", falling(0.5, kTiny, 0.5, 1, 1, -1), false},
      {"ee_end_points_meet", falling(1, 0, 2, 1, 1, -1), true},
      {"ee_contact_at_t1", falling(0.5, -1, 0.5, 1, 1, 0), true},
      {"ee_stops_2^-30_short_at_t1", falling(0.5, -1, 0.5, 1, 1, kTiny), false},
      {"ee_contact_at_t0_leaving", falling(0.5, -1, 0.5, 1, 0, 1), true},
      {"ee_zero_motion_crossing", falling(0.5, -1, 0.5, 1, 0, 0), true},
      {"ee_zero_motion_skew", falling(0.5, -1, 0.5, 1, kTiny, kTiny), false},
      {"ee_parallel_falling_onto", falling(0.25, 0, 2, 0, 1, -1), true},  // collinear overlap at t = 1/2
      {"ee_parallel_beside_by_2^-30", falling(0.25, kTiny, 2, kTiny, 1, -1), false},
      {"ee_collinear_disjoint", falling(1 + kTiny, 0, 2, 0, 0, 0), false},
      {"ee_collinear_touching", falling(1, 0, 2, 0, 0, 0), true},
      {"ee_collinear_sliding_into", against(Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)), true},
      {"ee_collinear_sliding_short", against(Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(1 + kTiny, 0, 0), Vec3(2 + kTiny, 0, 0)),
       false},
      {"ee_coplanar_sweep_hits", against(Vec3(0.5, 1, 0), Vec3(2, 1, 0), Vec3(0.5, -1, 0), Vec3(2, -1, 0)), true},
      {"ee_coplanar_sweep_misses", against(Vec3(1 + kTiny, 1, 0), Vec3(2, 1, 0), Vec3(1 + kTiny, -1, 0), Vec3(2, -1, 0)),
       false},
      {"ee_parallel_above_moving_along", against(Vec3(-1, 0, kTiny), Vec3(0, 0, kTiny), Vec3(1, 0, kTiny), Vec3(2, 0, kTiny)),
       false},
      {"ee_degenerate_point_through_edge", falling(0.5, 0, 0.5, 0, 1, -1), true},
      {"ee_degenerate_point_beside_edge", falling(0.5, kTiny, 0.5, kTiny, 1, -1), false},
      {"ee_both_degenerate_meet",
       make(Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(0, 0, 0),
            Vec3(0, 0, 0)),
       true},  // two points swapping places meet at t = 1/2
      {"ee_both_degenerate_pass",
       make(Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, kTiny), Vec3(1, 1, kTiny),
            Vec3(0, 0, 1 - kTiny), Vec3(0, 0, 1 - kTiny)),
       false},
      // Rotating edge b (its ends move oppositely) sweeping past the end of a.
      {"ee_rotating_hits", against(Vec3(0.5, -1, 1), Vec3(0.5, 1, -1), Vec3(0.5, -1, -1), Vec3(0.5, 1, 1)), true},
      {"ee_rotating_misses", against(Vec3(2, -1, 1), Vec3(2, 1, -1), Vec3(2, -1, -1), Vec3(2, 1, 1)), false},
      // Nearly parallel: b tilted by 2^-30 over its length, crossing a at t = 1/2.
      {"ee_nearly_parallel_hits", falling(0, 0, 1, kTiny, 1, -1), true},
      {"ee_nearly_parallel_misses", falling(0, kTiny, 1, 2 * kTiny, 1, -1), false},
  };
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)
    v.push_back({v[i].name + "_far", shifted(v[i].query, Vec3(-1048576, 524288, 1048576)), v[i].contact});
  return v;
}

}  // namespace

std::vector<NamedQuery> hard_queries(PrimitivePair kind) {
  return kind == PrimitivePair::VertexFace ? vertex_face() : edge_edge();
}

}  // namespace ccd::cloth
