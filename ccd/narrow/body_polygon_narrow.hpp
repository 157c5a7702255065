#pragma once
// The narrow phase of a moving body against a static polygon (ccd/scene/scenery.hpp): the
// polygon column of the narrow table (ccd/narrow/narrow_table.hpp), keyed by the body's
// shape; callers look the entry up there (narrow_table().find_polygon(kind)). The default
// table's entries:
//  - a sphere (kind Sphere, spinning or not): the exact sphere-polygon
//    entry (ccd/narrow/sphere_polygon_narrow.hpp), toi_error 0;
//  - any other shape: polygon_advancement, the generic entry of the body-body rigid pairs,
//    conservative advancement (ccd/narrow/conservative_advancement.hpp) against the polygon
//    as a convex shape at rest (polygon_proxy): certified, toi_error its bracket (the first
//    contact lies in [toi, toi + toi_error]; +infinity for a reported near miss).
// Sample test (in.sample): in contact at t0, as each entry defines it.
#include <ccd/narrow/contact_result.hpp>
#include <ccd/narrow/narrow_query.hpp>
#include <ccd/scene/scenery.hpp>

#include <cstdint>

namespace ccd {

/// Conservative advancement of `body` against the polygon at rest (any shape).
ContactResult polygon_advancement(const NarrowInput& in, std::uint32_t body, const StaticPolygon& polygon);

}  // namespace ccd
