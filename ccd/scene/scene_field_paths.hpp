#pragma once
// The field paths that scene reading and validation name in their messages
// (`bodies[3]`, `shapes[0]`): one spelling for both (ccd/scene/scene_read.cpp,
// ccd/scene/scene_validate.cpp).
#include <cstddef>
#include <string>

namespace ccd {

inline std::string body_path(std::size_t i) { return "bodies[" + std::to_string(i) + "]"; }
inline std::string shape_path(std::size_t i) { return "shapes[" + std::to_string(i) + "]"; }

}  // namespace ccd
