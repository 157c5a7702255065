#pragma once
// Reading ccdlab's JSON files, and typed field access for their formats.
//
// Parsing (parse_json_text, read_json_file) is stricter than JSON itself, so that a file
// means one thing: a key given twice in one object is an error (JSON leaves it open and
// nlohmann would keep the last), objects and arrays nest at most kMaxJsonDepth deep, a
// number must fit a double, and a file is at most kMaxJsonBytes long. Every failure
// throws InputError naming the file and, where there is one, the field path.
//
// Every reader names the fields it knows in each object (JsonReader::only_fields): a
// misspelt field is an error, never silently ignored.
//
// Field access (JsonReader): every failure throws InputError naming the file and the field
// path (`bodies[3].radius`), so readers of different formats report bad input the same way.
#include <ccd/geometry/vec3.hpp>
#include <ccd/io/input_error.hpp>

#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>

namespace ccd {

/// Deepest accepted nesting of objects and arrays (a scene needs 4).
inline constexpr int kMaxJsonDepth = 64;
/// Largest accepted input file: 1 GiB (a scene of a million bodies is about 250 MB).
inline constexpr std::uint64_t kMaxJsonBytes = std::uint64_t{1} << 30;

/// Parses `text`; `file` names it in error messages. Throws InputError.
nlohmann::json parse_json_text(std::string_view text, const std::string& file);
/// Reads and parses a file (a regular file, a pipe or a device; not a folder). The text is
/// parsed as it is read, so a stream that is not JSON fails at its first bad byte.
/// Throws InputError.
nlohmann::json read_json_file(const std::string& path);

struct JsonReader {
  const std::string& file;

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw InputError(file, field, what);
  }
  /// Rejects a key of the object `obj` (at `path`) that is not in `known` and is not
  /// "comment" (allowed in every object, for notes): `path.key: unknown field (did you mean
  /// "x"?)`, the nearest known name, or the list of known names when none is near.
  void only_fields(const nlohmann::json& obj, const std::string& path,
                   std::initializer_list<std::string_view> known) const {
    only_fields(obj, path, std::span<const std::string_view>(known.begin(), known.size()));
  }
  void only_fields(const nlohmann::json& obj, const std::string& path, std::span<const std::string_view> known) const;
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
  /// A non-negative integer of at most `max` (exactly representable: max <= 2^53).
  std::uint64_t count(const nlohmann::json& v, const std::string& field, std::uint64_t max) const;
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
