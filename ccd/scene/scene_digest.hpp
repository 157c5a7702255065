#pragma once
// The scene digest: SHA-256 (ccd/util/sha256.hpp) of the canonical scene text, the
// compact JSON of scene_to_json (ccd/scene/scene_io.hpp): keys sorted, no whitespace,
// every double in its shortest round-trip form. Two files that describe the same scene
// (whatever their whitespace, key order or number spelling) have the same digest; any
// change of a body, the box, gravity or the horizon changes it. Truth files record it
// (docs/truth.md) so that `ccdlab run --truth FILE` can check that FILE is this scene's.
#include <ccd/scene/scene.hpp>

#include <string>

namespace ccd {

/// The canonical text of `scene` (what the digest hashes).
std::string canonical_scene_text(const Scene& scene);
/// 64 lowercase hexadecimal digits.
std::string scene_digest(const Scene& scene);

}  // namespace ccd
