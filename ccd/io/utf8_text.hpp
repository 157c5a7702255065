#pragma once
// Text that may be stored in JSON. A file name on Linux is any bytes but '/' and NUL, so it
// need not be UTF-8 (`t\xff.json`), while a JSON string must be: nlohmann::json refuses to
// write a string holding an invalid byte. Names that reach a results, frames or page file
// pass through escape_invalid_utf8 first.
#include <string>
#include <string_view>

namespace ccd {

/// `text` unchanged when it is valid UTF-8; otherwise every byte that does not belong to a
/// valid UTF-8 sequence (a stray continuation byte, a truncated or overlong sequence, a
/// surrogate, a code point above U+10FFFF) is written as the four characters \xHH
/// (uppercase hex), e.g. "t\xff.json" becomes the 12 characters `t\xFF.json`.
std::string escape_invalid_utf8(std::string_view text);

/// True when `text` is valid UTF-8.
bool is_valid_utf8(std::string_view text);

}  // namespace ccd
