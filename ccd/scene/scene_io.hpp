#pragma once
// Reading and writing `ccdlab-scene/1` and `ccdlab-scene/2` files (format in
// docs/formats.md). Version 2 adds `shapes` and, per body, `shape`, `orientation`,
// `angular_velocity` and `angular_velocity_changes` (docs/rigid_bodies.md); those fields
// in a version 1 file are an error. A scene is written as version 1 when it has no shapes
// and no spin (Scene::is_rigid false), so sphere scenes and their digests stay as they were.
//
// Validation: malformed JSON (ccd/io/json_reader.hpp: duplicate keys included), a missing
// or mistyped required field, NaN or infinity, a magnitude above kMaxSceneMagnitude,
// radius <= 0, horizon <= 0, a box with min >= max on some axis, a body outside the box
// (centre closer than its radius to a wall), a body that could travel further than
// kMaxSceneMagnitude over the horizon (|v| T or |a + gravity| T^2 / 2), acceleration
// changes and velocity changes out of order or outside (0, horizon) (and each new velocity
// within the |v| T limit); version 2: an unknown shape kind or name,
// a duplicate shape name, a size <= 0, a hull with fewer than 4 points or no volume
// (coincident, collinear or coplanar points: ccd::hull_degeneracy), a body with both
// shape and radius, an orientation whose norm is further than 1e-6 from 1 (it is
// normalised otherwise), angular velocity changes out of order: each throws InputError naming the file,
// the field path and the body index (`bodies[3].radius`). An unknown field is an
// error naming it (JsonReader::only_fields; "comment" is allowed in every object).
#include <ccd/io/json_reader.hpp>  // read_json_file
#include <ccd/scene/scene.hpp>

#include <nlohmann/json.hpp>
#include <string>

namespace ccd {

/// Largest accepted magnitude of every number of a scene (m, m/s, m/s^2, s) and of the
/// distance a body can travel over the horizon. Lengths below 1e30 keep their squares
/// (1e60) and fourth powers (1e120), which the exact solvers form, far from overflow.
inline constexpr double kMaxSceneMagnitude = 1e30;

inline constexpr const char* kSceneFormat = "ccdlab-scene/2";
inline constexpr const char* kSceneFormatV1 = "ccdlab-scene/1";

/// Parses a scene from JSON; `file` is used only in error messages.
Scene scene_from_json(const nlohmann::json& j, const std::string& file);
/// Reads and validates a scene file: JSON, or the binary companion format when the file
/// starts with its magic (ccd/scene/scene_binary.hpp; a pipe or device is read as JSON).
/// Throws InputError.
Scene load_scene(const std::string& path);
/// Checks the invariants listed above on an in-memory scene. Throws InputError.
void validate_scene(const Scene& scene, const std::string& file);

nlohmann::json scene_to_json(const Scene& scene);
/// Writes the scene atomically (see ccd/io/atomic_file.hpp).
void save_scene(const Scene& scene, const std::string& path);

}  // namespace ccd
