// The library's errors by kind (base/error.hpp, the table of docs/conventions.md): what each
// failing call throws is still the standard exception callers catch, and its kind is the one
// that gives the exit code (a file that cannot be read or written: diff's 4; the rest 2).
#include <splinefig/base/error.hpp>
#include <splinefig/compare/compare.hpp>
#include <splinefig/figures/axes.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/image/io.hpp>
#include <splinefig/image/webp_animation.hpp>
#include <splinefig/kernel/kernel.hpp>
#include <splinefig/renderer/path.hpp>
#include <splinefig/renderer/renderer.hpp>
#include <splinefig/renderer/text_outlines.hpp>
#include <splinefig/resample/resample.hpp>
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/interp.hpp>
#include <splinefig/spline/points_csv.hpp>
#include <splinefig/spline/subdivision.hpp>
#include <splinefig/vector/vector.hpp>

#include <catch2/catch.hpp>

#include <sstream>
#include <stdexcept>

using splinefig::ErrorKind;

namespace {

// The kind of what `f` throws as the standard exception `Std`; fails if it throws nothing or
// something else.
template <class Std, class F>
ErrorKind kind_thrown(F&& f) {
  try {
    f();
  } catch (const Std& e) {
    INFO("message: " << e.what());
    return splinefig::error_kind(e);
  }
  FAIL("nothing thrown");
  return ErrorKind::bad_input;
}

// Whether `f` throws the error type `T` (a std::invalid_argument and a splinefig::Error of kind
// bad_input), not a bare std::invalid_argument, whose kind would be only the default's.
template <class T, class F>
bool throws_typed(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    INFO("message: " << e.what());
    const bool typed = dynamic_cast<const T*>(&e) != nullptr && dynamic_cast<const splinefig::Error*>(&e) != nullptr;
    CHECK(typed);
    return typed && splinefig::error_kind(e) == ErrorKind::bad_input;
  }
  FAIL("nothing thrown");
  return false;
}

}  // namespace

TEST_CASE("a bad argument to any library is its library's error type, whose kind gives the code") {
  using namespace splinefig;
  CHECK(throws_typed<SpecError>([] { parse_ends("nosuch"); }));
  CHECK(throws_typed<CurveError>([] { refine(Points(2, 5), -1); }));
  CHECK(throws_typed<CurveError>([] { relaxed_basis(0); }));
  CHECK(throws_typed<KernelError>([] { Kernel::lanczos(0); }));
  CHECK(throws_typed<KernelError>([] { Kernel::piecewise("k", 0, {}); }));
  CHECK(throws_typed<AnimationError>([] { WebpAnimation(0, 10); }));
  CHECK(throws_typed<render::DrawError>([] { render::Scene(10, 10).fill_circle({5, 5}, -1, {0, 0, 0, 1}); }));
  CHECK(throws_typed<render::DrawError>([] { render::Path().flatten(0); }));
  CHECK(throws_typed<render::DrawError>([] { render::Path().flattened_size(0); }));
  CHECK(throws_typed<render::DrawError>([] { render::text_path("\xff", {0, 0}, render::TextStyle{}); }));
  CHECK(throws_typed<ResampleError>([] { resample(Image(2, 2, 1), 0, 0, Kernel::box()); }));
  CHECK(throws_typed<compare::CompareError>([] {
    const Image a(4, 4, 1), mask(3, 3, 1);
    compare::compare_images(a, a, compare::Options{}, &mask);
  }));
  CHECK(throws_typed<figures::TickError>([] { figures::nice_ticks(0, 1, 5, 1e-300); }));
  // vector/: its own option checks are VectorError (refused before any file is made) ...
  for (const auto format : {vector::VectorFormat::svg, vector::VectorFormat::pdf}) {
    CHECK(throws_typed<vector::VectorError>([&] {
      vector::Options o;
      o.dpi = 1e9;
      vector::write_vector("/nonexistent/never", render::Scene(4, 4), format, o);
    }));
  }
  // ... and an item it refuses keeps the renderer's type in either format (a clipped item).
  auto clipped = [] {
    render::Scene s(8, 8);
    render::Path box;
    box.move_to({1, 1});
    box.line_to({6, 1});
    box.line_to({6, 6});
    box.close();
    s.set_clip(box);
    s.fill_circle({4, 4}, 3, {0, 0, 0, 1});
    return s;
  };
  CHECK(throws_typed<render::DrawError>([&] { vector::to_svg(clipped()); }));
  CHECK(throws_typed<render::DrawError>([&] { vector::to_pdf(clipped()); }));
}

TEST_CASE("bad input to the library is a bad_input error and still its standard exception") {
  using namespace splinefig;
  CHECK(kind_thrown<std::invalid_argument>([] { parse_basis("nosuch"); }) == ErrorKind::bad_input);
  CHECK(kind_thrown<std::invalid_argument>([] { make_curve(bspline(), Points{}, Ends::open); }) == ErrorKind::bad_input);
  CHECK(kind_thrown<std::runtime_error>([] {
          std::istringstream in("0,0\n1,x\n");
          read_csv_points(in, "k.csv");
        }) == ErrorKind::bad_input);
  CHECK(kind_thrown<std::runtime_error>([] { figures::parse_spec("[canvas]\nwidth = \"x\"\n", "f.toml"); }) ==
        ErrorKind::bad_input);
  // An exception that is no splinefig::Error (a standard one, from outside the library) counts as
  // bad input.
  CHECK(error_kind(std::invalid_argument("x")) == ErrorKind::bad_input);
  CHECK(error_kind(std::length_error("x")) == ErrorKind::bad_input);
}

TEST_CASE("a file that cannot be read or written is an unreadable or unwritable error") {
  using namespace splinefig;
  CHECK(kind_thrown<std::runtime_error>([] { read_image("/nonexistent/a.png"); }) == ErrorKind::unreadable);
  CHECK(kind_thrown<UnreadableImage>([] { check_image_header("/nonexistent/a.png"); }) == ErrorKind::unreadable);
  const Image im = Image::zeros(2, 2, 4);
  CHECK(kind_thrown<std::runtime_error>([&] { write_image("/nonexistent/a.png", im); }) == ErrorKind::unwritable);
  const unsigned char byte = 0;
  CHECK(kind_thrown<UnwritableFile>([&] { write_file_atomically("/nonexistent/a.bin", {&byte, 1}); }) ==
        ErrorKind::unwritable);
}
