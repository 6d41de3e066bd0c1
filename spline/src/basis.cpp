// The memo's basis matrices, its spec syntax, and the basis functions.
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/basis_kernel.hpp>
#include <splinefig/spline/near_miss.hpp>
#include <splinefig/spline/points_csv.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <string>

namespace splinefig {
namespace {

std::string fmt(double v) {
  std::array<char, 32> buf{};
  auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  (void)ec;
  return std::string(buf.data(), end);
}

Basis cubic(std::string family, std::string spec, std::array<double, 16> m) {
  return Basis{std::move(family), std::move(spec), 3, std::vector<double>(m.begin(), m.end())};
}

}  // namespace

Basis cardinal(double a) {
  // C_a = M1^-1 M2: X(0) = x0, X(1) = x1, X'(0) = a(x1 - x-1), X'(1) = a(x2 - x0).
  return cubic("cardinal", "cardinal:a=" + fmt(a),
               {-a, 2 - a, a - 2, a,        //
                2 * a, a - 3, 3 - 2 * a, -a,  //
                -a, 0, a, 0,                //
                0, 1, 0, 0});
}

Basis catmull_rom() {
  Basis b = cardinal(0.5);
  b.spec = "catmull-rom";
  return b;
}

Basis bspline() {
  // Each entry is an integer over 6, rounded once.
  return cubic("bspline", "bspline",
               {-1 / 6.0, 3 / 6.0, -3 / 6.0, 1 / 6.0,  //
                3 / 6.0, -6 / 6.0, 3 / 6.0, 0,         //
                -3 / 6.0, 0, 3 / 6.0, 0,               //
                1 / 6.0, 4 / 6.0, 1 / 6.0, 0});
}

Basis tensioned_bspline(double a) {
  // Duff's B_a; B_1 = B, and B_a = B_{1, 12(1-a)/a} (Barsky).
  return cubic("tensioned-bspline", "tensioned-bspline:a=" + fmt(a),
               {-a / 6, (12 - 9 * a) / 6, (9 * a - 12) / 6, a / 6,  //
                3 * a / 6, (12 * a - 18) / 6, (18 - 15 * a) / 6, 0,  //
                -3 * a / 6, 0, 3 * a / 6, 0,                         //
                a / 6, (6 - 2 * a) / 6, a / 6, 0});
}

Basis beta(double b1, double b2) {
  const double s2 = b1 * b1, s3 = s2 * b1;
  const double d = b2 + 2 * s3 + 4 * s2 + 4 * b1 + 2;
  if (d == 0 || !std::isfinite(d))
    throw SpecError("beta: no matrix for b1=" + fmt(b1) + ", b2=" + fmt(b2) +
                    ": its denominator d = b2 + 2b1^3 + 4b1^2 + 4b1 + 2 is zero");
  return cubic("beta", "beta:b1=" + fmt(b1) + ",b2=" + fmt(b2),
               {-2 * s3 / d, 2 * (b2 + s3 + s2 + b1) / d, -2 * (b2 + s2 + b1 + 1) / d, 2 / d,  //
                6 * s3 / d, -3 * (b2 + 2 * s3 + 2 * s2) / d, 3 * (b2 + 2 * s2) / d, 0,         //
                -6 * s3 / d, 6 * (s3 - b1) / d, 6 * b1 / d, 0,                                //
                2 * s3 / d, (b2 + 4 * (s2 + b1)) / d, 2 / d, 0});
}

Basis mitchell_netravali_basis(double b, double c) {
  return cubic("mitchell-netravali", "mitchell-netravali:b=" + fmt(b) + ",c=" + fmt(c),
               {(-b - 6 * c) / 6, (12 - 9 * b - 6 * c) / 6, (-12 + 9 * b + 6 * c) / 6, (b + 6 * c) / 6,  //
                (3 * b + 12 * c) / 6, (-18 + 12 * b + 6 * c) / 6, (18 - 15 * b - 12 * c) / 6, -c,         //
                (-3 * b - 6 * c) / 6, 0, (3 * b + 6 * c) / 6, 0,                                         //
                b / 6, (6 - 2 * b) / 6, b / 6, 0});
}

Basis uniform_bspline(int n) {
  if (n < 1 || n > 20)
    throw SpecError("uniform-bspline: degree=" + std::to_string(n) + " is out of range (1..20)");
  // Seed 002 §4.16.10: m_ij = 1/n! C(n,i) sum_{k=j..n} (n-k)^i (-1)^(k-j) C(n+1,k-j),
  // row i multiplying t^(n-i). Summed exactly in 128-bit integers, divided once.
  using i128 = __int128;
  auto binom = [](int a, int b) {
    i128 r = 1;
    for (int t = 1; t <= b; ++t) r = r * (a - b + t) / t;
    return r;
  };
  i128 fact = 1;
  for (int t = 2; t <= n; ++t) fact *= t;
  Basis b{"uniform-bspline", "uniform-bspline:degree=" + std::to_string(n), n, {}};
  b.m.resize(static_cast<size_t>((n + 1) * (n + 1)));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      i128 sum = 0;
      for (int k = j; k <= n; ++k) {
        i128 p = 1;
        for (int e = 0; e < i; ++e) p *= (n - k);
        const i128 term = p * binom(n + 1, k - j);
        sum += ((k - j) % 2 ? -term : term);
      }
      sum *= binom(n, i);
      b.m[static_cast<size_t>(i * (n + 1) + j)] = static_cast<double>(sum) / static_cast<double>(fact);
    }
  return b;
}

