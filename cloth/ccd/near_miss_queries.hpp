#pragma once
// Near-miss queries for vertex-face and edge-edge CCD, in the style of the public
// benchmark's handcrafted sets: a vertex passing beside a face's edge or corner, stopping
// short of the face, sliding parallel above it or coplanar beside it; edges passing beside
// an end point, an end point stopping short, parallel and collinear edges sliding or
// falling short, nearly parallel edges. Each case misses by a gap g of 2^-27 to 2^-40
// (about 7e-9 to 9e-13 of the primitives' unit size), or touches by overlapping by g.
// Every case is built in a canonical frame, then rotated and moved (rounded to doubles),
// with a common velocity added to all four points; the far cases are 2^10 times larger and
// 2^20 from the origin. The intended answer survives the rounding (the gaps are far above
// it), and the query files (written by `ccdlab ccd --write-near-miss`) hold the answer of
// the exact reference. The cases come from a fixed seed, drawn with the raw output of
// std::mt19937_64 (defined by the standard), so they are the same on every platform.
#include <cloth/ccd/hard_queries.hpp>

#include <vector>

namespace ccd::cloth {

std::vector<NamedQuery> near_miss_queries(PrimitivePair kind);

}  // namespace ccd::cloth
