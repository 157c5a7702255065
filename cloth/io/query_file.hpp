#pragma once
// Query files in the public CCD benchmark's CSV format (Wang et al. 2021, "A large scale
// benchmark and an inclusion-based algorithm for continuous collision detection").
//
// Eight rows per query, in LinearQuery's row order; each row has seven integer columns:
// x numerator, x denominator, y numerator, y denominator, z numerator, z denominator, and
// the expected result (0 or 1), the same on all eight rows. Integers are decimal, with an
// optional leading '-', of any length (the benchmark's reach about 112 bits); denominators
// are positive. Lines end with "\n" or "\r\n"; there is no header and no blank line.
//
// Reading is strict: any deviation throws InputError naming the file, the line and the
// column (`q.csv: line 17, column 2: denominator must be > 0`).
#include <cloth/ccd/linear_query.hpp>
#include <cloth/exact/exact_ccd.hpp>

#include <span>
#include <string>
#include <vector>

namespace ccd::cloth {

struct QueryFile {
  std::vector<RationalQuery> exact;  ///< the coordinates as written
  std::vector<LinearQuery> queries;  ///< each coordinate rounded to the nearest double
  std::vector<bool> expected;        ///< column 7
  std::size_t inexact_coordinates = 0;  ///< coordinates that are not doubles (rounded)
};

/// Reads a query file; `path` names it in errors. Throws InputError.
QueryFile read_query_file(const std::string& path);
/// Parses the text of a query file. Throws InputError naming `file`.
QueryFile parse_query_file(const std::string& text, const std::string& file);

/// The text of a query file for double queries (exact: every double is a dyadic rational).
std::string format_query_file(std::span<const LinearQuery> queries, const std::vector<bool>& expected);

/// The double nearest to q (ties to even); +-infinity beyond the largest double.
double nearest_double(const mpq_class& q);

}  // namespace ccd::cloth