namespace {

// User text a message repeats: as given when at most 40 bytes of printable ASCII, else as
// excerpt() quotes it (cut at 40 bytes, with its size).
std::string clipped(std::string_view text) {
  const bool plain = text.size() <= 40 && std::all_of(text.begin(), text.end(), [](char c) { return c >= 0x20 && c < 0x7f; });
  return plain ? std::string(text) : excerpt(text, '\'');
}

// One number: a decimal (from_chars' general format, a leading '+' allowed), or an exact
// rational P/Q of integers (Q > 0), the double nearest P/Q (one rounding when |P|, |Q| <= 2^53),
// as the docs write the defaults: mitchell-netravali:b=1/3,c=1/3.
double parse_number(std::string_view name, std::string_view key, std::string_view text) {
  const std::string what = std::string(name) + ": value of '" + std::string(key) + "' ";
  const auto slash = text.find('/');
  if (slash != std::string_view::npos) {
    const auto integer = [](std::string_view t, bool sign) {
      if (sign && !t.empty() && (t[0] == '+' || t[0] == '-')) t.remove_prefix(1);
      return !t.empty() && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    const std::string_view p = text.substr(0, slash), q = text.substr(slash + 1);
    if (!integer(p, true) || !integer(q, false))
      throw SpecError(what + "is not a number or a fraction P/Q of integers: " + excerpt(text, '\''));
    const std::string_view ps = p[0] == '+' ? p.substr(1) : p;
    double num = 0, den = 0;
    std::from_chars(ps.data(), ps.data() + ps.size(), num);  // digits (after a '-'): cannot fail
    std::from_chars(q.data(), q.data() + q.size(), den);
    if (den == 0) throw SpecError(what + "divides by zero: " + excerpt(text, '\''));
    const double v = num / den;
    if (!std::isfinite(v)) throw SpecError(what + "is out of the range of a double: " + excerpt(text, '\''));
    return v;
  }
  double v = 0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (!text.empty() && *first == '+') ++first;
  auto [ptr, ec] = std::from_chars(first, last, v);
  if (!text.empty() && first != last && ec == std::errc::result_out_of_range && ptr == last)
    throw SpecError(what + "is out of the range of a double: " + excerpt(text, '\''));
  if (text.empty() || ec != std::errc() || ptr != last)
    throw SpecError(what + "is not a number: " + excerpt(text, '\''));
  if (!std::isfinite(v)) throw SpecError(what + "is not finite: " + excerpt(text, '\''));
  return v;
}

// A matrix whose entries overflow (e.g. cardinal:a=1e308, where 2a is infinite) evaluates to
// NaN: refuse it, naming the parameters as given.
Basis finite_matrix(Basis b, std::string_view name, const std::string& given) {
  for (const double v : b.m)
    if (!std::isfinite(v))
      throw SpecError(std::string(name) + ": " + given +
                      " is too large: the matrix has entries beyond the range of a double");
  return b;
}

}  // namespace

Basis parse_basis(std::string_view spec) {
  const auto colon = spec.find(':');
  std::string_view name = spec.substr(0, colon);
  // "mitchell", the name OpenImageIO and libvips give the filter, is mitchell-netravali.
  if (name == "mitchell") name = "mitchell-netravali";
  // The name as messages say it: as given when short, else quoted and cut (excerpt).
  const std::string shown = clipped(name);
  std::map<std::string, double, std::less<>> params;
  std::map<std::string, std::string, std::less<>> raw;
  if (colon != std::string_view::npos) {
    std::string_view rest = spec.substr(colon + 1);
    if (rest.empty()) throw SpecError(shown + ": empty parameter list after ':'");
    while (true) {
      const auto comma = rest.find(',');
      const std::string_view item = rest.substr(0, comma);
      const auto eq = item.find('=');
      if (eq == std::string_view::npos || eq == 0)
        throw SpecError(shown + ": parameter " + excerpt(item, '\'') + " is not key=value");
      const std::string key(item.substr(0, eq));
      if (raw.count(key)) throw SpecError(shown + ": parameter " + excerpt(key, '\'') + " given twice");
      raw[key] = std::string(item.substr(eq + 1));
      if (comma == std::string_view::npos) break;
      rest = rest.substr(comma + 1);
    }
  }
  auto take = [&](std::initializer_list<std::pair<const char*, double>> allowed) {
    for (const auto& [key, text] : raw) {
      bool ok = false;
      for (const auto& a : allowed) ok = ok || key == a.first;
      if (!ok) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + std::string(a.first);
        throw SpecError(shown + ": unknown parameter " + excerpt(key, '\'') +
                        (list.empty() ? " (it takes none)" : " (known: " + list + ")"));
      }
      params[key] = parse_number(shown, key, text);
    }
    for (const auto& a : allowed)
      if (!params.count(a.first)) params[a.first] = a.second;
  };

