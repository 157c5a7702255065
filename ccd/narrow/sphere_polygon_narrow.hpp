#pragma once
// The narrow phase of a moving body against a static polygon (ccd/scene/scenery.hpp): the
// body as its sphere (a rigid body as its enclosing sphere: conservative, not exact).
//  - sample test (in.sample): in contact at t0 when the distance from the centre to the
//    polygon is <= r (point_polygon_closest): Overlapping at t0, else Miss;
//  - step query: the first contact in [in.t0, in.t1] from the exact piecewise-quadratic
//    path, piece by piece, with the exact sphere-polygon contact intervals
//    (ccd/queries/sphere_polygon.hpp, through body_polygon_intervals of
//    ccd/truth/static_truth.hpp, which solves each piece as the truth does, so a contact
//    time is bit-identical to the truth's): Overlapping when in contact at t0, Hit at the
//    first contact otherwise, Miss when none. toi_error 0 (exact).
// signed_distance: the distance from the centre to the polygon minus r at toi.
#include <ccd/narrow/contact_result.hpp>
#include <ccd/narrow/narrow_query.hpp>
#include <ccd/scene/scenery.hpp>

#include <cstdint>

namespace ccd {

ContactResult sphere_polygon_narrow(const NarrowInput& in, std::uint32_t body, const StaticPolygon& polygon);

}  // namespace ccd
