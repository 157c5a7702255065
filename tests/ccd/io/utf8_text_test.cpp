// escape_invalid_utf8: valid UTF-8 unchanged, every invalid byte as \xHH, the result valid.
#include <ccd/io/utf8_text.hpp>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>

namespace ccd_io_utf8_text_test {

TEST_CASE("escape_invalid_utf8 keeps valid UTF-8 and escapes each invalid byte", "[io][utf8]") {
  SECTION("valid text is unchanged") {
    for (const std::string s : {"", "t.json", "caf\xc3\xa9/\xe2\x82\xac/\xf0\x9f\x98\x80.json"}) {
      CHECK(ccd::is_valid_utf8(s));
      CHECK(ccd::escape_invalid_utf8(s) == s);
    }
  }
  SECTION("the issue's names: t\\xff.json and the folder d\\xff/") {
    CHECK_FALSE(ccd::is_valid_utf8("t\xff.json"));
    CHECK(ccd::escape_invalid_utf8("t\xff.json") == "t\\xFF.json");
    CHECK(ccd::escape_invalid_utf8("d\xff/t.json") == "d\\xFF/t.json");
  }
  SECTION("stray continuation, truncated, overlong, surrogate and too large sequences") {
    CHECK(ccd::escape_invalid_utf8("a\x80z") == "a\\x80z");               // a lone continuation byte
    CHECK(ccd::escape_invalid_utf8("a\xc3") == "a\\xC3");                 // truncated at the end
    CHECK(ccd::escape_invalid_utf8("\xc0\xaf") == "\\xC0\\xAF");          // overlong '/'
    CHECK(ccd::escape_invalid_utf8("\xe0\x80\xaf") == "\\xE0\\x80\\xAF");  // overlong, 3 bytes
    CHECK(ccd::escape_invalid_utf8("\xed\xa0\x80") == "\\xED\\xA0\\x80");  // a surrogate, U+D800
    CHECK(ccd::escape_invalid_utf8("\xf4\x90\x80\x80") == "\\xF4\\x90\\x80\\x80");  // above U+10FFFF
    CHECK(ccd::escape_invalid_utf8("\xc3\xa9\xff\xc3\xa9") == "\xc3\xa9\\xFF\xc3\xa9");  // valid around it
  }
  SECTION("the escaped text is valid and nlohmann::json writes it") {
    const std::string name = "r\xfe\xff\x80.json";
    CHECK_THROWS(nlohmann::json(name).dump());  // what failed after the work
    const std::string escaped = ccd::escape_invalid_utf8(name);
    CHECK(ccd::is_valid_utf8(escaped));
    CHECK(nlohmann::json(escaped).dump() == "\"r\\\\xFE\\\\xFF\\\\x80.json\"");
  }
}

}  // namespace ccd_io_utf8_text_test
