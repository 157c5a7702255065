// The CCD query reader (`ccdlab ccd FILE.csv`, cloth/io/query_file.hpp) and, on the first
// query of an accepted file, what the command does with it: the exact rational solver and the
// conservative floating-point kernel, for both primitive pairs.
//
// Invariants: the three lists have one entry per query; every double coordinate is the
// nearest double of its rational; a file without inexact coordinates is written and read
// back to the same queries; and where the first query's coordinates are exact doubles, the
// kernel never misses a contact the exact solver finds (its guarantee,
// cloth/ccd/triangle_ccd.hpp).
#include "fuzz_support.hpp"

#include <ccd/io/input_error.hpp>
#include <cloth/ccd/triangle_ccd.hpp>
#include <cloth/exact/exact_ccd.hpp>
#include <cloth/io/query_file.hpp>

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
  using namespace ccd::cloth;
  QueryFile file;
  try {
    file = parse_query_file(std::string(ccdfuzz::as_text(data, size)), "fuzz.csv");
  } catch (const ccd::InputError&) {
    return 0;
  }
  const std::size_t n = file.queries.size();
  FUZZ_CHECK(file.exact.size() == n && file.expected.size() == n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t r = 0; r < 8; ++r)
      for (int k = 0; k < 3; ++k)
        FUZZ_CHECK(file.queries[i].x[r][k] == nearest_double(file.exact[i].x[r][static_cast<std::size_t>(k)]));
  if (file.inexact_coordinates != 0 || n == 0) return 0;
  const QueryFile again = parse_query_file(format_query_file(file.queries, file.expected), "again");
  FUZZ_CHECK(again.queries.size() == n && again.inexact_coordinates == 0 && again.expected == file.expected);
  for (std::size_t i = 0; i < n; ++i) FUZZ_CHECK(again.queries[i].x == file.queries[i].x);

  for (PrimitivePair kind : {PrimitivePair::VertexFace, PrimitivePair::EdgeEdge}) {
    const TriangleCcdResult r = triangle_ccd(kind, file.queries[0]);
    if (exact_contact(kind, file.exact[0], 0)) FUZZ_CHECK(r.status != ccd::QueryStatus::Miss);
  }
  return 0;
}
