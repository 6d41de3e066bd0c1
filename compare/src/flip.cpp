// LDR-FLIP (see perceptual.hpp). Every 2-D filter of the paper is a sum of separable
// Gaussians, so it is applied as row and column passes; borders replicate the edge pixels.
#include <splinefig/compare/perceptual.hpp>
#include <splinefig/image/srgb.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace splinefig::compare {
namespace {

using Plane = std::vector<float>;
using Rgb = std::array<float, 3>;

constexpr double pi = std::numbers::pi;
constexpr float qc = 0.7f, qf = 0.5f, pc = 0.4f, pt = 0.95f;
// D65 white and its inverse (the paper's reference illuminant).
constexpr Rgb white = {0.950428545f, 1.0f, 1.088900371f};
constexpr Rgb inv_white = {1.052156925f, 1.0f, 0.918357670f};

Rgb linrgb_to_xyz(const Rgb& c) {
  return {float((10135552.0 / 24577794.0) * c[0] + (8788810.0 / 24577794.0) * c[1] + (4435075.0 / 24577794.0) * c[2]),
          float((2613072.0 / 12288897.0) * c[0] + (8788810.0 / 12288897.0) * c[1] + (887015.0 / 12288897.0) * c[2]),
          float((1425312.0 / 73733382.0) * c[0] + (8788810.0 / 73733382.0) * c[1] + (70074185.0 / 73733382.0) * c[2])};
}

Rgb xyz_to_linrgb(const Rgb& c) {
  return {3.241003275f * c[0] - 1.537398934f * c[1] - 0.498615861f * c[2],
          -0.969224334f * c[0] + 1.875930071f * c[1] + 0.041554224f * c[2],
          0.055639423f * c[0] - 0.204011202f * c[1] + 1.057148933f * c[2]};
}

Rgb xyz_to_ycxcz(const Rgb& c) {
  const float x = c[0] * inv_white[0], y = c[1] * inv_white[1], z = c[2] * inv_white[2];
  return {116.0f * y - 16.0f, 500.0f * (x - y), 200.0f * (y - z)};
}

Rgb ycxcz_to_xyz(const Rgb& c) {
  const float y = (c[0] + 16.0f) / 116.0f, cx = c[1] / 500.0f, cz = c[2] / 200.0f;
  return {(y + cx) * white[0], y * white[1], (y - cz) * white[2]};
}

Rgb xyz_to_lab(const Rgb& c) {
  constexpr float delta = 6.0f / 29.0f;
  auto f = [&](float t) {
    return t > delta * delta * delta ? std::cbrt(t) : t / (3.0f * delta * delta) + 4.0f / 29.0f;
  };
  const float fx = f(c[0] * inv_white[0]), fy = f(c[1] * inv_white[1]), fz = f(c[2] * inv_white[2]);
  return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}

Rgb hunt(const Rgb& lab) { return {lab[0], 0.01f * lab[0] * lab[1], 0.01f * lab[0] * lab[2]}; }

float hyab(const Rgb& a, const Rgb& b) {
  const float dl = a[0] - b[0], da = a[1] - b[1], db = a[2] - b[2];
  return std::fabs(dl) + std::sqrt(da * da + db * db);
}

// Correlation with kx along rows and ky along columns (both of odd size), edge replicated.
Plane separable(const Plane& in, int w, int h, const std::vector<float>& kx, const std::vector<float>& ky) {
  const int rx = int(kx.size()) / 2, ry = int(ky.size()) / 2;
  Plane tmp(in.size()), out(in.size());
  for (int j = 0; j < h; ++j) {
    const float* row = in.data() + std::size_t(j) * std::size_t(w);
    for (int i = 0; i < w; ++i) {
      float s = 0.0f;
      for (int k = -rx; k <= rx; ++k) s += kx[std::size_t(k + rx)] * row[std::clamp(i + k, 0, w - 1)];
      tmp[std::size_t(j) * std::size_t(w) + std::size_t(i)] = s;
    }
  }
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      float s = 0.0f;
      for (int k = -ry; k <= ry; ++k)
        s += ky[std::size_t(k + ry)] * tmp[std::size_t(std::clamp(j + k, 0, h - 1)) * std::size_t(w) + std::size_t(i)];
      out[std::size_t(j) * std::size_t(w) + std::size_t(i)] = s;
    }
  return out;
}

