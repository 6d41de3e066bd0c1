// The built-in figures set mathematics in italic, axis labels included (docs/figures.md, house
// style): a variable (one letter) or a function of one (k(s), |K(f)|, X(t)) in an axis label
// stands inside $...$ markup, never as upright text.
#include <catch2/catch.hpp>

#include <splinefig/figures/spec.hpp>

#include <filesystem>
#include <regex>
#include <string>

using namespace splinefig::figures;

namespace {

// The label with its $...$ parts removed: the text that is set upright.
std::string upright_part(const std::string& label) {
  std::string out;
  bool math = false;
  for (char c : label) {
    if (c == '$') math = !math;
    else if (!math) out += c;
  }
  return out;
}

// A one-letter word or a letter applied to something, f(x) or |K(f)|, in upright text.
bool has_upright_math(const std::string& text) {
  static const std::regex variable(R"((^|[\s(|])[A-Za-z]($|[\s)|,]))");
  static const std::regex function(R"([A-Za-z]\([^)]*\))");
  return std::regex_search(text, variable) || std::regex_search(text, function);
}

}  // namespace

TEST_CASE("the mathematics check finds upright variables and functions, and passes words", "[typeset]") {
  CHECK(has_upright_math(upright_part("x")));
  CHECK(has_upright_math(upright_part("k(s)")));
  CHECK(has_upright_math(upright_part("|K(f)| (dB)")));
  CHECK(has_upright_math(upright_part("t (samples)")));
  CHECK_FALSE(has_upright_math(upright_part("$k(s)$")));
  CHECK_FALSE(has_upright_math(upright_part("$|K(f)|$ (dB)")));
  CHECK_FALSE(has_upright_math(upright_part("$f$ (cycles per sample)")));
  CHECK_FALSE(has_upright_math(upright_part("knee $x$ − hip $x$")));
  CHECK_FALSE(has_upright_math(upright_part("frequency")));
}

TEST_CASE("every built-in figure sets the mathematics of its axis labels in italic", "[typeset]") {
  int labels = 0;
  for (const auto& entry : std::filesystem::directory_iterator(SPLINEFIG_SOURCE_DIR "/figures/specs")) {
    if (entry.path().extension() != ".toml") continue;
    const FigureSpec spec = load_spec(entry.path().string());
    for (const auto& item : spec.items)
      if (const auto* ax = std::get_if<AxesSpec>(&item))
        for (const AxisSpec* axis : {&ax->x, &ax->y}) {
          if (axis->label.empty()) continue;
          ++labels;
          INFO(entry.path().filename().string() << ": axis label \"" << axis->label << "\"");
          CHECK_FALSE(has_upright_math(upright_part(axis->label)));
        }
  }
  CHECK(labels >= 30);
}
