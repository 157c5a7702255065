#pragma once
// The vector type of ccdlab's geometry: Eigen's fixed-size 3-vector of doubles.
// Units are the scene's (metres and seconds by convention); nothing here is scaled.
#include <Eigen/Core>

namespace ccd {

using Vec3 = Eigen::Vector3d;

}  // namespace ccd