// The contrast sensitivity filter of one opponent channel: weights
// a1 sqrt(pi/b1) exp(-pi^2 d^2 / b1) + a2 sqrt(pi/b2) exp(-pi^2 d^2 / b2), d in degrees,
// normalised to sum 1 over the (2r+1)^2 grid.
Plane csf_filter(const Plane& in, int w, int h, double ppd, int r, double a1, double b1, double a2, double b2) {
  std::vector<float> e1(std::size_t(2 * r + 1)), e2(std::size_t(2 * r + 1));
  double s1 = 0.0, s2 = 0.0;
  for (int x = -r; x <= r; ++x) {
    const double d2 = (x / ppd) * (x / ppd);
    e1[std::size_t(x + r)] = float(std::exp(-pi * pi * d2 / b1));
    e2[std::size_t(x + r)] = float(std::exp(-pi * pi * d2 / b2));
    s1 += e1[std::size_t(x + r)];
    s2 += e2[std::size_t(x + r)];
  }
  const double w1 = a1 * std::sqrt(pi / b1), w2 = a2 * std::sqrt(pi / b2);
  const double total = w1 * s1 * s1 + w2 * s2 * s2;
  std::vector<float> k1 = e1;
  for (auto& v : k1) v = float(v * (w1 / total));
  Plane out = separable(in, w, h, k1, e1);
  if (a2 != 0.0) {
    std::vector<float> k2 = e2;
    for (auto& v : k2) v = float(v * (w2 / total));
    const Plane second = separable(in, w, h, k2, e2);
    for (std::size_t p = 0; p < out.size(); ++p) out[p] += second[p];
  }
  return out;
}

// Edge (first derivative) or point (second derivative) detector kernels: the derivative factor
// with positive weights normalised to sum 1 and negative to -1, and the Gaussian factor to 1.
void feature_kernels(double ppd, bool point, std::vector<float>& deriv, std::vector<float>& gauss) {
  const double sd = 0.5 * 0.082 * ppd;
  const int r = int(std::ceil(3.0 * sd));
  deriv.assign(std::size_t(2 * r + 1), 0.0f);
  gauss.assign(std::size_t(2 * r + 1), 0.0f);
  std::vector<double> d(std::size_t(2 * r + 1));
  double pos = 0.0, neg = 0.0, gs = 0.0;
  for (int x = -r; x <= r; ++x) {
    const double g = std::exp(-(x * x) / (2.0 * sd * sd));
    const double v = point ? (x * x / (sd * sd) - 1.0) * g : -x * g;
    d[std::size_t(x + r)] = v;
    gauss[std::size_t(x + r)] = float(g);
    gs += g;
    if (v > 0) pos += v;
    if (v < 0) neg -= v;
  }
  for (std::size_t k = 0; k < d.size(); ++k) {
    deriv[k] = float(d[k] > 0 ? d[k] / pos : d[k] / neg);
    gauss[k] = float(gauss[k] / gs);
  }
}

// Magnitude of the feature response (x and y detectors) at every pixel.
Plane feature_magnitude(const Plane& y, int w, int h, const std::vector<float>& deriv, const std::vector<float>& gauss) {
  const Plane fx = separable(y, w, h, deriv, gauss), fy = separable(y, w, h, gauss, deriv);
  Plane m(y.size());
  for (std::size_t p = 0; p < m.size(); ++p) m[p] = std::sqrt(fx[p] * fx[p] + fy[p] * fy[p]);
  return m;
}

// Linear RGB in [0, 1] of an image: decoded if sRGB, grey replicated, alpha ignored.
std::vector<Rgb> linear_rgb(const Image& im) {
  const Image lin = to_linear(im);
  int ch[3] = {-1, -1, -1}, k = 0;
  for (int c = 0; c < lin.channels && k < 3; ++c)
    if (c != lin.alpha_channel) ch[k++] = c;
  std::vector<Rgb> out(lin.pixel_count());
  for (std::size_t p = 0; p < out.size(); ++p) {
    const float* px = lin.pixels.data() + p * std::size_t(lin.channels);
    for (int c = 0; c < 3; ++c) {
      const float v = k == 3 ? px[ch[c]] : (k > 0 ? px[ch[0]] : 0.0f);
      out[p][std::size_t(c)] = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
    }
  }
  return out;
}

}  // namespace

