#pragma once
// SHA-256 (FIPS 180-4) of a byte string, as 64 lowercase hexadecimal digits. Used for the
// scene digest of truth files (ccd/scene/scene_digest.hpp); small enough to carry here
// rather than a cryptography library. Not constant-time; no secrets pass through it.
#include <string>
#include <string_view>

namespace ccd {

std::string sha256_hex(std::string_view bytes);

}  // namespace ccd
