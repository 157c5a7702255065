#pragma once
// The two limits of double that the kernels compare against, defined once for every file
// (a file-private copy of each would clash where several files are compiled as one).
#include <limits>

namespace ccd {

inline constexpr double kEps = std::numeric_limits<double>::epsilon();  ///< machine epsilon, 2^-52
inline constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace ccd
