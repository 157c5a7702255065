#pragma once
// Typed field access for ccdlab's JSON file formats: every failure throws InputError
// naming the file and the field path (`bodies[3].radius`), so readers of different
// formats report bad input the same way.
#include <ccd/geometry/vec3.hpp>
#include <ccd/scene/input_error.hpp>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace ccd {

struct JsonReader {
  const std::string& file;

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw InputError(file, field, what);
  }
  /// obj[key]; "missing required field" (named path.key) when absent.
  const nlohmann::json& require(const nlohmann::json& obj, const char* key, const std::string& path) const;
  /// A finite number.
  double number(const nlohmann::json& v, const std::string& field) const;
  /// An array of 3 finite numbers.
  Vec3 vec3(const nlohmann::json& v, const std::string& field) const;
  /// obj[key] as vec3, or zero when absent.
  Vec3 optional_vec3(const nlohmann::json& obj, const char* key, const std::string& path) const;
  /// A non-negative integer that fits a 32-bit body index.
  std::uint32_t index(const nlohmann::json& v, const std::string& field) const;
  /// An integer in [lo, hi] ("must be an integer in [lo, hi]").
  long long integer(const nlohmann::json& v, const std::string& field, long long lo, long long hi) const;
  /// A string.
  std::string string(const nlohmann::json& v, const std::string& field) const;
  /// A boolean.
  bool boolean(const nlohmann::json& v, const std::string& field) const;
  /// obj[key] as a finite number, or `fallback` when absent.
  double optional_number(const nlohmann::json& obj, const char* key, const std::string& path, double fallback) const;
  /// obj[key] as a boolean, or `fallback` when absent.
  bool optional_bool(const nlohmann::json& obj, const char* key, const std::string& path, bool fallback) const;
};

}  // namespace ccd
