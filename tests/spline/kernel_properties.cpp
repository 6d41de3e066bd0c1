// Basis functions as filters: exact rational values, the degree-n matrices against seed
// 002's m_ij formula in exact rationals, Cox-de Boor as an independent oracle for the
// degree-n kernels, integrals, continuity classes, and the asymmetric Beta kernel.
#include <catch2/catch.hpp>
#include <splinefig/spline/basis.hpp>
#include <splinefig/kernel/analysis.hpp>
#include <splinefig/spline/basis_kernel.hpp>

#include <cmath>
#include <cstdlib>
#include <numeric>

using namespace splinefig;

namespace {

// Just enough exact arithmetic for the m_ij sums with n <= 5 (all terms far below 2^62).
struct Q {
  long long p = 0, q = 1;
  Q(long long p = 0, long long q = 1) : p(p), q(q) {
    if (this->q < 0) this->p = -this->p, this->q = -this->q;
    const long long g = std::gcd(std::llabs(this->p), this->q);
    if (g > 1) this->p /= g, this->q /= g;
  }
  friend Q operator+(Q a, Q b) { return {a.p * b.q + b.p * a.q, a.q * b.q}; }
  friend Q operator*(Q a, Q b) { return {a.p * b.p, a.q * b.q}; }
  friend bool operator==(Q a, Q b) { return a.p == b.p && a.q == b.q; }
  double value() const { return static_cast<double>(p) / static_cast<double>(q); }  // correctly rounded
};

long long binomial(int n, int k) {
  if (k < 0 || k > n) return 0;
  long long r = 1;
  for (int t = 1; t <= k; ++t) r = r * (n - k + t) / t;
  return r;
}

// Seed 002 §4.16.10: m_ij = 1/n! C(n,i) sum_{k=j..n} (n-k)^i (-1)^(k-j) C(n+1,k-j).
Q m_ij(int n, int i, int j) {
  Q sum;
  for (int k = j; k <= n; ++k) {
    long long pw = 1;
    for (int e = 0; e < i; ++e) pw *= (n - k);
    sum = sum + Q(((k - j) % 2 ? -1 : 1) * pw * binomial(n + 1, k - j));
  }
  long long fact = 1;
  for (int t = 2; t <= n; ++t) fact *= t;
  return Q(binomial(n, i)) * sum * Q(1, fact);
}

// The uniform B-spline of degree n on [0, n+1] by the Cox-de Boor recursion:
// N_0 = 1 on [0,1); N_n(x) = (x N_{n-1}(x) + (n+1-x) N_{n-1}(x-1)) / n.
double cox_de_boor(int n, double x) {
  if (n == 0) return (x >= 0 && x < 1) ? 1.0 : 0.0;
  return (x * cox_de_boor(n - 1, x) + (n + 1 - x) * cox_de_boor(n - 1, x - 1)) / n;
}

}  // namespace

TEST_CASE("Degree-n B-spline matrices, n = 1..5, equal seed 002's m_ij in exact rationals") {
  for (int n = 1; n <= 5; ++n) {
    const Basis b = uniform_bspline(n);
    REQUIRE(b.degree == n);
    REQUIRE(b.m.size() == static_cast<size_t>((n + 1) * (n + 1)));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        INFO("n = " << n << ", m_" << i << j);
        CHECK(b(i, j) == m_ij(n, i, j).value());
      }
  }
  // Spot values by hand: n = 1 is [-1 1; 1 0]; n = 2 is 1/2 [1 -2 1; -2 2 0; 1 1 0].
  CHECK(m_ij(1, 0, 0) == Q(-1));
  CHECK(m_ij(2, 0, 1) == Q(-1));
  CHECK(m_ij(2, 1, 0) == Q(-1));
  CHECK(m_ij(2, 2, 1) == Q(1, 2));
  // n = 3 is the memo's B = 1/6 [-1 3 -3 1; 3 -6 3 0; -3 0 3 0; 1 4 1 0].
  const long long B[4][4] = {{-1, 3, -3, 1}, {3, -6, 3, 0}, {-3, 0, 3, 0}, {1, 4, 1, 0}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) CHECK(m_ij(3, i, j) == Q(B[i][j], 6));
}

TEST_CASE("Degree-n kernels are the Cox-de Boor B-splines, centred by h = (n-1)/2") {
  for (int n = 1; n <= 7; ++n) {
    const Basis b = uniform_bspline(n);
    const Support s = kernel_support(b);
    CHECK(s.hi - s.lo == n + 1);
    for (int j = 0; j <= 40 * (n + 1); ++j) {
      const double x = s.lo + j / 40.0;
      INFO("n = " << n << ", s = " << x);
      CHECK(kernel(b, x) == Approx(cox_de_boor(n, x - s.lo)).margin(1e-14));
    }
  }
}

