// Lagrange interpolation (seed 003 Figure 1): exact reproduction of polynomials, the data
// points themselves, and the swing of the degree-10 interpolant of docs/figures.md's step data.
#include <catch2/catch.hpp>
#include <splinefig/spline/lagrange.hpp>

#include <vector>

using namespace splinefig;

TEST_CASE("Lagrange reproduces a cubic from any 5 samples and passes through its data") {
  auto f = [](double t) { return std::vector<double>{2 * t * t * t - t + 1, -t * t + 4}; };
  const std::vector<double> ts{-1.5, 0.25, 1, 2.5, 3};
  Points S(2);
  for (double t : ts) S.push_back(f(t));
  const LagrangePolynomial p = lagrange(ts, S);
  for (double t = -2; t <= 4; t += 0.125) {
    std::vector<double> x(2);
    evaluate(p, t, x);
    CHECK(x[0] == Approx(f(t)[0]).margin(1e-12));
    CHECK(x[1] == Approx(f(t)[1]).margin(1e-12));
  }
  std::vector<double> x(2);
  evaluate(p, 2.5, x);
  CHECK(x[0] == S[3][0]);
}

TEST_CASE("Seed 003 Figure 1: the degree-10 interpolant of a step swings far out near the ends") {
  // docs/figures.md s003-fig01: t = 0..10, y = 0,0,0,0,0,1,1,1,1,1,1. Exact values by rational
  // arithmetic: P(1/2) = 362017/131072, P(19/2) = 415701/131072, P(3/2) = -75563/131072.
  std::vector<double> ts;
  Points S(1);
  for (int k = 0; k <= 10; ++k) {
    ts.push_back(k);
    S.push_back(std::vector<double>{k >= 5 ? 1.0 : 0.0});
  }
  const LagrangePolynomial p = lagrange(ts, S);
  std::vector<double> x(1);
  evaluate(p, 0.5, x);
  CHECK(x[0] == Approx(362017.0 / 131072).epsilon(1e-13));
  evaluate(p, 9.5, x);
  CHECK(x[0] == Approx(415701.0 / 131072).epsilon(1e-13));
  evaluate(p, 1.5, x);
  CHECK(x[0] == Approx(-75563.0 / 131072).epsilon(1e-12));
}

TEST_CASE("Lagrange refuses coincident parameters and mismatched sizes") {
  Points S(1);
  S.push_back(std::vector<double>{1});
  S.push_back(std::vector<double>{2});
  CHECK_THROWS_WITH(lagrange({1, 1}, S), Catch::Contains("coincide"));
  CHECK_THROWS_WITH(lagrange({1}, S), Catch::Contains("one parameter value per data point"));
}
