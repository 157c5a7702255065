#pragma once
// Helpers shared by the generator tests.
#include <ccd/scene/scene_io.hpp>
#include <generators/registry.hpp>

#include <nlohmann/json.hpp>
#include <string_view>

namespace ccdlab::testing {

/// Runs a generator from JSON parameters (the experiment-file path).
inline ccd::Scene make(std::string_view name, const nlohmann::json& params) {
  return generate_scene(name, params);
}

/// Bit-for-bit equality: the JSON form writes every double in round-trip precision.
inline bool same_scene(const ccd::Scene& a, const ccd::Scene& b) {
  return ccd::scene_to_json(a) == ccd::scene_to_json(b);
}

}  // namespace ccdlab::testing
