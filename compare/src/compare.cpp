// One comparison and its reports (see compare.hpp).
#include <splinefig/compare/compare.hpp>
#include <splinefig/image/srgb.hpp>

#include <splinefig/compare/perceptual.hpp>
#include <splinefig/compare/report.hpp>
#include <splinefig/compare/shift.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

namespace splinefig::compare {

namespace {

std::string window_text(const Window& w) {
  return "[" + std::to_string(w.x) + ", " + std::to_string(w.y) + ", " + std::to_string(w.width) + " x " +
         std::to_string(w.height) + "]";
}

// Both images are padded to their union, and every number is computed over it: bounded by the
// pixels the windows hold, so that two small images far apart (1 x 1 at (0, 0) and at (8000,
// 8000): 64M pixels, 3 GB and 10 s) are refused at once instead of comparing a sea of zeros.
void check_padding(const Window& a, const Window& b, const Window& u) {
  const auto area = [](const Window& w) { return std::int64_t{w.width} * w.height; };
  const std::int64_t held = area(a) + area(b), span = area(u);
  if (span > kMaxPaddedPixels && span > kMaxPaddingFactor * held)
    throw std::length_error("the data windows " + window_text(a) + " and " + window_text(b) + " span " +
                            std::to_string(u.width) + " x " + std::to_string(u.height) + " pixels, more than " +
                            std::to_string(kMaxPaddingFactor) + " times the " + std::to_string(held) +
                            " pixels they hold (limit: 2^22 pixels, or 16 times the pixels held)");
}

}  // namespace

Comparison compare_images(const Image& a_in, const Image& b_in, const Options& options, const Image* mask) {
  Comparison r;
  r.a = options.linear ? to_linear(a_in) : a_in;
  r.b = options.linear ? to_linear(b_in) : b_in;
  if (options.ignore_alpha) {
    r.a = without_alpha(r.a);
    r.b = without_alpha(r.b);
  }
  const Window w = union_window(window_of(r.a), window_of(r.b));
  check_padding(window_of(r.a), window_of(r.b), w);
  const int nch = std::max(r.a.channels, r.b.channels);
  r.sizes_differ = window_of(r.a) != window_of(r.b);
  r.channels_differ = r.a.channels != r.b.channels;
  r.pa = pad_to(r.a, w, nch);
  r.pb = pad_to(r.b, w, nch);
  if (r.a.channels >= r.b.channels) {
    r.pa.channel_names = r.a.channel_names;
    r.pb.channel_names = r.a.channel_names;
    r.pa.alpha_channel = r.pb.alpha_channel = r.a.alpha_channel;
  } else {
    r.pa.channel_names = r.b.channel_names;
    r.pb.channel_names = r.b.channel_names;
    r.pa.alpha_channel = r.pb.alpha_channel = r.b.alpha_channel;
  }

  Image keep;
  MetricOptions mo;
  mo.threads = options.threads;
  if (mask) {
    if (mask->width != w.width || mask->height != w.height)
      throw CompareError("mask is " + std::to_string(mask->width) + " x " + std::to_string(mask->height) +
                                  ", the images are " + std::to_string(w.width) + " x " + std::to_string(w.height));
    keep = Image::zeros(w.width, w.height, 1);
    keep.x = w.x;
    keep.y = w.y;
    for (std::size_t p = 0; p < keep.pixel_count(); ++p)
      keep.pixels[p] = mask->pixels[p * std::size_t(mask->channels)] != 0.0f ? 1.0f : 0.0f;
    mo.mask = &keep;
  }
  Image tolerated;
  if (options.shift > 0) {
    tolerated = shift_tolerant_error(r.pa, r.pb, options.shift);
    mo.error = &tolerated;
  }
  r.metrics = idiff_metrics(r.a, r.b, options.thresholds.fail, options.thresholds.warn, mo);
  r.idiff = idiff_verdict(r.metrics, options.thresholds);
  r.verdict = r.idiff;

  const bool want_ssim = options.perceptual || options.ssim_min.has_value();
  const bool want_flip = options.perceptual || options.flip_max.has_value();
  if (want_ssim) {
    r.ssim = ssim(r.pa, r.pb);
    if (options.ssim_min) {
      if (!r.ssim)
        r.failures.push_back("SSIM needs images of at least 11 x 11 pixels");
      else if (!(*r.ssim >= *options.ssim_min))
        r.failures.push_back("SSIM " + format_g(*r.ssim) + " is below " + format_g(*options.ssim_min));
    }
  }
  if (want_flip) {
    const FlipResult f = flip(r.pa, r.pb);
    r.flip_mean = f.mean;
    r.flip_max = f.max;
    if (options.flip_max && !(f.mean <= *options.flip_max))
      r.failures.push_back("mean FLIP " + format_g(f.mean) + " is above " + format_g(*options.flip_max));
  }
  if (!r.failures.empty()) r.verdict = Verdict::failure;
  return r;
}

namespace {

std::string size_text(const Image& im) {
  std::string s = std::to_string(im.width) + " x " + std::to_string(im.height);
  if (im.x != 0 || im.y != 0) s += " at (" + std::to_string(im.x) + ", " + std::to_string(im.y) + ")";
  return s;
}

}  // namespace

std::string text_report(const Comparison& c, const Options& options, const std::string& name_a,
                        const std::string& name_b, bool verbose, bool quiet) {
  std::string s;
  if (!quiet) {
    s += "Comparing \"" + name_a + "\" and \"" + name_b + "\"\n";
    if (c.sizes_differ)
      s += "Images differ in size: " + size_text(c.a) + " vs " + size_text(c.b) + " (compared over their union, " +
           std::to_string(c.pa.width) + " x " + std::to_string(c.pa.height) + ", missing pixels as 0)\n";
    if (c.channels_differ)
      s += "Images differ in channel count: " + std::to_string(c.a.channels) + " vs " + std::to_string(c.b.channels) +
           " (missing channels as 0)\n";
  }
  if (verbose || (c.verdict != Verdict::match && !quiet)) {
    s += idiff_report_lines(c.metrics, options.thresholds, c.a, c.b);
    if (options.shift > 0)
      s += "  Shift tolerance = " + std::to_string(options.shift) + " pixel" + (options.shift > 1 ? "s" : "") + "\n";
    if (c.ssim) s += "  SSIM = " + format_g(*c.ssim) + "\n";
    if (c.flip_mean) s += "  FLIP mean = " + format_g(*c.flip_mean) + ", max = " + format_g(*c.flip_max) + "\n";
    for (const auto& f : c.failures) s += "  " + f + "\n";
  }
  if (!quiet || c.verdict == Verdict::failure) s += std::string(verdict_word(c.verdict)) + "\n";
  return s;
}

namespace {

std::string json_string(const std::string& v) {
  return nlohmann::json(v).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string json_number(double v) {
  if (std::isnan(v)) return "\"nan\"";
  if (std::isinf(v)) return v > 0 ? "\"inf\"" : "\"-inf\"";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// A float as the shortest text that reads back to it.
std::string json_float(float v) {
  if (!std::isfinite(v)) return json_number(double(v));
  return format_shortest(v);
}

std::string json_size(const Image& im) {
  return "{\"width\": " + std::to_string(im.width) + ", \"height\": " + std::to_string(im.height) +
         ", \"x\": " + std::to_string(im.x) + ", \"y\": " + std::to_string(im.y) +
         ", \"channels\": " + std::to_string(im.channels) + "}";
}

}  // namespace

std::string json_report(const Comparison& c, const Options& options, const std::string& name_a,
                        const std::string& name_b) {
  const Metrics& m = c.metrics;
  const Thresholds& t = options.thresholds;
  const double npels = double(m.npels);
  std::string channel;
  if (m.max_c < int(c.a.channel_names.size()))
    channel = c.a.channel_names[std::size_t(m.max_c)];
  else if (m.max_c < int(c.b.channel_names.size()))
    channel = c.b.channel_names[std::size_t(m.max_c)];
  else
    channel = "channel " + std::to_string(m.max_c);
  std::string s = "{\n";
  s += "  \"a\": " + json_string(name_a) + ",\n";
  s += "  \"b\": " + json_string(name_b) + ",\n";
  s += "  \"verdict\": " + json_string(verdict_word(c.verdict)) + ",\n";
  s += "  \"exit_code\": " + std::to_string(exit_code(c.verdict)) + ",\n";
  s += "  \"idiff_verdict\": " + json_string(verdict_word(c.idiff)) + ",\n";
  s += "  \"image_a\": " + json_size(c.a) + ",\n";
  s += "  \"image_b\": " + json_size(c.b) + ",\n";
  s += std::string("  \"sizes_differ\": ") + (c.sizes_differ ? "true" : "false") + ",\n";
  s += std::string("  \"channels_differ\": ") + (c.channels_differ ? "true" : "false") + ",\n";
  s += std::string("  \"linear\": ") + (options.linear ? "true" : "false") + ",\n";
  s += std::string("  \"ignore_alpha\": ") + (options.ignore_alpha ? "true" : "false") + ",\n";
  s += "  \"shift\": " + std::to_string(options.shift) + ",\n";
  s += "  \"mean_error\": " + json_number(m.mean_error) + ",\n";
  s += "  \"rms_error\": " + json_number(m.rms_error) + ",\n";
  s += "  \"psnr\": " + json_number(m.psnr) + ",\n";
  s += "  \"max_error\": " + json_float(m.max_error) + ",\n";
  s += "  \"max_error_at\": {\"x\": " + std::to_string(m.max_x) + ", \"y\": " + std::to_string(m.max_y) +
       ", \"channel\": " + json_string(channel) + "},\n";
  s += "  \"pixels\": " + std::to_string(m.npels) + ",\n";
  s += "  \"warn\": {\"threshold\": " + json_float(t.warn) + ", \"percent_allowed\": " + json_float(t.warnpercent) +
       ", \"hard\": " + json_float(t.hardwarn) + ", \"pixels_over\": " + std::to_string(m.nwarn) +
       ", \"percent_over\": " + json_number(100.0 * double(m.nwarn) / npels) + "},\n";
  s += "  \"fail\": {\"threshold\": " + json_float(t.fail) + ", \"percent_allowed\": " + json_float(t.failpercent) +
       ", \"hard\": " + json_float(t.hardfail) + ", \"pixels_over\": " + std::to_string(m.nfail) +
       ", \"percent_over\": " + json_number(100.0 * double(m.nfail) / npels) + "},\n";
  if (c.ssim) s += "  \"ssim\": " + json_number(*c.ssim) + ",\n";
  if (options.ssim_min) s += "  \"ssim_min\": " + json_number(*options.ssim_min) + ",\n";
  if (c.flip_mean) s += "  \"flip_mean\": " + json_number(*c.flip_mean) + ",\n  \"flip_max\": " + json_number(*c.flip_max) + ",\n";
  if (options.flip_max) s += "  \"flip_max_allowed\": " + json_number(*options.flip_max) + ",\n";
  s += "  \"failures\": [";
  for (std::size_t i = 0; i < c.failures.size(); ++i) s += (i ? ", " : "") + json_string(c.failures[i]);
  s += "]\n}\n";
  return s;
}

}  // namespace splinefig::compare
