#include <cloth/io/query_file.hpp>

#include <ccd/io/input_error.hpp>

#include <catch2/catch.hpp>
#include <string>

namespace cloth_io_query_file_test {

using ccd::InputError;
using ccd::cloth::format_query_file;
using ccd::cloth::LinearQuery;
using ccd::cloth::nearest_double;
using ccd::cloth::parse_query_file;

namespace {

// Eight rows of one query, every row "x,1,y,1,z,1,e" with x the row index.
std::string rows(const std::string& expected = "1") {
  std::string s;
  for (int i = 0; i < 8; ++i) s += std::to_string(i) + ",1,0,1,0,1," + expected + "\n";
  return s;
}

std::string error_of(const std::string& text) {
  try {
    parse_query_file(text, "q.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("query files: values, 112-bit integers and round trips", "[cloth][io]") {
  SECTION("rationals are kept exactly and rounded to the nearest double") {
    // 1/3 is not a double: rounded, and counted. 2^112 + 1 over 2^112 rounds to 1.
    std::string text = "1,3,-5,4,5192296858534827628530496329220097,5192296858534827628530496329220096,0\n";
    for (int i = 1; i < 8; ++i) text += "0,1,0,1,0,1,0\n";
    const auto f = parse_query_file(text, "q.csv");
    REQUIRE(f.queries.size() == 1);
    CHECK(f.exact[0].x[0][0] == mpq_class(1, 3));
    CHECK(f.queries[0].x[0].x() == 1.0 / 3.0);
    CHECK(f.queries[0].x[0].y() == -1.25);
    CHECK(f.queries[0].x[0].z() == 1.0);
    CHECK(f.inexact_coordinates == 2);
    CHECK_FALSE(f.expected[0]);
  }
  SECTION("format then parse gives the same doubles; CRLF is accepted") {
    LinearQuery q;
    for (int i = 0; i < 8; ++i) q.x[static_cast<std::size_t>(i)] = ccd::Vec3(0.1 * i, -1e-300, 12345.678 * i);
    std::string text = format_query_file(std::span<const LinearQuery>(&q, 1), {true});
    const auto f = parse_query_file(text, "q.csv");
    CHECK(f.queries[0].x == q.x);
    CHECK(f.inexact_coordinates == 0);
    CHECK(f.expected[0]);
    std::string crlf;
    for (char c : text) {
      if (c == '\n') crlf += '\r';
      crlf += c;
    }
    CHECK(parse_query_file(crlf, "q.csv").queries[0].x == q.x);
  }
  SECTION("leading zeros are decimal, not octal") {
    // Regression (fuzz_query_file): the integers went to GMP with base 0, which reads a
    // leading 0 as octal: "010" was 8, and "09" (not octal) threw std::invalid_argument out
    // of the reader, ending `ccdlab ccd` with an uncaught exception instead of exit 2.
    std::string text = "010,1,-010,04,09,0001,0\n";
    for (int i = 1; i < 8; ++i) text += "0,1,0,1,0,1,0\n";
    const auto f = parse_query_file(text, "q.csv");
    CHECK(f.queries[0].x[0].x() == 10.0);
    CHECK(f.queries[0].x[0].y() == -2.5);
    CHECK(f.queries[0].x[0].z() == 9.0);
    CHECK(f.inexact_coordinates == 0);
  }
  SECTION("nearest_double rounds to nearest, ties to even") {
    CHECK(nearest_double(mpq_class(1, 3)) == 1.0 / 3.0);
    CHECK(nearest_double(mpq_class(-2, 3)) == -2.0 / 3.0);
    // 1 + 2^-53 is halfway between 1 and 1 + 2^-52: ties to the even significand, 1.
    mpq_class half = 1 + mpq_class(1) / (mpz_class(1) << 53);
    CHECK(nearest_double(half) == 1.0);
    mpq_class above = half + mpq_class(1) / (mpz_class(1) << 80);
    CHECK(nearest_double(above) == 1.0 + 0x1p-52);
  }
}

TEST_CASE("query files: every malformed input is an InputError naming line and column", "[cloth][io]") {
  CHECK(error_of(rows().substr(0, rows().size() - 14)) == "q.csv: line 7: the file ends inside a query (7 of 8 rows)");
  std::string blank_first = "\n";
  blank_first += rows();
  CHECK(error_of(blank_first) == "q.csv: line 1: blank line (8 rows of 7 integers per query)");
  CHECK(error_of("1,1,0,1,0,1\n") == "q.csv: line 1: expected 7 comma-separated integers, found 6 fields");
  CHECK(error_of("1,1,0,1,0,1,1,\n") == "q.csv: line 1: expected 7 comma-separated integers, found 8 fields");
  CHECK(error_of("1,1,0,1,0.5,1,1\n") == "q.csv: line 1, column 5: not a decimal integer: '0.5'");
  CHECK(error_of("1,1,0,1,,1,1\n") == "q.csv: line 1, column 5: not a decimal integer: ''");
  CHECK(error_of("1,1,0,1,- 1,1,1\n") == "q.csv: line 1, column 5: not a decimal integer: '- 1'");
  CHECK(error_of("1,1,0,0,0,1,1\n") == "q.csv: line 1, column 4: denominator must be > 0");
  CHECK(error_of("1,1,0,-3,0,1,1\n") == "q.csv: line 1, column 4: denominator must be > 0");
  CHECK(error_of("1,1,0,1,0,1,2\n") == "q.csv: line 1, column 7: expected result must be 0 or 1");
  const std::string huge = "1" + std::string(400, '0');
  std::string huge_row = huge;
  huge_row += ",1,0,1,0,1,1\n";
  CHECK(error_of(huge_row) == "q.csv: line 1, column 1: coordinate beyond the range of a double");
  std::string mixed = rows();
  mixed.replace(mixed.find("3,1,0,1,0,1,1"), 13, "3,1,0,1,0,1,0");
  CHECK(error_of(mixed) == "q.csv: line 4, column 7: expected result differs from the query's first row (line 1)");
  CHECK(error_of(rows() + rows("0")) == "no error");
}

}  // namespace cloth_io_query_file_test