TEST_CASE("Exact kernel values: Catmull-Rom 9/16, -1/16, B-spline 23/48, 1/48, cardinal (4+a)/8, -a/8") {
  const Basis cr = catmull_rom(), bs = bspline();
  CHECK(kernel(cr, 0.5) == 9.0 / 16);
  CHECK(kernel(cr, -0.5) == 9.0 / 16);
  CHECK(kernel(cr, 1.5) == -1.0 / 16);
  CHECK(kernel(cr, -1.5) == -1.0 / 16);
  CHECK(kernel(bs, 0.5) == Approx(23.0 / 48).epsilon(1e-15));
  CHECK(kernel(bs, 1.5) == Approx(1.0 / 48).epsilon(1e-14));
  CHECK(kernel(bs, -1.5) == Approx(1.0 / 48).epsilon(1e-14));
  for (double a : {0.0, 0.25, 1.0, 2.0}) {
    INFO("a = " << a);
    CHECK(kernel(cardinal(a), 0.5) == Approx((4 + a) / 8).margin(1e-15));
    CHECK(kernel(cardinal(a), 1.5) == Approx(-a / 8).margin(1e-15));
  }
  // Derivatives: Catmull-Rom k'(1/2) = 3(3/2)(1/4) - 5(1/2) = -11/8; B-spline k''(0) = -2.
  CHECK(basis_kernel(cr).derivative(0.5, 1) == -11.0 / 8);
  CHECK(basis_kernel(bs).derivative(0.0, 2) == Approx(-2.0).epsilon(1e-15));
  CHECK(basis_kernel(bs).derivative(3.0, 1) == 0.0);
}

TEST_CASE("The Beta kernel with bias is not symmetric: b1 = 2, b2 = 0 gives k(-1), k(0), k(1) = 2, 24, 16 over 42") {
  // d = b2 + 2b1^3 + 4b1^2 + 4b1 + 2 = 42; at u = 0 the pieces are the matrix's last row.
  const Basis b = beta(2.0, 0.0);
  CHECK(kernel(b, -1) == Approx(2.0 / 42).epsilon(1e-15));
  CHECK(kernel(b, 0) == Approx(24.0 / 42).epsilon(1e-15));
  CHECK(kernel(b, 1) == Approx(16.0 / 42).epsilon(1e-15));
  CHECK(kernel(b, 0.5) != Approx(kernel(b, -0.5)));
  // b1 = 1 is the B-spline again, symmetric.
  for (double s : {0.25, 0.5, 1.25, 1.75}) CHECK(kernel(beta(1.0, 0.0), s) == Approx(kernel(beta(1.0, 0.0), -s)));
}

TEST_CASE("Kernel integrals are 1 for every family (partition of unity)") {
  for (const Basis& b : {catmull_rom(), cardinal(0.0), cardinal(1.7), bspline(), tensioned_bspline(0.25),
                         beta(2.0, 0.0), beta(0.3, 5.0), uniform_bspline(1), uniform_bspline(2), uniform_bspline(6)}) {
    INFO(b.spec);
    CHECK(basis_kernel(b).integral() == Approx(1.0).margin(1e-15));
    // And the integer translates sum to 1 everywhere: sum_j k(s - j) = 1.
    for (double s : {0.0, 0.125, 0.5, 0.875}) {
      double sum = 0;
      for (int j = -12; j <= 12; ++j) sum += kernel(b, s - j);
      CHECK(sum == Approx(1.0).margin(1e-14));
    }
  }
}

TEST_CASE("Continuity classes: cardinal C1, B-spline C2, Duff C1, Beta with bias C0, degree n C(n-1)") {
  CHECK(continuity(basis_kernel(catmull_rom())) == 1);
  CHECK(continuity(basis_kernel(cardinal(1.0))) == 1);
  CHECK(continuity(basis_kernel(cardinal(0.0))) == 1);  // the Hermite (smoothstep) kernel
  CHECK(continuity(basis_kernel(bspline())) == 2);
  CHECK(continuity(basis_kernel(tensioned_bspline(1.0))) == 2);
  CHECK(continuity(basis_kernel(tensioned_bspline(0.5))) == 1);  // b2 = 12 != 0: X'' jumps by b2 X'
  CHECK(continuity(basis_kernel(beta(2.0, 0.0))) == 0);          // X' jumps by the factor b1
  CHECK(continuity(basis_kernel(beta(1.0, 3.0))) == 1);
  for (int n = 1; n <= 6; ++n) CHECK(continuity(basis_kernel(uniform_bspline(n))) == n - 1);
  // Catmull-Rom's k'' at s = 0: c_1''(0) = -5 = c_2''(1), no jump; at s = 1:
  // c_0''(0) - c_1''(1) = 2 - 4 = -2 (c_0 = -u^3/2 + u^2 - u/2, c_1 = 3u^3/2 - 5u^2/2 + 1).
  const std::vector<double> j2 = jumps(basis_kernel(catmull_rom()), 2);
  REQUIRE(j2.size() == 5);  // knots -2, -1, 0, 1, 2
  CHECK(j2[2] == Approx(0.0).margin(1e-14));
  CHECK(j2[3] == Approx(-2.0).epsilon(1e-14));
  CHECK(j2[1] == Approx(2.0).epsilon(1e-14));  // k'' is even, so the jump at -1 is +2
}
