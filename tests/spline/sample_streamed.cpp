// Samples far larger than the caches are streamed past them (curve.cpp): the same doubles as a
// small sampling of each piece, which stays on the ordinary path, non-finite values included,
// in a block and in the partial block at a piece's end.
#include <catch2/catch.hpp>
#include <splinefig/spline/curve.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

using namespace splinefig;

namespace {

// Bits equal, or both NaN.
bool same(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Knots in [-1, 1] (xorshift), dim coordinates, with `bad` written at knot `at`.
Points knots(std::size_t n, int dim, std::size_t at, double bad) {
  Points p(dim, n);
  std::uint64_t s = 0x9E3779B97F4A7C15ull;
  for (double& x : p.coords) {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    x = static_cast<double>(s >> 11) * 0x1p-52 - 1.0;
  }
  p.coords[at * static_cast<std::size_t>(dim)] = bad;
  return p;
}

// Piece i of the curve sampled alone: its four knots, one piece, grain + 1 points.
std::vector<double> piece_alone(const Points& k, const Basis& b, std::size_t i, int grain, int derivative) {
  const std::size_t D = static_cast<std::size_t>(k.dim);
  Points four(k.dim);
  four.coords.assign(k.coords.begin() + static_cast<std::ptrdiff_t>(i * D),
                     k.coords.begin() + static_cast<std::ptrdiff_t>((i + 4) * D));
  const Curve c = make_curve(b, four, Ends::open);
  return sample(c, grain, derivative).coords;
}

}  // namespace

TEST_CASE("A sample larger than the caches gives the doubles of each piece sampled alone, non-finite ones too") {
  // grain x dim = 10 outputs a piece: two blocks of 4 and a partial block of 2 (weight_table.hpp).
  // 220000 knots: 2.2e6 doubles, 17.6 MB, over the streaming threshold (16 MiB).
  const int grain = 5, dim = 2;
  const std::size_t n = 220000, mid = 110000;
  for (const double bad : {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN(), 1e308}) {
    const Points k = knots(n, dim, mid, bad);
    for (const Basis& b : {catmull_rom(), bspline()})
      for (int derivative = 0; derivative <= 2; ++derivative) {
        const Curve c = make_curve(b, k, Ends::open);
        const std::size_t count = sample_count(c, grain) * static_cast<std::size_t>(dim);
        const std::size_t K = static_cast<std::size_t>(grain * dim);
        REQUIRE(count * sizeof(double) > (std::size_t{16} << 20));
        // The output 16-byte aligned (streamed) and one double further (the ordinary stores).
        std::vector<double> buffer(count + 3, -7.0);
        const std::size_t shift = reinterpret_cast<std::uintptr_t>(buffer.data()) % 16 == 0 ? 0 : 1;
        for (const std::size_t offset : {shift, shift + 1}) {
          INFO("bad knot " << bad << ", basis " << b.spec << ", derivative " << derivative << ", offset " << offset);
          std::span<double> out(buffer.data() + offset, count);
          sample_into(c, grain, derivative, out);
          std::vector<std::size_t> pieces{0, 1, c.segments() - 1};
          for (std::size_t i = mid - 4; i <= mid + 1; ++i) pieces.push_back(i);
          for (std::size_t i = 7; i < c.segments(); i += 10007) pieces.push_back(i);
          std::size_t non_finite = 0;
          for (const std::size_t i : pieces) {
            const std::vector<double> alone = piece_alone(k, b, i, grain, derivative);
            for (std::size_t j = 0; j < K; ++j) {
              INFO("piece " << i << ", output " << j);
              REQUIRE(same(out[i * K + j], alone[j]));
              non_finite += !std::isfinite(alone[j]);
            }
            if (i == c.segments() - 1)  // the final point, u = 1 of the last piece
              for (std::size_t j = K; j < K + static_cast<std::size_t>(dim); ++j) REQUIRE(same(out[i * K + j], alone[j]));
          }
          // The bad knot reaches the outputs (inf and NaN always; 1e308 where it overflows).
          if (!std::isfinite(bad)) CHECK(non_finite > 0);
          CHECK(buffer[offset + count] == -7.0);  // nothing written past the output
        }
      }
  }
}
