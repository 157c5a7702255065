#include <ccd/util/parameters.hpp>
#include <ccd/util/nearest_name.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace ccd {
namespace {

std::string in_quotes(std::string_view s) {
  std::string out(1, '\'');  // appended, not "'" + s + "'": GCC 12 warns falsely (-Wrestrict) on that
  out.append(s);
  out.push_back('\'');
  return out;
}

std::string valid_names(std::span<const ParameterSpec> specs) {
  std::string out;
  for (const ParameterSpec& s : specs) out += (out.empty() ? "" : ", ") + std::string(s.name);
  return out;
}

[[noreturn]] void fail(std::string_view name, const std::string& what) {
  throw std::invalid_argument("parameter " + in_quotes(name) + ": " + what);
}

double parse_number(std::string_view name, std::string_view token) {
  double x = 0.0;
  const char* first = token.data();
  const char* last = token.data() + token.size();
  const auto [end, ec] = std::from_chars(first, last, x);
  if (token.empty() || ec != std::errc() || end != last) fail(name, in_quotes(token) + " is not a number");
  // An integer written out beyond 2^53 would be rounded silently on its way to a double
  // (seed=9007199254740993 would run as 9007199254740992).
  std::string_view digits = token.substr(token[0] == '-' ? 1 : 0);
  if (!digits.empty() && digits.find_first_not_of("0123456789") == std::string_view::npos) {
    digits.remove_prefix(std::min(digits.find_first_not_of('0'), digits.size()));
    constexpr std::string_view two_53 = "9007199254740992";
    if (digits.size() > two_53.size() || (digits.size() == two_53.size() && digits > two_53))
      fail(name, "integer " + std::string(token) + " is too large to be exact (|x| > 2^53)");
  }
  return x;
}

}  // namespace

std::string format_number(double x) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

std::string describe_range(const ParameterSpec& spec) {
  const ParameterRange& r = spec.range;
  const bool has_lo = r.lo > -std::numeric_limits<double>::max();
  const bool has_hi = r.hi < std::numeric_limits<double>::max();
  std::string what = spec.kind == ParameterKind::Integer  ? "an integer"
                     : spec.kind == ParameterKind::Vector ? "one number or three, each"
                                                          : "a number";
  if (has_lo && has_hi)
    return what + " in " + (r.lo_open ? "(" : "[") + format_number(r.lo) + ", " + format_number(r.hi) +
           (r.hi_open ? ")" : "]");
  if (has_lo) return what + (r.lo_open ? " > " : " >= ") + format_number(r.lo);
  if (has_hi) return what + (r.hi_open ? " < " : " <= ") + format_number(r.hi);
  return "a finite number";
}

