#pragma once
// Reading and writing `ccdlab-scene/1` files (format in docs/formats.md).
//
// Validation: malformed JSON, a missing or mistyped required field, NaN or infinity,
// radius <= 0, horizon <= 0, a box with min >= max on some axis, a body outside the box
// (centre closer than its radius to a wall), acceleration changes out of order or
// outside (0, horizon): each throws InputError naming the file, the field path and
// the body index (`bodies[3].radius`). Unknown fields are ignored.
#include <ccd/scene/scene.hpp>

#include <nlohmann/json.hpp>
#include <string>

namespace ccd {

/// Parses a scene from JSON; `file` is used only in error messages.
Scene scene_from_json(const nlohmann::json& j, const std::string& file);
/// Reads and validates a scene file. Throws InputError.
Scene load_scene(const std::string& path);
/// Checks the invariants listed above on an in-memory scene. Throws InputError.
void validate_scene(const Scene& scene, const std::string& file);

nlohmann::json scene_to_json(const Scene& scene);
/// Writes the scene atomically (see ccd/io/atomic_file.hpp).
void save_scene(const Scene& scene, const std::string& path);

/// Reads a JSON file, throwing InputError with the parser's position on bad syntax.
nlohmann::json read_json_file(const std::string& path);

}  // namespace ccd
