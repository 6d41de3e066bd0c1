// Tick selection and number formatting, pinned to hand-worked values.
#include <catch2/catch.hpp>

#include <splinefig/figures/axes.hpp>

using namespace splinefig::figures;

namespace {
std::vector<std::string> labels(const std::vector<Tick>& t) {
  std::vector<std::string> out;
  for (const auto& x : t) out.push_back(x.label);
  return out;
}
}  // namespace

TEST_CASE("nice ticks step 1, 2 or 5 times a power of ten and stay inside the range") {
  // [-0.2, 1.1] with about 6 ticks: span 1.3 / 6 = 0.217 -> step 0.2: -0.2, 0, ..., 1.0.
  auto t = nice_ticks(-0.2, 1.1, 6);
  CHECK(labels(t) == std::vector<std::string>{"\u22120.2", "0.0", "0.2", "0.4", "0.6", "0.8", "1.0"});
  // [0, 100] with about 5: step 20.
  CHECK(labels(nice_ticks(0, 100, 5)) == std::vector<std::string>{"0", "20", "40", "60", "80", "100"});
  // [-2, 2] with about 8: step 0.5.
  CHECK(nice_ticks(-2, 2, 8).size() == 9);
  CHECK(nice_ticks(-2, 2, 8)[1].label == "\u22121.5");  // the minus sign U+2212
  // Reversed ranges give the same ticks.
  CHECK(labels(nice_ticks(1.1, -0.2, 6)) == labels(t));
  // Tiny and huge spans.
  CHECK(labels(nice_ticks(0.001, 0.0042, 3)) == std::vector<std::string>{"0.001", "0.002", "0.003", "0.004"});
  CHECK(labels(nice_ticks(0, 5e6, 5)) == std::vector<std::string>{"0", "1000000", "2000000", "3000000", "4000000", "5000000"});
}

TEST_CASE("nice_step picks the 1-2-5 step closest to the wanted count") {
  CHECK(nice_step(0, 10, 5) == Approx(2));
  CHECK(nice_step(0, 10, 10) == Approx(1));
  CHECK(nice_step(0, 10, 2) == Approx(5));
  CHECK(nice_step(0, 0.3, 3) == Approx(0.1));
}

TEST_CASE("forced tick steps and zero without a sign") {
  auto t = nice_ticks(-0.05, 0.75, 5, 0.1);
  CHECK(labels(t) == std::vector<std::string>{"0.0", "0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7"});
  CHECK(format_number(-0.0, 1) == "0.0");
  CHECK(format_number(-1e-12, 2) == "0.00");
  CHECK(format_number(-2, 0) == "-2");
  CHECK(tick_number(-2, 0) == "\xe2\x88\x92" "2");  // U+2212 in UTF-8
  CHECK(tick_number(-0.0, 1) == "0.0");
}

TEST_CASE("log ticks are decades labelled with superscript markup") {
  auto t = log_ticks(1e-4, 1);
  CHECK(labels(t) == std::vector<std::string>{"10^{\u22124}", "10^{\u22123}", "10^{\u22122}", "10^{\u22121}", "10^{0}"});
  CHECK(t[0].value == Approx(1e-4));
  // Less than a decade: ordinary ticks.
  CHECK(labels(log_ticks(2, 8)).front() == "2");
}

TEST_CASE("axis maps send the range ends to the box edges, linear, log and dB") {
  AxisMap lin{Scale::Linear, -2, 2, 51, 780};
  CHECK(lin.to_pixel(-2) == Approx(51));
  CHECK(lin.to_pixel(2) == Approx(780));
  CHECK(lin.to_pixel(0) == Approx(415.5));
  CHECK(lin.from_pixel(lin.to_pixel(1.25)) == Approx(1.25));
  AxisMap log{Scale::Log, 1e-3, 1, 400, 100};  // y: bottom 400, top 100
  CHECK(log.to_pixel(1e-3) == Approx(400));
  CHECK(log.to_pixel(1e-2) == Approx(300));
  CHECK(log.to_pixel(1) == Approx(100));
  AxisMap db{Scale::Decibel, -80, 0, 400, 100};  // range in dB, data magnitudes
  CHECK(db.to_pixel(1.0) == Approx(100));
  CHECK(db.to_pixel(0.1) == Approx(400 - 300.0 * 60 / 80));  // -20 dB
  CHECK(db.to_pixel(1e-4) == Approx(400));
}
