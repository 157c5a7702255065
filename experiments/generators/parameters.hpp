#pragma once
// Parameters of scene generators: declared once per generator as a table of specs
// {name, default, one-line doc, kind, range}, given either on the command line as
// `name=value` or in an experiment file as a JSON object, and checked by ONE function,
// resolve_parameters(), whatever their origin.
//
// Values are numbers. A Vector parameter (`offset`) takes one number (applied to all
// three axes) or three. Units are the scene's (metres, seconds). Every check failure
// throws std::invalid_argument with a one-line message that names the parameter and
// the rule, e.g. "parameter 'bodies': must be an integer in [0, 1e+08] (got 2.5)";
// callers prefix it with their context (command, file, field).
#include <ccd/geometry/vec3.hpp>

#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ccdlab {

enum class ParameterKind {
  Real,     ///< one finite number
  Integer,  ///< one integer-valued number (stored exactly in a double: |x| <= 2^53)
  Vector,   ///< one number (all axes) or three
};

/// Allowed values of a parameter (each component of a Vector): lo (<|<=) x (<|<=) hi.
struct ParameterRange {
  double lo = -std::numeric_limits<double>::max();
  double hi = std::numeric_limits<double>::max();
  bool lo_open = false;
  bool hi_open = false;

  bool contains(double x) const { return (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi); }
};

struct ParameterSpec {
  std::string_view name;
  double default_value = 0.0;  ///< a Vector's default applies to all axes
  std::string_view doc;        ///< one line, for `--help` and docs/generators.md
  ParameterKind kind = ParameterKind::Real;
  ParameterRange range{};
};

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
                                                 ParameterKind::Real, {0.0, 1e9, true, false}};
inline constexpr ParameterSpec kOffsetParameter{
    "offset", 0.0, "moves every position and the box (one number for all axes, or x,y,z)",
    ParameterKind::Vector, {-kMaxOffset, kMaxOffset, false, false}};

// Parameters several generators share, with the generator's own default.
/// r_min and r_max of radii uniform in [r_min, r_max].
constexpr ParameterSpec uniform_r_min_parameter(double default_value) {
  return {"r_min", default_value, "smallest radius (radii uniform in [r_min, r_max])", ParameterKind::Real,
          kPositiveLength};
}
constexpr ParameterSpec r_max_parameter(double default_value) {
  return {"r_max", default_value, "largest radius", ParameterKind::Real, kPositiveLength};
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

/// One parameter as given, before checking: a name and one or more numbers.
struct ParameterValue {
  std::string name;
  std::vector<double> values;
};

/// Parses a command-line argument `name=value` or `name=x,y,z`. Numbers are read in full
/// (std::from_chars); anything else throws std::invalid_argument naming the argument.
ParameterValue parameter_value_from_text(std::string_view argument);

/// Reads a JSON object {"name": number | [numbers], ...} (null means {}). A value of any
/// other type throws std::invalid_argument naming the key.
std::vector<ParameterValue> parameter_values_from_json(const nlohmann::json& params);

/// The checked, complete set of a generator's parameters (defaults filled in).
class GeneratorParameters {
 public:
  /// A Real or Integer parameter's value. Throws std::logic_error for an undeclared name.
  double number(std::string_view name) const;
  /// An Integer parameter's value.
  std::uint64_t integer(std::string_view name) const;
  /// A Vector parameter's value.
  ccd::Vec3 vector(std::string_view name) const;
  /// All values, for result files: {"bodies": 1000, "offset": [0, 0, 0], ...}.
  nlohmann::json to_json() const;

 private:
  friend GeneratorParameters resolve_parameters(std::span<const ParameterSpec>, std::span<const ParameterValue>);
  const std::pair<ParameterSpec, ccd::Vec3>& find(std::string_view name) const;
  std::vector<std::pair<ParameterSpec, ccd::Vec3>> values_;  // in spec order; scalars in x
};

/// THE check: every given name must be declared (all unknown names are listed, with the
/// valid ones), given at most once, with the right count of numbers, finite, integral for
/// an Integer, inside its range. Missing parameters take their defaults.
GeneratorParameters resolve_parameters(std::span<const ParameterSpec> specs,
                                       std::span<const ParameterValue> given);

/// A rule between two parameters: throws std::invalid_argument unless
/// number(lo) <= number(hi), e.g. "r_min (2) must be <= r_max (1)".
void require_not_greater(const GeneratorParameters& params, std::string_view lo, std::string_view hi);

/// Shortest text that reads back as the same double ("0.02", "1e+06").
std::string format_number(double x);
/// The rule of a spec in words: "integer in [0, 1e+08]", "number in (0, 0.5)".
std::string describe_range(const ParameterSpec& spec);

}  // namespace ccdlab
