#pragma once
// Exact ground truth of bodies against the static scenery (ccd/scene/scenery.hpp): every
// maximal closed time interval in [0, horizon] during which body i's sphere touches
// polygon j (distance from the centre to the polygon <= radius). docs/scenery.md.
//
// Over a candidate run [u0, u1] (ccd/truth/truth_candidates.hpp), the body's trajectory
// pieces (walls, gravity, acceleration changes) are walked in order; a piece whose centre
// box, grown by the radius and a rounding margin, overlaps a polygon's box is solved exactly on the WHOLE piece by sphere_polygon_contacts
// (ccd/queries/sphere_polygon.hpp) with the piece's own expansion point, then clipped to
// the requested window; intervals of consecutive pieces that meet at a break, or are
// separated by no more than merge_gap(horizon) (ccd/truth/pair_contact.hpp), are merged,
// as in the body-body truth. So the same (body, polygon) gives bit-identical times
// whatever window it is asked about.
//
// Polygon indices are those of Scene::scenery (polygons, then mesh triangles). Units:
// seconds. Touching contacts have enter == exit. Scenes that wrap around are refused by
// the scene reader when they have scenery. Rigid bodies of other shapes take the certified
// search of ccd/truth/rigid_static_truth.hpp; this file solves their enclosing spheres.
#include <ccd/geometry/aabb.hpp>
#include <ccd/motion/trajectory.hpp>
#include <ccd/queries/contact_interval.hpp>
#include <ccd/scene/scenery.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace ccd {

/// One contact of a body with a static polygon.
struct StaticEvent {
  std::uint32_t body = 0;
  std::uint32_t polygon = 0;  ///< index into Scene::scenery
  double enter = 0.0;         ///< seconds, 0 <= enter <= exit <= horizon
  double exit = 0.0;
  bool operator==(const StaticEvent&) const = default;
};

/// The order of static events: (enter, body, polygon).
bool static_event_order(const StaticEvent& x, const StaticEvent& y);

/// Appends every maximal contact interval of `body` with `poly` within [u0, u1], sorted
/// (entries already in `out` are left alone).
void body_polygon_intervals(const Trajectories& traj, std::uint32_t body, const StaticPolygon& poly, double u0,
                            double u1, std::vector<ContactInterval>& out);

/// The static events of compute_truth (ccd/truth/truth.hpp) of `traj` as a motion of
/// balls, sorted by static_event_order. threads 0: one per hardware core; the result does
/// not depend on it.
std::vector<StaticEvent> compute_static_truth(const Trajectories& traj, std::span<const StaticPolygon> scenery,
                                              unsigned threads = 0);

}  // namespace ccd
