// One meaning per colour across the built-in figures (docs/figures.md, "Colours and what they
// mean"): a recurring concept (Catmull-Rom, the B-spline, the Hermite kernel, a control polygon,
// data points) is drawn in one colour and style in every figure, and a colour that draws a
// concept draws nothing else that is labelled. The key is the label: a series belongs to a
// concept when its label names it (markup removed, lower case), by the rules of concept_of()
// below; a series without a label is not seen (index.json lists labelled series only). The
// series and their styles are the layout's own (figures::layout_figure, as index.json has them).
#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace splinefig;

namespace {

// The label as read: no `$`, `\`, braces, ASCII letters in lower case.
std::string normalised(const std::string& label) {
  std::string s;
  for (char c : label) {
    if (c == '$' || c == '\\' || c == '{' || c == '}') continue;
    s += (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  }
  return s;
}

// The recurring concept a label names, or "" for none. A tensioned or prefiltered B-spline is
// another curve than the B-spline; a "B-spline control polygon" is a control polygon.
std::string concept_of(const std::string& label) {
  const std::string s = normalised(label);
  auto has = [&](const char* w) { return s.find(w) != std::string::npos; };
  if (has("control polygon")) return "control polygon";
  if (s.rfind("data", 0) == 0) return "data points";
  if (has("hermite")) return "Hermite kernel";
  if (has("catmull-rom")) return "Catmull-Rom";
  if (has("b-spline") && !has("tensioned") && !has("prefiltered")) return "B-spline";
  return "";
}

std::string style_of(const figures::SeriesInfo& s) {
  std::ostringstream o;
  o << s.color << (s.line ? " line" : " no line");
  if (s.line) {
    o << " dash [";
    for (std::size_t i = 0; i < s.dash.size(); ++i) o << (i ? ", " : "") << s.dash[i];
    o << "]";
  }
  if (!s.marker.empty()) o << " " << s.marker << " markers";
  return o.str();
}

struct Seen {
  std::string figure, label;
};

// What contradicts one meaning per colour among the labelled series of the figures given.
std::vector<std::string> contradictions(const std::vector<figures::FigureInfo>& infos) {
  std::map<std::string, std::map<std::string, Seen>> styles;  // concept -> style -> first use
  std::map<std::string, std::map<std::string, Seen>> meanings;  // colour -> concept ("" none) -> first use
  for (const auto& info : infos)
    for (const auto& ax : info.axes)
      for (const auto& s : ax.series) {
        if (s.kind == "fill") continue;  // areas
        // The coloured pieces of one kernel are no concept, but their colour must not be one's.
        const std::string c = s.piece ? "" : concept_of(s.label);
        if (!c.empty()) styles[c].emplace(style_of(s), Seen{info.name, s.label});
        meanings[s.color].emplace(c, Seen{info.name, s.label});
      }
  std::vector<std::string> out;
  for (const auto& [c, by_style] : styles)
    if (by_style.size() > 1) {
      std::ostringstream m;
      m << c << " is drawn in " << by_style.size() << " styles:";
      for (const auto& [style, seen] : by_style) m << " " << style << " (" << seen.figure << ", \"" << seen.label << "\");";
      out.push_back(m.str());
    }
  for (const auto& [colour, by_concept] : meanings) {
    const auto named = std::count_if(by_concept.begin(), by_concept.end(), [](const auto& e) { return !e.first.empty(); });
    if (named == 0 || by_concept.size() < 2) continue;
    std::ostringstream m;
    m << colour << " means " << by_concept.size() << " things:";
    for (const auto& [c, seen] : by_concept)
      m << " " << (c.empty() ? "(no concept)" : c) << " (" << seen.figure << ", \"" << seen.label << "\");";
    out.push_back(m.str());
  }
  return out;
}

figures::FigureInfo layout_of(const std::string& toml, const std::string& name) {
  return figures::layout_figure(figures::parse_spec(toml, name, "."));
}

}  // namespace

TEST_CASE("a label names its concept: markup and case do not matter, relatives are other curves") {
  CHECK(concept_of("$b_1$ = 1 (B-spline)") == "B-spline");
  CHECK(concept_of("limit: the B-spline segment") == "B-spline");
  CHECK(concept_of("$a$ = 0.5 (Catmull-Rom)") == "Catmull-Rom");
  CHECK(concept_of("$a$ → 0 (Hermite)") == "Hermite kernel");
  CHECK(concept_of("B-spline control polygon") == "control polygon");
  CHECK(concept_of("data $S_i$") == "data points");
  CHECK(concept_of("tensioned B-spline $a$ = 0.5").empty());
  CHECK(concept_of("B-spline, prefiltered").empty());
  CHECK(concept_of("β-spline $b_1$ = 2").empty());
  CHECK(concept_of("$b_1$ = 2").empty());
}

TEST_CASE("every concept has one colour and style, and every concept's colour one meaning, over the built-in figures") {
  std::vector<figures::FigureInfo> infos;
  for (const auto& entry : std::filesystem::directory_iterator(SPLINEFIG_SOURCE_DIR "/figures/specs"))
    if (entry.path().extension() == ".toml") infos.push_back(figures::layout_figure(figures::load_spec(entry.path().string())));
  CHECK(infos.size() >= 33);
  // The concepts are there to be checked: each is named by series of several figures.
  std::map<std::string, std::vector<std::string>> figures_of;
  for (const auto& info : infos)
    for (const auto& ax : info.axes)
      for (const auto& s : ax.series)
        if (const std::string c = concept_of(s.label); !c.empty()) {
          auto& v = figures_of[c];
          if (std::find(v.begin(), v.end(), info.name) == v.end()) v.push_back(info.name);
        }
  for (const char* c : {"Catmull-Rom", "B-spline", "control polygon", "data points", "Hermite kernel"}) {
    INFO(c);
    CHECK(figures_of[c].size() >= 2);
  }
  for (const std::string& problem : contradictions(infos)) FAIL_CHECK(problem);
}

TEST_CASE("the check catches a concept drawn two ways and a colour with two meanings") {
  const std::string head = "[axes]\nx_range = [0, 1]\ny_range = [0, 1]\n";
  auto series = [](const char* label, const char* color, const char* extra = "") {
    return std::string("[[axes.series]]\npoints = [[0, 0], [1, 1]]\ncolor = \"") + color + "\"\nlabel = \"" + label +
           "\"\n" + extra;
  };
  const auto a = layout_of(head + series("B-spline", "#0072b2", "dash = [5, 4]\n") + series("Catmull-Rom", "#d55e00"), "a");
  const auto same = layout_of(head + series("$b_1$ = 1 (B-spline)", "#0072b2", "dash = [5, 4]\n"), "same");
  CHECK(contradictions({a, same}).empty());
  // The B-spline solid in one figure and dashed in the other.
  const auto solid = layout_of(head + series("B-spline, multiplicity 1", "#0072b2"), "solid");
  CHECK(contradictions({a, solid}).size() == 1);
  // The B-spline's blue for a curve that is not the B-spline.
  const auto other = layout_of(head + series("Lagrange polynomial", "#0072b2", "dash = [5, 4]\n"), "other");
  CHECK(contradictions({a, other}).size() == 1);
  // Two concepts in one colour (red for the B-spline here, for Catmull-Rom there): two styles of
  // the B-spline and one colour with two meanings.
  const auto red = layout_of(head + series("B-spline", "#d55e00", "dash = [5, 4]\n"), "red");
  CHECK(contradictions({a, red}).size() == 2);
  // A kernel's coloured pieces are no concept, but the B-spline's blue for one of its halves is
  // a second meaning of that blue; a colour no concept has is theirs to take.
  const std::string kernel = "[axes]\nx_range = [-2, 2]\ny_range = [-0.2, 1.1]\n[[axes.kernel]]\nbasis = \"catmull-rom\"\n"
                             "labels = [\"$c_3$\", \"$c_2$\", \"$c_1$\", \"$c_0$\"]\n";
  const auto halves_blue = layout_of(kernel + "colors = [\"#0072b2\", \"#0072b2\", \"#e69f00\", \"#e69f00\"]\n", "hb");
  REQUIRE(halves_blue.axes.at(0).series.size() == 4);
  CHECK(halves_blue.axes.at(0).series.at(0).piece);
  CHECK(contradictions({a, halves_blue}).size() == 1);
  const auto halves_indigo = layout_of(kernel + "colors = [\"#332288\", \"#332288\", \"#e69f00\", \"#e69f00\"]\n", "hi");
  CHECK(contradictions({a, halves_indigo}).empty());
  // Colours that draw no concept may recur with several meanings.
  const auto free1 = layout_of(head + series("$b_1$ = 2", "#333333"), "f1");
  const auto free2 = layout_of(head + series("key frames", "#333333"), "f2");
  CHECK(contradictions({free1, free2}).empty());
}
