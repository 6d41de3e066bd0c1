// The memo's matrices, entered here by hand from the memo's text, and the identities
// C_a = M1^-1 M2, B = B_1 = B_{1,0}, B_a = B_{1,12(1-a)/a}.
#include <catch2/catch.hpp>
#include <splinefig/spline/basis.hpp>

using namespace splinefig;

namespace {
void check_matrix(const Basis& b, const double (&expect)[4][4], double tol = 0) {
  REQUIRE(b.degree == 3);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      INFO("row " << r << " col " << c);
      if (tol == 0)
        CHECK(b(r, c) == expect[r][c]);
      else
        CHECK(b(r, c) == Approx(expect[r][c]).margin(tol));
    }
}

// The SpecError message for a spec, or "no error".
std::string msg(const char* spec) {
  try {
    parse_basis(spec);
  } catch (const SpecError& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST_CASE("Catmull-Rom matrix is the memo's C = 1/2 [...]") {
  const double C[4][4] = {{-0.5, 1.5, -1.5, 0.5}, {1, -2.5, 2, -0.5}, {-0.5, 0, 0.5, 0}, {0, 1, 0, 0}};
  check_matrix(catmull_rom(), C);
  check_matrix(parse_basis("catmull-rom"), C);
  check_matrix(parse_basis("cardinal"), C);
  check_matrix(parse_basis("cardinal:a=0.5"), C);
}

TEST_CASE("B-spline matrix is the memo's B = 1/6 [...]") {
  const double B[4][4] = {{-1 / 6.0, 3 / 6.0, -3 / 6.0, 1 / 6.0},
                          {3 / 6.0, -6 / 6.0, 3 / 6.0, 0},
                          {-3 / 6.0, 0, 3 / 6.0, 0},
                          {1 / 6.0, 4 / 6.0, 1 / 6.0, 0}};
  check_matrix(bspline(), B);
  check_matrix(tensioned_bspline(1.0), B, 1e-16);
  check_matrix(beta(1.0, 0.0), B, 1e-16);
  check_matrix(uniform_bspline(3), B, 1e-16);
}

TEST_CASE("Cardinal C_a = M1^-1 M2 for several a") {
  // M1^-1 for M1 = [0 0 0 1; 1 1 1 1; 0 0 1 0; 3 2 1 0] (hand-inverted: Hermite matrix).
  const double M1inv[4][4] = {{2, -2, 1, 1}, {-3, 3, -2, -1}, {0, 0, 1, 0}, {1, 0, 0, 0}};
  for (double a : {0.0, 0.25, 0.5, 1.0, -0.3, 2.0}) {
    const double M2[4][4] = {{0, 1, 0, 0}, {0, 0, 1, 0}, {-a, 0, a, 0}, {0, -a, 0, a}};
    double P[4][4] = {};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k) P[r][c] += M1inv[r][k] * M2[k][c];
    INFO("a = " << a);
    check_matrix(cardinal(a), P, 1e-15);
  }
}

TEST_CASE("Duff's B_a equals Barsky's B_{1, 12(1-a)/a}") {
  for (double a : {1.0, 0.5, 0.25, 0.1, 2.0}) {
    const Basis d = tensioned_bspline(a), b = beta(1.0, 12 * (1 - a) / a);
    INFO("a = " << a);
    for (int i = 0; i < 16; ++i) CHECK(d.m[i] == Approx(b.m[i]).margin(1e-14));
  }
}

TEST_CASE("Beta-spline matrices with b1 != 1 derived from Barsky's definition in exact fractions") {
  // Barsky's definition (the memo's Beta-spline section): the segment Q_i(u) = sum_{r=-2..1}
  // V_{i+r} b_r(u) of cubics b_r, with Q_{i+1}(0) = Q_i(1), Q_{i+1}'(0) = b1 Q_i'(1) and
  // Q_{i+1}''(0) = b1^2 Q_i''(1) + b2 Q_i'(1) for every polygon V, and sum_r b_r(u) = 1.
  // The coefficient of each V_{i+r} gives 15 linear equations in the 16 coefficients, the
  // partition of unity 4 more; solved exactly with Python's fractions (beta_derivation.py in
  // this directory, which also checks that the solution is unique), not from the memo's
  // printed matrix. Columns are b_{-2} .. b_1 (x[i-1] .. x[i+2]), rows u^3 .. 1. Every entry
  // agrees with the memo's matrix over d = b2 + 2b1^3 + 4b1^2 + 4b1 + 2 (43, 33/4, 104, 515/54).
  // Spot check by hand, b1 = 2, b2 = 1: row u, column x[i]: 6(b1^3 - b1)/d = 36/43; the
  // constant row sums to (16 + 25 + 2)/43 = 1.
  // Where b1 and the fractions' operands are doubles, beta() divides exactly representable
  // numerators by d once, as the division of the fraction below does, so the doubles agree
  // bit for bit; b1 = 2/3 is not a double and agrees to 1e-15.
  const double b21[4][4] = {{-16.0 / 43, 30.0 / 43, -16.0 / 43, 2.0 / 43},
                            {48.0 / 43, -75.0 / 43, 27.0 / 43, 0},
                            {-48.0 / 43, 36.0 / 43, 12.0 / 43, 0},
                            {16.0 / 43, 25.0 / 43, 2.0 / 43, 0}};
  check_matrix(beta(2.0, 1.0), b21);
  check_matrix(parse_basis("beta:b1=2,b2=1"), b21);
  const double bhalf3[4][4] = {{-1.0 / 33, 31.0 / 33, -38.0 / 33, 8.0 / 33},
                               {1.0 / 11, -15.0 / 11, 14.0 / 11, 0},
                               {-1.0 / 11, -3.0 / 11, 4.0 / 11, 0},
                               {1.0 / 33, 8.0 / 11, 8.0 / 33, 0}};
  check_matrix(beta(0.5, 3.0), bhalf3);
  const double b30[4][4] = {{-27.0 / 52, 3.0 / 4, -1.0 / 4, 1.0 / 52},
                            {81.0 / 52, -27.0 / 13, 27.0 / 52, 0},
                            {-81.0 / 52, 18.0 / 13, 9.0 / 52, 0},
                            {27.0 / 52, 6.0 / 13, 1.0 / 52, 0}};
  check_matrix(beta(3.0, 0.0), b30);
  const double b23[4][4] = {{-32.0 / 515, 422.0 / 515, -498.0 / 515, 108.0 / 515},
                            {96.0 / 515, -129.0 / 103, 549.0 / 515, 0},
                            {-96.0 / 515, -24.0 / 103, 216.0 / 515, 0},
                            {32.0 / 515, 75.0 / 103, 108.0 / 515, 0}};
  check_matrix(beta(2.0 / 3, 2.5), b23, 1e-15);
}

TEST_CASE("Kernel values: Catmull-Rom k(0)=1 and min -2/27 at 4/3, B-spline 2/3 and 1/6") {
  const Basis c = catmull_rom(), b = bspline();
  CHECK(kernel(c, 0) == 1.0);
  CHECK(kernel(c, 1) == 0.0);
  CHECK(kernel(c, -1) == 0.0);
  CHECK(kernel(c, 2) == 0.0);
  CHECK(kernel(c, 4.0 / 3) == Approx(-2.0 / 27).epsilon(1e-14));
  CHECK(kernel(c, -4.0 / 3) == Approx(-2.0 / 27).epsilon(1e-14));
  CHECK(kernel(b, 0) == Approx(2.0 / 3).epsilon(1e-15));
  CHECK(kernel(b, 1) == Approx(1.0 / 6).epsilon(1e-15));
  CHECK(kernel(b, -1) == Approx(1.0 / 6).epsilon(1e-15));
  CHECK(kernel(b, 2) == 0.0);
  CHECK(kernel(b, 3) == 0.0);
}

TEST_CASE("Invalid basis specs name what is wrong") {
  CHECK_THAT(msg("bezier"), Catch::Contains("unknown basis 'bezier'"));
  CHECK_THAT(msg("cardinal:b=1"), Catch::Contains("unknown parameter 'b'"));
  CHECK_THAT(msg("cardinal:a=nan"), Catch::Contains("not finite"));
  CHECK_THAT(msg("cardinal:a=x"), Catch::Contains("not a number"));
  CHECK_THAT(msg("beta:b1=-1,b2=0"), Catch::Contains("is zero"));
  CHECK_THAT(msg("catmull-rom:a=1"), Catch::Contains("takes none"));
  CHECK_THAT(msg("uniform-bspline:degree=2.5"), Catch::Contains("not an integer"));
  CHECK_THAT(msg("uniform-bspline:degree=0"), Catch::Contains("out of range"));
  CHECK_THAT(msg("cardinal:a=1,a=2"), Catch::Contains("given twice"));
}

TEST_CASE("Spec parameters: negative tangents and overflow are refused, the polygon limits accepted") {
  // Out of the range of a double is not "not a number".
  CHECK(msg("cardinal:a=1e400") == "cardinal: value of 'a' is out of the range of a double: '1e400'");
  CHECK_THAT(msg("uniform-bspline:degree=-1e999"), Catch::Contains("out of the range of a double"));
  // Matrices whose entries overflow (2a, 9a, 2b2, b1^3 beyond 1.8e308) would evaluate to NaN.
  CHECK(msg("cardinal:a=1e308") == "cardinal: a=1e308 is too large: the matrix has entries beyond the range of a double");
  CHECK_THAT(msg("tensioned-bspline:a=1e308"), Catch::Contains("a=1e308 is too large"));
  CHECK_THAT(msg("tensioned-bspline:a=-1e308"), Catch::Contains("negative"));
  CHECK_THAT(msg("beta:b1=1e103"), Catch::Contains("b1=1e103,b2=0 is too large"));
  CHECK_THAT(msg("beta:b2=1e308"), Catch::Contains("b1=1,b2=1e308 is too large"));
  // The tangent at knot x0 is a (x1 - x-1) for C_a, a/2 (x1 - x-1) for B_a: a < 0 points it backwards.
  CHECK_THAT(msg("cardinal:a=-1"), Catch::Contains("cardinal: a=-1 is negative: the tangent at every knot"));
  CHECK_THAT(msg("cardinal:a=-1e-300"), Catch::Contains("negative"));
  CHECK_THAT(msg("tensioned-bspline:a=-1"), Catch::Contains("tensioned-bspline: a=-1 is negative"));
  // b1 is the velocity ratio at every joint: b1 < 0 reverses the curve there. b1 = -1, b2 = 0 has
  // no matrix at all (d = 0); with b1 >= 0, b2 < -(2b1^3 + 4b1^2 + 4b1 + 2) makes d < 0.
  CHECK_THAT(msg("beta:b1=-0.5,b2=0"), Catch::Contains("beta: b1=-0.5 is negative"));
  CHECK_THAT(msg("beta:b1=-1,b2=0"), Catch::Contains("is zero"));
  CHECK_THAT(msg("beta:b1=-1,b2=3"), Catch::Contains("negative"));
  CHECK_THAT(msg("beta:b1=1,b2=-13"), Catch::Contains("the denominator d = b2 + 2b1^3 + 4b1^2 + 4b1 + 2 is negative"));
  CHECK_THAT(msg("beta:b1=0,b2=-2.5"), Catch::Contains("is negative"));
  CHECK_THAT(msg("beta:b1=0,b2=-2"), Catch::Contains("is zero"));

  // Accepted: a = 1 and a = +1e300, every value the figures use, negative tension where d > 0.
  for (const char* ok : {"cardinal:a=1", "cardinal:a=+1", "cardinal:a=1e300", "cardinal:a=-0", "tensioned-bspline:a=1",
                         "tensioned-bspline:a=3", "tensioned-bspline:a=0.1", "beta:b1=0.2,b2=0", "beta:b1=3,b2=150",
                         "beta:b1=1,b2=-11.9", "beta:b1=0,b2=-1.5", "beta:b1=1e-300"})
    CHECK(msg(ok) == "no error");
  // The a = 0 limits of C_a and B_a are both the control polygon traversed by the cubic Hermite
  // blend 3u^2 - 2u^3 (zero tangents); b1 = b2 = 0 is the polygon traversed as u^3.
  const double hermite[4][4] = {{0, 2, -2, 0}, {0, -3, 3, 0}, {0, 0, 0, 0}, {0, 1, 0, 0}};
  check_matrix(parse_basis("cardinal:a=0"), hermite);
  check_matrix(parse_basis("tensioned-bspline:a=0"), hermite);
  const double cubed[4][4] = {{0, 0, -1, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 1, 0}};
  check_matrix(parse_basis("beta:b1=0,b2=0"), cubed);
}

TEST_CASE("Canonical specs read back to the same basis") {
  for (const char* spec : {"catmull-rom", "cardinal:a=0.1", "bspline", "tensioned-bspline:a=0.3333333333333333",
                           "beta:b1=2.5,b2=1e-07", "uniform-bspline:degree=5"}) {
    const Basis b = parse_basis(spec);
    INFO(spec << " -> " << b.spec);
    CHECK(b.spec == spec);
    const Basis again = parse_basis(b.spec);
    CHECK(again.m == b.m);
    CHECK(again.family == b.family);
  }
  // Defaults and key order do not matter; the spec comes back in canonical form.
  CHECK(parse_basis("beta:b2=3,b1=0.5").spec == "beta:b1=0.5,b2=3");
  CHECK(parse_basis("beta").spec == "beta:b1=1,b2=0");
  CHECK(parse_basis("uniform-bspline").spec == "uniform-bspline:degree=3");
}
