#pragma once
// The message a scene's JSON is refused with (ccd::InputError), or "" when it is accepted,
// for tests of the scene reader's validation.
#include <ccd/io/input_error.hpp>
#include <ccd/scene/scene_io.hpp>

#include <nlohmann/json.hpp>

#include <string>

namespace ccd::test {

inline std::string error_of(const nlohmann::json& j) {
  try {
    scene_from_json(j, "s.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace ccd::test