  if (name == "catmull-rom") {
    take({});
    return catmull_rom();
  }
  // The parameters as the user gave them (the default where not given), for messages.
  auto given = [&](const char* key) { return key + std::string("=") + (raw.count(key) ? clipped(raw[key]) : fmt(params[key])); };
  // Cardinal C_a and Duff's B_a have the tangent a (x1 - x-1) resp. a/2 (x1 - x-1) at knot x0: a < 0
  // turns it backwards at every knot; a = 0 stops there (the control polygon, their common limit).
  auto forward = [&](const char* family, const char* range) {
    if (params["a"] < 0)
      throw SpecError(std::string(family) + ": " + given("a") +
                      " is negative: the tangent at every knot would point backwards (a >= 0; " + range + ")");
  };
  if (name == "cardinal") {
    take({{"a", 0.5}});
    forward("cardinal", "a = 0 is the control polygon, 0.5 Catmull-Rom");
    return finite_matrix(cardinal(params["a"]), name, given("a"));
  }
  if (name == "bspline") {
    take({});
    return bspline();
  }
  if (name == "tensioned-bspline") {
    take({{"a", 1.0}});
    forward("tensioned-bspline", "a = 1 is the B-spline, a -> 0 the control polygon");
    return finite_matrix(tensioned_bspline(params["a"]), name, given("a"));
  }
  if (name == "beta") {
    take({{"b1", 1.0}, {"b2", 0.0}});
    const double b1 = params["b1"], b2 = params["b2"];
    const std::string both = given("b1") + "," + given("b2");
    const double s2 = b1 * b1, s3 = s2 * b1;
    const double d = b2 + 2 * s3 + 4 * s2 + 4 * b1 + 2;  // as beta() computes it
    if (!std::isfinite(d)) throw SpecError("beta: " + both + " is too large: the denominator d overflows");
    // b1 is the ratio of the velocities right and left of every joint; with b1 >= 0, d < 0 makes
    // the velocity at the knots of a straight, evenly spaced polygon point backwards.
    if (d != 0 && b1 < 0)
      throw SpecError("beta: " + given("b1") +
                      " is negative: b1 is the ratio of the velocities after and before every joint, so the "
                      "curve would reverse at each one (b1 >= 0)");
    if (d < 0)
      throw SpecError("beta: " + both +
                      ": the denominator d = b2 + 2b1^3 + 4b1^2 + 4b1 + 2 is negative, so the tangent at every "
                      "knot would point backwards (b2 > -(2b1^3 + 4b1^2 + 4b1 + 2))");
    return finite_matrix(beta(b1, b2), name, both);  // beta() refuses d = 0
  }
  if (name == "uniform-bspline") {
    take({{"degree", 3.0}});
    const double d = params["degree"];
    if (d != std::floor(d))
      throw SpecError("uniform-bspline: " + given("degree") + " is not an integer");
    if (d < 1 || d > 20)
      throw SpecError("uniform-bspline: " + given("degree") + " is out of range (1..20)");
    return uniform_bspline(static_cast<int>(d));
  }
  if (name == "mitchell-netravali") {
    take({{"b", 1.0 / 3}, {"c", 1.0 / 3}});
    return mitchell_netravali_basis(params["b"], params["c"]);
  }
  const auto near = near_misses(name, split_names(known_bases()));
  throw SpecError("unknown basis " + excerpt(name, '\'') + " (" + (near.empty() ? "" : "did you mean " + or_list(near) + "? ") +
                  "known: " + known_bases() + ")");
}

std::string known_bases() {
  return "catmull-rom, cardinal, bspline, tensioned-bspline, beta, uniform-bspline, mitchell-netravali";
}

double basis_segment(const Basis& b, int c, double u) {
  const int n = b.degree;
  double v = b(0, c);
  for (int r = 1; r <= n; ++r) v = v * u + b(r, c);
  return v;
}

Support kernel_support(const Basis& b) {
  const int h = (b.degree - 1) / 2;
  return {static_cast<double>(h - b.degree), static_cast<double>(h + 1)};
}

// Straight from the matrix columns, independently of the Kernel type (which tests check against it).
double kernel(const Basis& b, double s) {
  const int n = b.degree;
  const int h = (n - 1) / 2;
  // Every family here is continuous at the ends of its support, so k = 0 there exactly
  // (Horner at u = 1 would leave a rounding residue of the column sum).
  if (!(s > h - n && s < h + 1)) return 0.0;
  // Column c covers [h-c, h-c+1); the right end h+1 belongs to column 0.
  const int c = std::clamp(h - static_cast<int>(std::floor(s)), 0, n);
  return basis_segment(b, c, s - (h - c));
}

}  // namespace splinefig
