#pragma once
// Parameter tables: the options of every registry entry (scene generators, broad phases,
// bounds) are declared once as a table of specs {name, default, one-line doc, kind,
// range, unit}, given on the command line as `name=value`, in a method name as
// `NAME:name=value,...` or in an experiment file as a JSON object, and checked by ONE
// function, resolve_parameters(), whatever their origin.
//
// Values are numbers. A Vector parameter (a generator's `offset`) takes one number
// (applied to all three axes) or three. Units are the scene's (metres, seconds). Every check failure
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

namespace ccd {

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
  std::string_view doc;        ///< one line, for `--help`, `ccdlab methods` and the docs
  ParameterKind kind = ParameterKind::Real;
  ParameterRange range{};
  std::string_view unit;       ///< e.g. "m", "s", "pieces"; empty: a pure number

  constexpr ParameterSpec(std::string_view name_, double default_value_, std::string_view doc_,
                          ParameterKind kind_ = ParameterKind::Real, ParameterRange range_ = {},
                          std::string_view unit_ = {})
      : name(name_), default_value(default_value_), doc(doc_), kind(kind_), range(range_), unit(unit_) {}
};

/// One parameter as given, before checking: a name and one or more numbers.
struct ParameterValue {
  std::string name;
  std::vector<double> values;
};

/// Parses a command-line argument `name=value` or `name=x,y,z`. Numbers are read in full
/// (std::from_chars); anything else throws std::invalid_argument naming the argument.
ParameterValue parameter_value_from_text(std::string_view argument);

/// Parses the options of a registry entry as written after its name's colon:
/// `name=value,name=value` (scalars only). A bare value (no `=`) is the value of the
/// table's first parameter (so `horn:4` is `horn:pieces=4`); `first_parameter` is that
/// name (empty: a bare value is an error). Throws std::invalid_argument naming the part.
std::vector<ParameterValue> option_values_from_text(std::string_view options, std::string_view first_parameter);

/// The table as text for `--help` and `ccdlab methods`: "name=default unit (doc; range)".
std::string describe_parameter(const ParameterSpec& spec);

/// Reads a JSON object {"name": number | [numbers], ...} (null means {}). A value of any
/// other type throws std::invalid_argument naming the key.
std::vector<ParameterValue> parameter_values_from_json(const nlohmann::json& params);

/// The checked, complete set of an entry's parameters (defaults filled in).
class ParameterSet {
 public:
  /// A Real or Integer parameter's value. Throws std::logic_error for an undeclared name.
  double number(std::string_view name) const;
  /// An Integer parameter's value.
  std::uint64_t integer(std::string_view name) const;
  /// A Vector parameter's value.
  Vec3 vector(std::string_view name) const;
  /// All values, for result files: {"bodies": 1000, "offset": [0, 0, 0], ...}.
  nlohmann::json to_json() const;

 private:
  friend ParameterSet resolve_parameters(std::span<const ParameterSpec>, std::span<const ParameterValue>);
  const std::pair<ParameterSpec, Vec3>& find(std::string_view name) const;
  std::vector<std::pair<ParameterSpec, Vec3>> values_;  // in spec order; scalars in x
};

/// THE check: every given name must be declared (all unknown names are listed, with the
/// valid ones), given at most once, with the right count of numbers, finite, integral for
/// an Integer, inside its range. Missing parameters take their defaults.
ParameterSet resolve_parameters(std::span<const ParameterSpec> specs,
                                       std::span<const ParameterValue> given);

/// A rule between two parameters: throws std::invalid_argument unless
/// number(lo) <= number(hi), e.g. "r_min (2) must be <= r_max (1)".
void require_not_greater(const ParameterSet& params, std::string_view lo, std::string_view hi);

/// Shortest text that reads back as the same double ("0.02", "1e+06").
std::string format_number(double x);
/// The rule of a spec in words: "integer in [0, 1e+08]", "number in (0, 0.5)".
std::string describe_range(const ParameterSpec& spec);

}  // namespace ccd
