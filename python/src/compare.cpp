// Comparison: idiff's numbers and verdict, SSIM and FLIP (compare/compare.hpp), and the pictures
// of a difference.
#include "common.hpp"
#include "modules.hpp"

#include <splinefig/compare/compare.hpp>
#include <splinefig/compare/visualize.hpp>

#include <pybind11/stl.h>

namespace splinefig::python {
namespace {

const char* verdict_name(compare::Verdict v) {
  return v == compare::Verdict::match ? "match" : v == compare::Verdict::warning ? "warning" : "failure";
}

Image encoded(const f32array& a, bool srgb) { return image_from_array(a, srgb ? Encoding::srgb : Encoding::linear); }

}  // namespace

void bind_compare(py::module_& m) {
  m.def("compare", [](const f32array& a, bool a_srgb, const f32array& b, bool b_srgb, const py::dict& opts,
                      std::optional<f32array> mask, const std::string& name_a, const std::string& name_b) {
    compare::Options o;
    auto& t = o.thresholds;
    t.fail = opts["fail"].cast<float>();
    t.warn = opts["warn"].cast<float>();
    t.failpercent = opts["failpercent"].cast<float>();
    t.warnpercent = opts["warnpercent"].cast<float>();
    t.hardfail = opts["hardfail"].cast<float>();
    t.hardwarn = opts["hardwarn"].cast<float>();
    t.allowfailures = opts["allowfailures"].cast<long long>();
    o.linear = opts["linear"].cast<bool>();
    o.ignore_alpha = opts["ignore_alpha"].cast<bool>();
    o.shift = opts["shift"].cast<int>();
    o.ssim_min = opts["ssim"].cast<std::optional<double>>();
    o.flip_max = opts["flip"].cast<std::optional<double>>();
    o.perceptual = opts["perceptual"].cast<bool>();
    o.threads = opts["threads"].cast<int>();
    const Image ia = encoded(a, a_srgb), ib = encoded(b, b_srgb);
    std::optional<Image> im;
    if (mask) im = image_from_array(*mask, Encoding::srgb);
    compare::Comparison c;
    std::string text, json;
    {
      py::gil_scoped_release unlocked;
      c = compare::compare_images(ia, ib, o, im ? &*im : nullptr);
      text = compare::text_report(c, o, name_a, name_b, true);
      json = compare::json_report(c, o, name_a, name_b);
    }
    py::dict d;
    const auto& mt = c.metrics;
    d["verdict"] = verdict_name(c.verdict);
    d["idiff_verdict"] = verdict_name(c.idiff);
    d["mean_error"] = mt.mean_error;
    d["rms_error"] = mt.rms_error;
    d["psnr"] = mt.psnr;
    d["max_error"] = mt.max_error;
    d["max_pixel"] = py::make_tuple(mt.max_x, mt.max_y);
    d["max_channel"] = mt.max_c;
    d["nwarn"] = mt.nwarn;
    d["nfail"] = mt.nfail;
    d["npels"] = mt.npels;
    d["nvalues"] = mt.nvalues;
    d["sizes_differ"] = c.sizes_differ;
    d["channels_differ"] = c.channels_differ;
    d["ssim"] = c.ssim;
    d["flip_mean"] = c.flip_mean;
    d["flip_max"] = c.flip_max;
    d["failures"] = c.failures;
    d["text"] = text;
    d["json"] = json;
    // The images as compared (union window and channels), for the pictures of the difference.
    d["_srgb"] = c.pa.encoding == Encoding::srgb;
    d["_a"] = array_from_image(std::move(c.pa));
    d["_b"] = array_from_image(std::move(c.pb));
    return d;
  });
  m.def("difference_image", [](const f32array& a, const f32array& b, float scale) {
    return array_from_image(compare::difference_image(image_from_array(a), image_from_array(b), scale));
  });
  m.def("triptych", [](const f32array& expected, bool e_srgb, const f32array& actual, bool a_srgb, float heat_scale) {
    return array_from_image(compare::triptych(encoded(expected, e_srgb), encoded(actual, a_srgb), heat_scale));
  });
}

}  // namespace splinefig::python