ParameterValue parameter_value_from_text(std::string_view argument) {
  const std::size_t eq = argument.find('=');
  if (eq == std::string_view::npos || eq == 0)
    throw std::invalid_argument("expected NAME=VALUE, got " + in_quotes(argument));
  ParameterValue v;
  v.name = std::string(argument.substr(0, eq));
  std::string_view rest = argument.substr(eq + 1);
  while (true) {
    const std::size_t comma = rest.find(',');
    v.values.push_back(parse_number(v.name, rest.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
  }
  return v;
}

std::vector<ParameterValue> option_values_from_text(std::string_view options, std::string_view first_parameter) {
  std::vector<ParameterValue> out;
  std::string_view rest = options;
  while (true) {
    const std::size_t comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    const std::size_t eq = item.find('=');
    if (item.empty()) throw std::invalid_argument("empty option in " + in_quotes(options));
    if (eq == std::string_view::npos) {
      if (first_parameter.empty() || !out.empty())
        throw std::invalid_argument("expected NAME=VALUE, got " + in_quotes(item));
      out.push_back({std::string(first_parameter), {parse_number(first_parameter, item)}});
    } else {
      if (eq == 0) throw std::invalid_argument("expected NAME=VALUE, got " + in_quotes(item));
      const std::string name(item.substr(0, eq));
      out.push_back({name, {parse_number(name, item.substr(eq + 1))}});
    }
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
  }
  return out;
}

std::string describe_parameter(const ParameterSpec& spec) {
  std::string s = std::string(spec.name) + "=" + format_number(spec.default_value);
  if (!spec.unit.empty()) s += " " + std::string(spec.unit);
  return s + " (" + std::string(spec.doc) + "; " + describe_range(spec) + ")";
}

std::vector<ParameterValue> parameter_values_from_json(const nlohmann::json& params) {
  std::vector<ParameterValue> out;
  if (params.is_null()) return out;
  if (!params.is_object())
    throw std::invalid_argument("generator parameters must be a JSON object {\"name\": number, ...}");
  auto number = [](const std::string& name, const nlohmann::json& x) {
    if (!x.is_number()) fail(name, "must be a number or an array of numbers (got " + x.dump() + ")");
    // An integer beyond 2^53 would be rounded silently on its way to a double.
    if ((x.is_number_unsigned() && x.get<std::uint64_t>() > (std::uint64_t{1} << 53)) ||
        (x.is_number_integer() && !x.is_number_unsigned() && std::llabs(x.get<std::int64_t>()) > (std::int64_t{1} << 53)))
      fail(name, "integer " + x.dump() + " is too large to be exact (|x| > 2^53)");
    return x.get<double>();
  };
  for (const auto& [key, value] : params.items()) {
    ParameterValue v{key, {}};
    if (value.is_array()) {
      for (const nlohmann::json& x : value) v.values.push_back(number(key, x));
      if (v.values.empty()) fail(key, "must be a number or an array of numbers (got [])");
    } else {
      v.values.push_back(number(key, value));
    }
    out.push_back(std::move(v));
  }
  return out;
}

ParameterSet resolve_parameters(std::span<const ParameterSpec> specs, std::span<const ParameterValue> given) {
  auto spec_of = [&](std::string_view name) {
    return std::find_if(specs.begin(), specs.end(), [&](const ParameterSpec& s) { return s.name == name; });
  };
  std::string unknown;
  int unknown_count = 0;
  std::vector<std::string_view> names;
  for (const ParameterSpec& s : specs) names.push_back(s.name);
  for (const ParameterValue& v : given) {
    if (spec_of(v.name) != specs.end()) continue;
    const std::string near = nearest_name(v.name, names);
    unknown += (unknown.empty() ? "" : ", ") + in_quotes(v.name) + (near.empty() ? "" : " (did you mean " + in_quotes(near) + "?)");
    ++unknown_count;
  }
  if (unknown_count > 0)
    throw std::invalid_argument(std::string(unknown_count == 1 ? "unknown parameter " : "unknown parameters ") +
                                unknown + "; valid parameters: " + valid_names(specs));

  ParameterSet out;
  for (const ParameterSpec& spec : specs) out.values_.emplace_back(spec, Vec3::Constant(spec.default_value));
  std::vector<bool> seen(specs.size(), false);
  for (const ParameterValue& v : given) {
    const std::size_t i = static_cast<std::size_t>(spec_of(v.name) - specs.begin());
    const ParameterSpec& spec = specs[i];
    if (seen[i]) fail(spec.name, "given more than once");
    seen[i] = true;
    const bool vector = spec.kind == ParameterKind::Vector;
    if (v.values.size() != 1 && !(vector && v.values.size() == 3))
      fail(spec.name, std::string(vector ? "expects one number or three" : "expects one number") + " (got " +
                          std::to_string(v.values.size()) + ")");
    for (double x : v.values) {
      const bool integral = spec.kind != ParameterKind::Integer || std::floor(x) == x;
      if (!std::isfinite(x) || !integral || !spec.range.contains(x))
        fail(spec.name, "must be " + describe_range(spec) + " (got " + format_number(x) + ")");
    }
    out.values_[i].second =
        v.values.size() == 3 ? Vec3(v.values[0], v.values[1], v.values[2]) : Vec3::Constant(v.values[0]);
  }
  return out;
}

const std::pair<ParameterSpec, Vec3>& ParameterSet::find(std::string_view name) const {
  for (const auto& entry : values_)
    if (entry.first.name == name) return entry;
  throw std::logic_error("parameter '" + std::string(name) + "' is not declared in its table");
}

double ParameterSet::number(std::string_view name) const {
  const auto& [spec, value] = find(name);
  if (spec.kind == ParameterKind::Vector) throw std::logic_error("parameter '" + std::string(name) + "' is a vector");
  return value.x();
}

std::uint64_t ParameterSet::integer(std::string_view name) const {
  const auto& [spec, value] = find(name);
  if (spec.kind != ParameterKind::Integer || value.x() < 0.0)
    throw std::logic_error("parameter '" + std::string(name) + "' is not a non-negative integer");
  return static_cast<std::uint64_t>(value.x());
}

Vec3 ParameterSet::vector(std::string_view name) const {
  const auto& [spec, value] = find(name);
  if (spec.kind != ParameterKind::Vector) throw std::logic_error("parameter '" + std::string(name) + "' is a scalar");
  return value;
}

void require_not_greater(const ParameterSet& params, std::string_view lo, std::string_view hi) {
  const double a = params.number(lo);
  const double b = params.number(hi);
  if (a > b)
    throw std::invalid_argument(std::string(lo) + " (" + format_number(a) + ") must be <= " + std::string(hi) + " (" +
                                format_number(b) + ")");
}

nlohmann::json ParameterSet::to_json() const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [spec, value] : values_) {
    const std::string key(spec.name);
    if (spec.kind == ParameterKind::Vector)
      j[key] = {value.x(), value.y(), value.z()};
    else if (spec.kind == ParameterKind::Integer)
      j[key] = static_cast<std::int64_t>(value.x());
    else
      j[key] = value.x();
  }
  return j;
}

}  // namespace ccd
