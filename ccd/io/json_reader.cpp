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

}  // namespace ccd
