#pragma once
// Numbers as the mesh writers print them: the shortest text that reads back to the same
// value (std::to_chars), appended to a string without a temporary.
#include <array>
#include <charconv>
#include <string>

namespace ccd::cloth {

template <class T>
void append_number(std::string& out, T v) {
  std::array<char, 32> buf{};
  const auto [ptr, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  (void)ec;  // 32 bytes hold every shortest double, float and 64-bit integer
  out.append(buf.data(), ptr);
}

}  // namespace ccd::cloth
