#include "quoted_word.hpp"

namespace ccd::cloth {

std::string quoted_word(std::string_view word) {
  std::string out = "'";
  for (char c : word.substr(0, 40)) out += c >= 0x20 && c < 0x7f ? c : '?';
  out += word.size() > 40 ? "...'" : "'";
  return out;
}

}  // namespace ccd::cloth
