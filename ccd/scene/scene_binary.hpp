#pragma once
// `ccdlab-scene-binary/1`: a binary companion of a sphere scene file, for scenes too large
// to parse quickly as JSON (a 1,000,000-body scene is 280 MB of JSON and about 88 MB in
// this format). docs/formats.md gives the layout byte by byte: a fixed 192-byte header
// (magic, version, counts, the digest of the scene, horizon, gravity, box), then one array
// per body field (radius, position, velocity, acceleration, the number of acceleration and
// velocity changes of each body) and the changes themselves, all little-endian.
//
// What it carries: every field of a sphere scene (`ccdlab-scene/1`: horizon, gravity, box
// and its boundaries, each body's radius, position, velocity, acceleration, acceleration
// and velocity changes). A scene with shapes, spin or static scenery is refused by
// scene_to_binary (keep it as JSON).
//
// Reading (scene_from_binary) refuses a file whose magic, version, flags, reserved bytes
// or digest text are wrong, whose sections do not fit its length exactly (truncated, or
// bytes after the last section), or whose per-body change counts do not add up to the
// header's; each names the part of the file (`velocity: truncated ...`). The scene is
// then checked by ccd::validate_scene, so a bad value is refused with the same message as
// in a JSON file (`S.ccds: bodies[3].radius: must be > 0`). Every read is bounds-checked
// against the file's length before it happens.
//
// The digest stored at writing is ccd::scene_digest of the scene written; a scene read back
// is bit for bit the scene written, so its digest is the stored one. load_scene does not
// recompute it (that is the cost this format avoids); verify_binary_scene_digest does.
#include <ccd/scene/scene.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace ccd {

/// The first 8 bytes of every binary scene: 0x89 "CCDS" CR LF 0x1A (no JSON text starts
/// with 0x89; CR LF and 0x1A expose a transfer that rewrites line ends or stops at ^Z).
inline constexpr std::string_view kSceneBinaryMagic{"\x89" "CCDS\r\n\x1a", 8};
inline constexpr std::uint32_t kSceneBinaryVersion = 1;
inline constexpr std::size_t kSceneBinaryHeaderBytes = 192;
/// Largest accepted binary scene file: 4 GiB (about 48,000,000 bodies without changes).
inline constexpr std::uint64_t kMaxSceneBinaryBytes = std::uint64_t{1} << 32;

/// What keeps a scene out of the binary format: the first field it does not carry.
struct BinaryUnsupported {
  std::string field;   ///< `shapes`, `bodies[4]`, `scenery`, `scenery_mesh`
  std::string reason;
};
/// Why `scene` cannot be written in the binary format; nullopt when it can.
std::optional<BinaryUnsupported> binary_scene_unsupported(const Scene& scene);

/// The binary file of `scene`, with its digest (ccd::scene_digest). Throws InputError
/// naming `file` and the field when binary_scene_unsupported(scene) is not empty.
std::string scene_to_binary(const Scene& scene, const std::string& file);

/// Parses and validates a binary scene; `file` names it in error messages. `digest`, when
/// given, receives the stored digest. Throws InputError.
Scene scene_from_binary(std::string_view bytes, const std::string& file, std::string* digest = nullptr);

/// The file at `path` is a regular file that starts with kSceneBinaryMagic. False when it
/// cannot be opened (the JSON reader then reports why).
bool is_binary_scene_file(const std::string& path);

/// Reads and validates a binary scene file (at most kMaxSceneBinaryBytes). Throws InputError.
Scene load_binary_scene(const std::string& path, std::string* digest = nullptr);

/// Writes the binary file of `scene` atomically (ccd/io/atomic_file.hpp).
void save_binary_scene(const Scene& scene, const std::string& path);

/// Recomputes the digest of a scene read from a binary file and compares it with the stored
/// one: throws InputError naming `file` and `digest` when they differ.
void verify_binary_scene_digest(const Scene& scene, const std::string& stored, const std::string& file);

}  // namespace ccd
