// The command line's integer parser: digits only, in full, within the range.
#include <ccd/util/integer_text.hpp>

#include <catch2/catch.hpp>

namespace ccd_util_integer_text_test {

TEST_CASE("parse_integer accepts digits in range and nothing else", "[util][cli]") {
  using ccd::parse_integer;
  CHECK(parse_integer("4", 1, 4096) == 4u);
  CHECK(parse_integer("4096", 1, 4096) == 4096u);
  CHECK(parse_integer("007", 1, 10) == 7u);  // leading zeros are digits
  CHECK(parse_integer("18446744073709551615", 0, UINT64_MAX) == UINT64_MAX);
  for (const char* bad : {"", "0", "4097", "-1", "+1", " 1", "1 ", "1e3", "2.0", "0x10", "abc",
                          "18446744073709551616"})
    CHECK_FALSE(parse_integer(bad, 1, 4096).has_value());
}

TEST_CASE("parse_integer_list reads comma-separated integers", "[util][cli]") {
  using ccd::parse_integer_list;
  CHECK(parse_integer_list("1000,10000", 1, 1000000) == std::vector<std::uint64_t>{1000, 10000});
  CHECK(parse_integer_list("5", 1, 10) == std::vector<std::uint64_t>{5});
  for (const char* bad : {"", ",", "1,", ",1", "1,,2", "1,x", "1;2"})
    CHECK_FALSE(parse_integer_list(bad, 1, 1000000).has_value());
}

}  // namespace ccd_util_integer_text_test
