#pragma once
// A word of an input file quoted for a one-line error message: between single quotes, cut
// to 40 bytes ("..." marks the cut), every byte that is not printable ASCII shown as '?'.
#include <string>
#include <string_view>

namespace ccd::cloth {

std::string quoted_word(std::string_view word);

}  // namespace ccd::cloth
