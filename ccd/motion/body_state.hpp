#pragma once
// The state of a body at one instant: what the start of a step hands to the bounds
// (bounds/bound.hpp) and to the narrow phase's sample test (ccd/narrow/).
// Units: the scene's (metres, seconds).
#include <ccd/geometry/vec3.hpp>

namespace ccd {

struct BodyState {
  Vec3 position{Vec3::Zero()};  ///< centre
  Vec3 velocity{Vec3::Zero()};
  double radius = 0.0;          ///< radius of the sphere that encloses the body
};

}  // namespace ccd
