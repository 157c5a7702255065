#pragma once
// Certified ground truth of rigid bodies against the static scenery (docs/scenery.md,
// docs/truth.md): every contact interval of every (body, polygon) pair, where contact
// means the closed shape and the closed polygon intersect.
//
// A polygon is a convex shape at rest: its vertices as a ConvexProxy (radius 0) with the
// identity pose at the origin (polygon_proxy, ccd/scene/scenery.hpp), so the vertices enter the distance exactly,
// as read. The signed distance between a body and a polygon is then Lipschitz in time with
// L = max_point_speed(body) (ccd/motion/rigid_motion.hpp; the polygon does not move), and
// the bracket search of the body-body rigid truth (ccd/truth/bracket_search.hpp) labels
// time with it: events with `enter_error`, `exit_error` and the `grazing` flag, exactly as
// body-body rigid events (time tolerance, band and evaluation limit from
// RigidTruthOptions; the band's size term is the body's enclosing radius plus the
// polygon's circumradius about its first vertex).
// The scene's truth is compute_truth (ccd/truth/truth.hpp): the candidate finder
// (ccd/truth/truth_candidates.hpp) gives the (body, polygon, run of windows) and the truth
// table (ccd/truth/truth_table.hpp) calls the search below for every kind but spheres.
// Bodies of kind Sphere (plain or spinning: the spin does not move a ball's points) keep
// the exact sphere-polygon truth (ccd/truth/static_truth.hpp; errors 0), so a scene's
// sphere events are bit-identical whether or not it also holds other shapes.
// Scenes that wrap around have no scenery (refused by the scene reader).
#include <ccd/motion/rigid_motion.hpp>
#include <ccd/scene/scenery.hpp>
#include <ccd/truth/rigid_truth.hpp>
#include <ccd/truth/static_truth.hpp>
#include <ccd/truth/truth_io.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace ccd {

struct RigidStaticTruthResult {
  std::vector<StaticEvent> events;  ///< sorted by static_event_order
  std::vector<EventError> errors;   ///< one per event (zero for sphere bodies)
  std::size_t evaluations = 0;      ///< convex_distance calls
  std::size_t grazing = 0;          ///< events flagged grazing
};

/// The bracket search of one rigid body against one polygon over [u0, u1]; appends the
/// events (with `polygon` as their polygon index) and their errors. Returns the number of
/// distance evaluations.
std::size_t body_polygon_bracket_events(const RigidMotion& motion, std::uint32_t body, const StaticPolygon& polygon,
                                        std::uint32_t polygon_index, double u0, double u1, double time_tolerance,
                                        std::size_t max_evaluations, std::vector<StaticEvent>& events,
                                        std::vector<EventError>& errors);

/// The static events of compute_truth (ccd/truth/truth.hpp) with these options
/// (generic_spheres ignored: spheres stay exact); errors has one entry per event.
RigidStaticTruthResult compute_rigid_static_truth(const RigidMotion& motion, std::span<const StaticPolygon> scenery,
                                                  const RigidTruthOptions& options = {});

}  // namespace ccd
