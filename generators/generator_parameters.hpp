#pragma once
// The parameters every scene generator shares, and ranges common to several, declared
// with ccd's parameter tables (ccd/util/parameters.hpp). docs/generators.md lists them.
#include <ccd/util/parameters.hpp>

namespace ccdlab {

using ccd::ParameterKind;
using ccd::ParameterRange;
using ccd::ParameterSet;
using ccd::ParameterSpec;
using ccd::ParameterValue;
using ccd::describe_range;
using ccd::format_number;
using ccd::parameter_value_from_text;
using ccd::parameter_values_from_json;
using ccd::require_not_greater;
using ccd::resolve_parameters;

// Ranges shared by the generators (documented in docs/generators.md).
inline constexpr double kMaxLength = 1e6;          ///< radii and lengths
inline constexpr double kMaxRate = 1e9;            ///< speeds and accelerations
inline constexpr double kMaxBodies = 1e8;          ///< bodies per scene
inline constexpr double kMaxOffset = 1e12;         ///< |offset| per axis
inline constexpr double kMaxSeed = 9007199254740992.0;  ///< 2^53: every seed is exact in JSON
inline constexpr ParameterRange kPositiveLength{0.0, kMaxLength, true, false};
inline constexpr ParameterRange kNonNegativeRate{0.0, kMaxRate, false, false};
inline constexpr ParameterRange kVolumeFraction{0.0, 0.5, true, true};

// The four parameters every generator has, in this order, first in its table.
inline constexpr ParameterSpec kSeedParameter{"seed", 1.0, "seed of the std::mt19937_64 random engine",
                                              ParameterKind::Integer, {0.0, kMaxSeed, false, false}};
inline constexpr ParameterSpec kBodiesParameter{"bodies", 1000.0, "number of bodies", ParameterKind::Integer,
                                                {0.0, kMaxBodies, false, false}};
inline constexpr ParameterSpec kHorizonParameter{"horizon", 1.0, "the scene runs over [0, horizon] seconds",
                                                 ParameterKind::Real, {0.0, 1e9, true, false}, "s"};
inline constexpr ParameterSpec kOffsetParameter{
    "offset", 0.0, "moves every position and the box (one number for all axes, or x,y,z)",
    ParameterKind::Vector, {-kMaxOffset, kMaxOffset, false, false}, "m"};

// Parameters several generators share, with the generator's own default.
/// r_min and r_max of radii uniform in [r_min, r_max].
constexpr ParameterSpec uniform_r_min_parameter(double default_value) {
  return {"r_min", default_value, "smallest radius (radii uniform in [r_min, r_max])", ParameterKind::Real,
          kPositiveLength, "m"};
}
constexpr ParameterSpec r_max_parameter(double default_value) {
  return {"r_max", default_value, "largest radius", ParameterKind::Real, kPositiveLength, "m"};
}
/// The volume fraction that sets the side L of a cubic box.
inline constexpr ParameterSpec kBoxFractionParameter{
    "fraction", 0.02, "volume fraction of the box [0, L]^3 filled by the spheres", ParameterKind::Real,
    kVolumeFraction};

/// Whether bodies may overlap at t = 0 (the random generators redraw overlapping positions
/// unless it is 1).
inline constexpr ParameterSpec kOverlapParameter{
    "overlap", 0.0, "1 keeps bodies that overlap at t = 0; 0 draws an overlapping position again",
    ParameterKind::Integer, {0.0, 1.0, false, false}};

}  // namespace ccdlab
