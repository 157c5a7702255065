#pragma once
// The sweep axis of sweep-and-prune methods: the axis along which the box centres have
// the largest variance, computed with Welford's update (no s2 - s^2/n cancellation far
// from the origin). Ties keep the lower axis; an empty span gives axis 0.
#include <ccd/geometry/aabb.hpp>

#include <span>

namespace ccd {

int largest_variance_axis(std::span<const Aabb> boxes);

}  // namespace ccd