FlipResult flip(const Image& reference, const Image& test, double ppd) {
  const int w = reference.width, h = reference.height;
  const std::size_t n = std::size_t(w) * std::size_t(h);
  const std::vector<Rgb> ref = linear_rgb(reference), tst = linear_rgb(test);

  // Opponent planes of both images.
  std::array<Plane, 3> ro, to;
  for (auto& p : ro) p.resize(n);
  for (auto& p : to) p.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    const Rgb r = xyz_to_ycxcz(linrgb_to_xyz(ref[p])), t = xyz_to_ycxcz(linrgb_to_xyz(tst[p]));
    for (int c = 0; c < 3; ++c) {
      ro[std::size_t(c)][p] = r[std::size_t(c)];
      to[std::size_t(c)][p] = t[std::size_t(c)];
    }
  }

  // Colour pipeline.
  const int r = int(std::ceil(3.0 * std::sqrt(0.04 / (2.0 * pi * pi)) * ppd));
  static constexpr double csf[3][4] = {{1.0, 0.0047, 0.0, 1e-5}, {1.0, 0.0053, 0.0, 1e-5}, {34.1, 0.04, 13.5, 0.025}};
  std::array<Plane, 3> rf, tf;
  for (int c = 0; c < 3; ++c) {
    const auto& k = csf[c];
    rf[std::size_t(c)] = csf_filter(ro[std::size_t(c)], w, h, ppd, r, k[0], k[1], k[2], k[3]);
    tf[std::size_t(c)] = csf_filter(to[std::size_t(c)], w, h, ppd, r, k[0], k[1], k[2], k[3]);
  }
  auto preprocess = [](const Rgb& opp) {
    Rgb rgb = xyz_to_linrgb(ycxcz_to_xyz(opp));
    for (auto& v : rgb) v = std::clamp(v, 0.0f, 1.0f);
    return hunt(xyz_to_lab(linrgb_to_xyz(rgb)));
  };
  const float cmax = std::pow(hyab(hunt(xyz_to_lab(linrgb_to_xyz({0, 1, 0}))), hunt(xyz_to_lab(linrgb_to_xyz({0, 0, 1})))), qc);
  const float pccmax = pc * cmax;

  // Feature pipeline.
  std::vector<float> edge_d, edge_g, point_d, point_g;
  feature_kernels(ppd, false, edge_d, edge_g);
  feature_kernels(ppd, true, point_d, point_g);
  Plane ry(n), ty(n);
  for (std::size_t p = 0; p < n; ++p) {
    ry[p] = (ro[0][p] + 16.0f) / 116.0f;
    ty[p] = (to[0][p] + 16.0f) / 116.0f;
  }
  const Plane re = feature_magnitude(ry, w, h, edge_d, edge_g), te = feature_magnitude(ty, w, h, edge_d, edge_g);
  const Plane rp = feature_magnitude(ry, w, h, point_d, point_g), tp = feature_magnitude(ty, w, h, point_d, point_g);

  FlipResult result;
  result.map = Image::zeros(w, h, 1, Encoding::linear);
  result.map.x = reference.x;
  result.map.y = reference.y;
  result.map.alpha_channel = -1;
  double total = 0.0;
  float mx = 0.0f;
  for (std::size_t p = 0; p < n; ++p) {
    const Rgb a = preprocess({rf[0][p], rf[1][p], rf[2][p]}), b = preprocess({tf[0][p], tf[1][p], tf[2][p]});
    const float dc_raw = std::pow(hyab(a, b), qc);
    const float dc = dc_raw < pccmax ? (pt / pccmax) * dc_raw : pt + ((dc_raw - pccmax) / (cmax - pccmax)) * (1.0f - pt);
    const float df_raw = std::max(std::fabs(re[p] - te[p]), std::fabs(rp[p] - tp[p]));
    const float df = std::pow(df_raw / std::sqrt(2.0f), qf);
    const float e = std::pow(dc, 1.0f - df);
    result.map.pixels[p] = e;
    total += e;
    mx = std::max(mx, e);
  }
  result.mean = n ? total / double(n) : 0.0;
  result.max = mx;
  return result;
}

}  // namespace splinefig::compare
