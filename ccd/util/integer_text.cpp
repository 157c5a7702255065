#include <ccd/util/integer_text.hpp>

#include <charconv>

namespace ccd {

std::optional<std::uint64_t> parse_integer(std::string_view text, std::uint64_t lo, std::uint64_t hi) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || v < lo || v > hi) return std::nullopt;
  return v;
}

std::optional<std::vector<std::uint64_t>> parse_integer_list(std::string_view text, std::uint64_t lo,
                                                             std::uint64_t hi) {
  std::vector<std::uint64_t> out;
  while (true) {
    const std::size_t comma = text.find(',');
    const auto v = parse_integer(text.substr(0, comma), lo, hi);
    if (!v) return std::nullopt;
    out.push_back(*v);
    if (comma == std::string_view::npos) return out;
    text = text.substr(comma + 1);
  }
}

}  // namespace ccd
