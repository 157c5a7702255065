#pragma once
// SHA-256 (FIPS 180-4) of a byte string, as 64 lowercase hex digits: the fingerprint that
// tells whether two results were computed from the same scene (ccd::scene_digest).
#include <string>
#include <string_view>

namespace ccd {

std::string sha256_hex(std::string_view bytes);

}  // namespace ccd
