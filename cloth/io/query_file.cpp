#include "query_file.hpp"

#include <ccd/io/input_error.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace ccd::cloth {

double nearest_double(const mpq_class& q) {
  const double d = q.get_d();  // truncated towards zero
  if (!std::isfinite(d)) return d;
  double best = d;
  mpq_class best_gap = abs(mpq_class(d) - q);
  for (double c : {std::nextafter(d, std::numeric_limits<double>::infinity()),
                   std::nextafter(d, -std::numeric_limits<double>::infinity())}) {
    if (!std::isfinite(c)) continue;
    const mpq_class gap = abs(mpq_class(c) - q);
    int exponent = 0;
    const bool even = std::fmod(std::ldexp(std::frexp(c, &exponent), 53), 2.0) == 0.0;
    // Nearest; on a tie the even significand (get_d's truncation never ties both ways).
    if (gap < best_gap || (gap == best_gap && even)) {
      best = c;
      best_gap = gap;
    }
  }
  return best;
}

namespace {

std::string where(std::size_t line, std::size_t column) {
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// A decimal integer: optional '-', then digits, nothing else.
bool is_integer(const std::string& s) {
  std::size_t i = s.size() > 0 && s[0] == '-' ? 1 : 0;
  if (i == s.size()) return false;
  for (; i < s.size(); ++i)
    if (s[i] < '0' || s[i] > '9') return false;
  return true;
}

}  // namespace

QueryFile parse_query_file(const std::string& text, const std::string& file) {
  QueryFile out;
  std::size_t line_no = 0, pos = 0;
  RationalQuery exact;
  LinearQuery query;
  int expected = -1;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) throw InputError(file, "line " + std::to_string(line_no), "blank line (8 rows of 7 integers per query)");
    std::vector<std::string> cols;
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = line.find(',', start);
      cols.push_back(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (cols.size() != 7)
      throw InputError(file, "line " + std::to_string(line_no), "expected 7 comma-separated integers, found " + std::to_string(cols.size()) + " fields");
    const std::size_t row = (line_no - 1) % 8;
    for (std::size_t c = 0; c < 7; ++c)
      if (!is_integer(cols[c])) throw InputError(file, where(line_no, c + 1), "not a decimal integer: '" + cols[c].substr(0, 40) + "'");
    for (std::size_t k = 0; k < 3; ++k) {
      // Base 10 always: GMP's default (base 0) would read a leading 0 as octal ("010" = 8).
      const mpz_class num(cols[2 * k], 10), den(cols[2 * k + 1], 10);
      if (sgn(den) <= 0) throw InputError(file, where(line_no, 2 * k + 2), "denominator must be > 0");
      mpq_class v(num, den);
      v.canonicalize();
      const double d = nearest_double(v);
      if (!std::isfinite(d)) throw InputError(file, where(line_no, 2 * k + 1), "coordinate beyond the range of a double");
      if (mpq_class(d) != v) ++out.inexact_coordinates;
      exact.x[row][k] = v;
      query.x[row][static_cast<int>(k)] = d;
    }
    if (cols[6] != "0" && cols[6] != "1") throw InputError(file, where(line_no, 7), "expected result must be 0 or 1");
    const int e = cols[6] == "1";
    if (row == 0) {
      expected = e;
    } else if (e != expected) {
      throw InputError(file, where(line_no, 7), "expected result differs from the query's first row (line " +
                                                     std::to_string(line_no - row) + ")");
    }
    if (row == 7) {
      out.exact.push_back(exact);
      out.queries.push_back(query);
      out.expected.push_back(expected == 1);
    }
  }
  if (line_no % 8 != 0)
    throw InputError(file, "line " + std::to_string(line_no), "the file ends inside a query (" + std::to_string(line_no % 8) + " of 8 rows)");
  return out;
}

QueryFile read_query_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the file");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw InputError(path, "", "cannot read the file");
  return parse_query_file(ss.str(), path);
}

std::string format_query_file(std::span<const LinearQuery> queries, const std::vector<bool>& expected) {
  std::string out;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    for (const Vec3& p : queries[i].x) {
      for (int k = 0; k < 3; ++k) {
        const mpq_class v(p[k]);  // exact
        out += v.get_num().get_str() + "," + v.get_den().get_str() + ",";
      }
      out += expected[i] ? "1\n" : "0\n";
    }
  }
  return out;
}

}  // namespace ccd::cloth
