#include <cloth/exact/rational_polynomial.hpp>

#include <catch2/catch.hpp>

namespace cloth_exact_rational_polynomial_test {

using ccd::cloth::IsolatedRoot;
using ccd::cloth::RationalPolynomial;

namespace {
// (t - r1)(t - r2)...
RationalPolynomial with_roots(std::initializer_list<mpq_class> roots) {
  RationalPolynomial p = RationalPolynomial::constant(1);
  for (const mpq_class& r : roots) p = p * RationalPolynomial::linear(-r, 1);
  return p;
}
}  // namespace

TEST_CASE("rational polynomial arithmetic, gcd and square-free part", "[cloth][exact]") {
  const RationalPolynomial p = with_roots({mpq_class(1, 3), mpq_class(1, 2)});
  CHECK(p(mpq_class(1, 3)) == 0);
  CHECK(p(0) == mpq_class(1, 6));
  SECTION("division is exact and the remainder is of lower degree") {
    RationalPolynomial q, r;
    divide(p * RationalPolynomial::linear(1, 1) + RationalPolynomial::constant(5), p, q, r);
    CHECK(q == RationalPolynomial::linear(1, 1));
    CHECK(r == RationalPolynomial::constant(5));
  }
  SECTION("gcd of polynomials sharing one root is monic t - 1/2") {
    const RationalPolynomial g = gcd(p, with_roots({mpq_class(1, 2), mpq_class(7)}));
    CHECK(g == RationalPolynomial::linear(mpq_class(-1, 2), 1));
  }
  SECTION("square-free part of a double root") {
    const RationalPolynomial s = square_free(p * with_roots({mpq_class(1, 2)}));
    CHECK(s == p);  // (t-1/3)(t-1/2)^2 -> (t-1/3)(t-1/2), both monic
  }
}

TEST_CASE("root isolation and signs at algebraic roots", "[cloth][exact]") {
  SECTION("three close rational roots are isolated in order") {
    const RationalPolynomial q = with_roots({mpq_class(1, 3), mpq_class(1, 3) + mpq_class(1, 1 << 30), mpq_class(3, 4)});
    const auto roots = isolate_roots_in_unit_interval(q);
    REQUIRE(roots.size() == 3);
    CHECK(roots[0].b <= roots[1].a);
    CHECK(roots[0].a < mpq_class(1, 3));
    CHECK(roots[0].b > mpq_class(1, 3));
    CHECK(roots[2].a < mpq_class(3, 4));
    CHECK(roots[2].b > mpq_class(3, 4));
  }
  SECTION("roots outside (0, 1) are not reported") {
    CHECK(isolate_roots_in_unit_interval(with_roots({mpq_class(-1, 2), mpq_class(3, 2)})).empty());
  }
  SECTION("sign of g at sqrt(1/2), root of 2t^2 - 1") {
    const RationalPolynomial q({-1, 0, 2});
    auto roots = isolate_roots_in_unit_interval(q);
    REQUIRE(roots.size() == 1);
    IsolatedRoot r = roots[0];
    // t - 7071/10000 > 0 at 0.70710678..., t - 7072/10000 < 0, 4t^4 - 1 = 0 there.
    CHECK(sign_at_root(RationalPolynomial::linear(mpq_class(-7071, 10000), 1), q, r) == 1);
    CHECK(sign_at_root(RationalPolynomial::linear(mpq_class(-7072, 10000), 1), q, r) == -1);
    CHECK(sign_at_root(RationalPolynomial({-1, 0, 0, 0, 4}), q, r) == 0);
    // A double root of g at the same point: g = (2t^2 - 1)^2 is zero there, not positive.
    CHECK(sign_at_root(q * q, q, r) == 0);
    CHECK(sign_at_root(q * q + RationalPolynomial::constant(mpq_class(1, 1000000)), q, r) == 1);
  }
}

}  // namespace cloth_exact_rational_polynomial_test
