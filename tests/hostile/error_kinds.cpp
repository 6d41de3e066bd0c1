// The library's errors by kind (base/error.hpp, the table of docs/conventions.md): what each
// failing call throws is still the standard exception callers catch, and its kind is the one
// that gives the exit code (a file that cannot be read or written: diff's 4; the rest 2).
#include <splinefig/base/error.hpp>
#include <splinefig/figures/spec.hpp>
#include <splinefig/image/io.hpp>
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/curve.hpp>
#include <splinefig/spline/points_csv.hpp>

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

}  // namespace

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
  // An exception that is no splinefig::Error (a renderer call's check) counts as bad input.
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
