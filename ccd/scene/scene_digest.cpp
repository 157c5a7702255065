#include <ccd/scene/scene_digest.hpp>

#include <ccd/scene/scene_io.hpp>
#include <ccd/util/sha256.hpp>

namespace ccd {

std::string canonical_scene_text(const Scene& scene) { return scene_to_json(scene).dump(); }

std::string scene_digest(const Scene& scene) { return sha256_hex(canonical_scene_text(scene)); }

}  // namespace ccd
