#pragma once
// Hand-built hard queries for vertex-face and edge-edge CCD: coplanar motion, parallel and
// collinear edges, zero motion, contact exactly at t = 0 and t = 1, a vertex on an edge,
// an edge through a vertex, degenerate and nearly degenerate primitives, and the same
// cases far from the origin. Every coordinate is dyadic (exact in binary), so the exact
// reference decides each case without any rounding. The tests and the query files in
// data/ccd/ (written by `ccdlab ccd --write-hard`) use them.
#include <cloth/ccd/linear_query.hpp>

#include <string>
#include <vector>

namespace ccd::cloth {

struct NamedQuery {
  std::string name;
  LinearQuery query;
  bool contact = false;  ///< the intended answer at separation 0 (the tests re-check it exactly)
};

std::vector<NamedQuery> hard_queries(PrimitivePair kind);

}  // namespace ccd::cloth
