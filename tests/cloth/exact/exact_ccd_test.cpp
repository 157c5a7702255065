#include <cloth/ccd/hard_queries.hpp>
#include <cloth/exact/exact_ccd.hpp>

#include <catch2/catch.hpp>

namespace cloth_exact_exact_ccd_test {

using ccd::Vec3;
using ccd::cloth::exact_contact;
using ccd::cloth::hard_queries;
using ccd::cloth::LinearQuery;
using ccd::cloth::PrimitivePair;
using ccd::cloth::to_rational;

TEST_CASE("exact CCD decides every hand-built hard case as intended", "[cloth][exact]") {
  for (PrimitivePair kind : {PrimitivePair::VertexFace, PrimitivePair::EdgeEdge}) {
    for (const auto& c : hard_queries(kind)) {
      INFO(c.name);
      CHECK(exact_contact(kind, to_rational(c.query), 0) == c.contact);
    }
  }
}

TEST_CASE("exact CCD with a minimum separation", "[cloth][exact]") {
  // A vertex passing 1/4 above the corner-free middle of the unit right triangle's plane:
  // distance 1/4, reached on the whole motion.
  const Vec3 f0(0, 0, 0), f1(1, 0, 0), f2(0, 1, 0);
  const LinearQuery above{{Vec3(-1, 0.25, 0.25), f0, f1, f2, Vec3(2, 0.25, 0.25), f0, f1, f2}};
  SECTION("vertex-face: distance exactly the separation counts; just above does not") {
    CHECK(exact_contact(PrimitivePair::VertexFace, to_rational(above), mpq_class(1, 16)));
    CHECK_FALSE(exact_contact(PrimitivePair::VertexFace, to_rational(above), mpq_class(1, 16) - mpq_class(1, 1 << 30)));
  }
  SECTION("vertex-face: nearest feature is a corner (distance sqrt(2)/4 from f0)") {
    // Vertex still at (-1/4, -1/4, 0): distance to the triangle is |(-1/4,-1/4)| = sqrt(1/8).
    const LinearQuery q{{Vec3(-0.25, -0.25, 0), f0, f1, f2, Vec3(-0.25, -0.25, 0), f0, f1, f2}};
    CHECK(exact_contact(PrimitivePair::VertexFace, to_rational(q), mpq_class(1, 8)));
    CHECK_FALSE(exact_contact(PrimitivePair::VertexFace, to_rational(q), mpq_class(1, 8) - mpq_class(1, 1 << 30)));
  }
  SECTION("vertex-face: nearest feature is an edge") {
    // Vertex still at (1/2, -1/2, 1/2): distance to edge f0 f1 is sqrt(1/2).
    const LinearQuery q{{Vec3(0.5, -0.5, 0.5), f0, f1, f2, Vec3(0.5, -0.5, 0.5), f0, f1, f2}};
    CHECK(exact_contact(PrimitivePair::VertexFace, to_rational(q), mpq_class(1, 2)));
    CHECK_FALSE(exact_contact(PrimitivePair::VertexFace, to_rational(q), mpq_class(1, 2) - mpq_class(1, 1 << 30)));
  }
  SECTION("edge-edge: skew edges 1/8 apart at closest, and an end point 1/2 away") {
    const LinearQuery skew{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, -1, 0.125), Vec3(0.5, 1, 0.125), Vec3(0, 0, 0),
                            Vec3(1, 0, 0), Vec3(0.5, -1, 0.125), Vec3(0.5, 1, 0.125)}};
    CHECK(exact_contact(PrimitivePair::EdgeEdge, to_rational(skew), mpq_class(1, 64)));
    CHECK_FALSE(exact_contact(PrimitivePair::EdgeEdge, to_rational(skew), mpq_class(1, 64) - mpq_class(1, 1 << 30)));
    const LinearQuery ends{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1.5, 0, 0), Vec3(2, 1, 0), Vec3(0, 0, 0), Vec3(1, 0, 0),
                            Vec3(1.5, 0, 0), Vec3(2, 1, 0)}};
    CHECK(exact_contact(PrimitivePair::EdgeEdge, to_rational(ends), mpq_class(1, 4)));
    CHECK_FALSE(exact_contact(PrimitivePair::EdgeEdge, to_rational(ends), mpq_class(1, 4) - mpq_class(1, 1 << 30)));
  }
}

}  // namespace cloth_exact_exact_ccd_test
