// `splinefig diff A B`: compares two images the way OpenImageIO's idiff does (same numbers,
// report lines and exit codes: 0 match, 1 warning, 2 failure, 4 unreadable file), with the
// options image tests need (linear light, alpha, mask, shift tolerance, SSIM, FLIP) and
// pictures of the difference. See docs/compare.md.
#include "command.hpp"
#include "stdio.hpp"

#include <splinefig/compare/compare.hpp>
#include <splinefig/image/io.hpp>
#include <splinefig/compare/visualize.hpp>

#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

namespace {

using namespace splinefig;

struct DiffArgs {
  std::string a, b;
  compare::Options o;  // the flags bind to it directly (idiff's defaults)
  bool json = false, verbose = false, quiet = false;
  std::optional<float> scale;
  std::string mask, diff_image, triptych;
};

// Thresholds are floats: a number >= 0 that reads as a finite float (`stored`, CLI11's reading:
// 3.4028235e+38 is the largest); `allow_inf`: also inf as typed (no limit: --hardfail's and
// --hardwarn's default), not a number that overflows to it.
void check_threshold(const CLI::App& app, const char* flag, float stored, bool allow_inf = false) {
  const cli::TypedNumber n = cli::typed_number(app, flag, stored);
  const bool inf = std::isinf(n.v) && n.v > 0 && !n.overflow;
  if (!(n.v >= 0.0 && std::isfinite(stored)) && !(allow_inf && inf))
    throw cli::Failure(n.said + ": must be a number in [0, 3.4028235e+38] (a float)" + (allow_inf ? ", or inf for none" : ""));
}

void check_range(const CLI::App& app, const char* flag, double stored, double lo, double hi, const char* what) {
  const cli::TypedNumber n = cli::typed_number(app, flag, stored);
  if (!(n.v >= lo && n.v <= hi)) throw cli::Failure(n.said + ": must be " + what);
}

Image load(const std::string& path, bool linear) {
  try {
    return read_image(path, linear ? ReadMode::linear : ReadMode::as_stored);
  } catch (const UnreadableImage& e) {
    throw cli::Failure(std::string("cannot read ") + e.what(), e);
  }
}

void write(const std::string& path, const Image& im) {
  try {
    write_image(path, im);
  } catch (const UnwritableImage& e) {
    throw cli::Failure(std::string("cannot write ") + e.what(), e);
  }
}

int run(const DiffArgs& args, const CLI::App& app) {
  const compare::Options& o = args.o;
  const compare::Thresholds& t = o.thresholds;
  check_threshold(app, "--fail", t.fail);
  check_threshold(app, "--warn", t.warn);
  check_threshold(app, "--hardfail", t.hardfail, true);
  check_threshold(app, "--hardwarn", t.hardwarn, true);
  check_range(app, "--failpercent", t.failpercent, 0, 100, "a percentage in [0, 100]");
  check_range(app, "--warnpercent", t.warnpercent, 0, 100, "a percentage in [0, 100]");
  if (t.allowfailures < 0) throw cli::Failure("--allowfailures " + std::to_string(t.allowfailures) + ": must be >= 0");
  if (o.shift < 0 || o.shift > 64) throw cli::Failure("--shift " + std::to_string(o.shift) + ": must be an integer in [0, 64]");
  if (o.ssim_min) check_range(app, "--ssim", *o.ssim_min, -1, 1, "in [-1, 1]");
  if (o.flip_max) check_range(app, "--flip", *o.flip_max, 0, 1, "in [0, 1]");
  if (args.scale) {
    const cli::TypedNumber n = cli::typed_number(app, "--scale", *args.scale);
    if (!(n.v > 0.0 && std::isfinite(*args.scale) && *args.scale > 0.0f))
      throw cli::Failure(n.said + ": must be a number in (0, 3.4028235e+38] (a float)");
  }

  // `-` is stdin for one of A and B; stdout holds the report.
  if (cli::is_stdio(args.a) && cli::is_stdio(args.b)) throw cli::Failure("A and B are both - (stdin holds one image)");
  if (cli::is_stdio(args.mask)) throw cli::Failure("--mask -: stdin is not read for the mask (give a file)");
  for (const auto& [flag, out] : {std::pair{"--diff-image", &args.diff_image}, std::pair{"--triptych", &args.triptych}})
    if (cli::is_stdio(*out)) throw cli::Failure(std::string(flag) + " -: stdout holds the report (give a file)");
  cli::Scratch scratch;
  const std::string stdin_path = cli::is_stdio(args.a) || cli::is_stdio(args.b) ? cli::stdin_image(scratch) : "";
  const auto path_of = [&](const std::string& p) { return cli::is_stdio(p) ? stdin_path : p; };
  const auto said = [&](const std::string& m) { return cli::said_as(m, stdin_path, "stdin"); };

  // An output over an input would destroy it: refused before anything is read or written.
  for (const std::string* out : {&args.diff_image, &args.triptych}) {
    if (out->empty()) continue;
    for (const std::string* in : {&args.a, &args.b, &args.mask})
      if (!in->empty() && !cli::is_stdio(*in) && same_file(*out, *in))
        throw cli::Failure("cannot write " + *out + ": it is the input " + *in, ErrorKind::unwritable);
  }
  if (!args.diff_image.empty() && !args.triptych.empty() &&
      (args.diff_image == args.triptych || same_file(args.diff_image, args.triptych)))
    throw cli::Failure("--diff-image and --triptych name the same file " + args.diff_image);

  // Every input's header against the image limits before any is decoded.
  for (const std::string* in : {&args.a, &args.b, &args.mask}) {
    if (in->empty()) continue;
    try {
      check_image_header(path_of(*in));
    } catch (const UnreadableImage& e) {
      throw cli::Failure(said(std::string("cannot read ") + e.what()), e);
    }
  }
  const auto load_input = [&](const std::string& p) {
    try {
      return load(path_of(p), o.linear);
    } catch (const cli::Failure& e) {
      throw cli::Failure(said(e.what()), e);
    }
  };
  const Image a = load_input(args.a);
  const Image b = load_input(args.b);
  std::unique_ptr<Image> mask;
  if (!args.mask.empty()) mask = std::make_unique<Image>(load(args.mask, false));

  compare::Comparison c;
  try {
    const bool perceptual = o.perceptual || o.ssim_min || o.flip_max;
    const cli::ProgressLine progress("diff", perceptual && static_cast<long long>(a.width) * a.height >= (1LL << 20));
    progress.say("comparing " + std::to_string(a.width) + "x" + std::to_string(a.height) + " (SSIM, FLIP)");
    c = compare::compare_images(a, b, o, mask.get());
  } catch (const std::invalid_argument& e) {
    throw cli::Failure(std::string("--mask ") + args.mask + ": " + e.what());
  } catch (const std::length_error& e) {
    throw cli::Failure(args.a + " and " + args.b + ": " + e.what());
  }

  if (!args.diff_image.empty()) write(args.diff_image, compare::difference_image(c.pa, c.pb, args.scale.value_or(1.0f)));
  if (!args.triptych.empty()) {
    const float heat = args.scale ? *args.scale
                                  : (c.metrics.max_error > 0.0f && std::isfinite(c.metrics.max_error) ? 1.0f / c.metrics.max_error : 1.0f);
    write(args.triptych, compare::triptych(c.pa, c.pb, heat));
  }

  if (args.json)
    std::cout << compare::json_report(c, o, args.a, args.b);
  else
    std::cout << compare::text_report(c, o, args.a, args.b, args.verbose, args.quiet);
  std::cout.flush();
  return compare::exit_code(c.verdict);
}

const cli::Registration reg{
    "diff", "Compare two images as idiff does (exit 0 match, 1 warning, 2 failure, 4 unreadable)",
    [](CLI::App& app) {
      auto args = std::make_shared<DiffArgs>();
      app.add_option("A", args->a, "First (expected) image")->type_name("PATH")->required();
      app.add_option("B", args->b, "Second (actual) image")->type_name("PATH")->required();
      app.add_option("--fail", args->o.thresholds.fail, "Failure threshold on a value's absolute difference")->capture_default_str();
      app.add_option("--failpercent", args->o.thresholds.failpercent, "Percentage of pixels allowed over --fail")->capture_default_str();
      app.add_option("--hardfail", args->o.thresholds.hardfail, "Fail if any value differs by more than this")->capture_default_str();
      app.add_option("--warn", args->o.thresholds.warn, "Warning threshold")->capture_default_str();
      app.add_option("--warnpercent", args->o.thresholds.warnpercent, "Percentage of pixels allowed over --warn")->capture_default_str();
      app.add_option("--hardwarn", args->o.thresholds.hardwarn, "Warn if any value differs by more than this")->capture_default_str();
      app.add_option("--allowfailures", args->o.thresholds.allowfailures, "Number of failing pixels that still pass")->capture_default_str();
      app.add_flag("--linear", args->o.linear, "Decode sRGB-encoded images (PNG) to linear light before comparing");
      app.add_flag("--ignore-alpha", args->o.ignore_alpha, "Leave the alpha channel out of the comparison");
      app.add_option("--mask", args->mask, "Image whose zero pixels are left out of the comparison")->type_name("PATH");
      app.add_option("--shift", args->o.shift, "Tolerate translations up to N pixels (see docs/compare.md)")->capture_default_str();
      app.add_option("--ssim", args->o.ssim_min, "Fail if SSIM (of luminance) is below T");
      app.add_option("--flip", args->o.flip_max, "Fail if the mean LDR-FLIP error is above T");
      app.add_flag("--perceptual", args->o.perceptual, "Report SSIM and FLIP without thresholds");
      app.add_option("--diff-image", args->diff_image, "Write |A-B| * scale to this file")->type_name("PATH");
      app.add_option("--triptych", args->triptych, "Write expected | actual | heat map to this file")->type_name("PATH");
      app.add_option("--scale", args->scale, "Scale of the difference image (1 when not given) and heat map (1/max error when not given)");
      app.add_flag("--json", args->json, "Print a JSON report instead of idiff's lines");
      app.add_flag("-v,--verbose", args->verbose, "Print the report even when the images match");
      app.add_flag("-q,--quiet", args->quiet, "Print only FAILURE");
      app.footer(
          "A or B (not both) may be -, the image on stdin.\n\n"
          "Example: splinefig diff expected.png actual.png --linear --fail 0.004 --diff-image diff.png");
      return cli::Runner([args, &app] {
        if (app.count("--scale") && args->diff_image.empty() && args->triptych.empty())
          throw cli::Failure("--scale applies only to --diff-image and --triptych");
        return run(*args, app);
      });
    }};

}  // namespace
