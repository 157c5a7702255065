#include <ccd/io/json_reader.hpp>

#include <cmath>
#include <limits>

namespace ccd {

using nlohmann::json;

const json& JsonReader::require(const json& obj, const char* key, const std::string& path) const {
  auto it = obj.find(key);
  if (it == obj.end()) fail(path.empty() ? key : path + "." + key, "missing required field");
  return *it;
}

double JsonReader::number(const json& v, const std::string& field) const {
  if (!v.is_number()) fail(field, "must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) fail(field, "must be finite");
  return x;
}

Vec3 JsonReader::vec3(const json& v, const std::string& field) const {
  if (!v.is_array() || v.size() != 3) fail(field, "must be an array of 3 numbers");
  return {number(v[0], field + "[0]"), number(v[1], field + "[1]"), number(v[2], field + "[2]")};
}

Vec3 JsonReader::optional_vec3(const json& obj, const char* key, const std::string& path) const {
  auto it = obj.find(key);
  return it == obj.end() ? Vec3::Zero() : vec3(*it, path + "." + key);
}

std::uint32_t JsonReader::index(const json& v, const std::string& field) const {
  if (!v.is_number_integer() || (!v.is_number_unsigned() && v.get<std::int64_t>() < 0))
    fail(field, "must be a non-negative integer");
  const std::uint64_t x = v.get<std::uint64_t>();
  if (x > std::numeric_limits<std::uint32_t>::max()) fail(field, "body index too large");
  return static_cast<std::uint32_t>(x);
}

long long JsonReader::integer(const json& v, const std::string& field, long long lo, long long hi) const {
  const std::string rule = "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!v.is_number_integer()) fail(field, rule);
  if (v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(hi)) fail(field, rule);
  const long long x = v.get<long long>();
  if (x < lo || x > hi) fail(field, rule);
  return x;
}

std::string JsonReader::string(const json& v, const std::string& field) const {
  if (!v.is_string()) fail(field, "must be a string");
  return v.get<std::string>();
}

bool JsonReader::boolean(const json& v, const std::string& field) const {
  if (!v.is_boolean()) fail(field, "must be true or false");
  return v.get<bool>();
}

double JsonReader::optional_number(const json& obj, const char* key, const std::string& path, double fallback) const {
  auto it = obj.find(key);
  return it == obj.end() ? fallback : number(*it, path.empty() ? key : path + "." + key);
}

bool JsonReader::optional_bool(const json& obj, const char* key, const std::string& path, bool fallback) const {
  auto it = obj.find(key);
  return it == obj.end() ? fallback : boolean(*it, path.empty() ? key : path + "." + key);
}

}  // namespace ccd
