// What a reader sees of the built-in figures holds no internal names: every text drawn in a
// figure (titles, axis and tick labels, legends, tile labels, annotations; its animation's
// frames too), its title, caption and source as index.json carries them, the title its files
// carry (a viewer's title bar), and the gallery page's visible text and alt texts. An internal name is a basis or filter name
// as the CLI spells it (the list the spline library parses, not one typed here), a filter spec
// with parameters ("cardinal:a=1"), a figure's file stem ("s003-fig16") or a reference to a
// seed text ("seed 003 section 5"). Every card also names the source figure it reproduces.
#include <catch2/catch.hpp>

#include <splinefig/figures/animation.hpp>
#include <splinefig/figures/catalog.hpp>
#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/output.hpp>
#include <splinefig/spline/basis.hpp>
#include <splinefig/spline/basis_kernel.hpp>
#include <splinefig/spline/near_miss.hpp>

#include <algorithm>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <variant>
#include <vector>

using namespace splinefig::figures;

namespace {

const std::string kSpecs = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/";

bool name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == ':' ||
         c == '=';
}

// Whether `word` occurs in `text` as a whole token (not inside a longer name: "bspline" is not
// found in "tensioned-bspline"), spelt exactly (the reader's "Catmull-Rom" is not "catmull-rom").
bool has_token(const std::string& text, const std::string& word) {
  for (size_t p = text.find(word); p != std::string::npos; p = text.find(word, p + 1)) {
    const bool left = p == 0 || !name_char(text[p - 1]);
    const size_t end = p + word.size();
    // A sentence's full stop or a colon's ':' after the name still ends it.
    const bool right = end == text.size() || !name_char(text[end]) ||
                       ((text[end] == ':') && (end + 1 == text.size() || text[end + 1] == ' '));
    if (left && right) return true;
  }
  return false;
}

// Names that are ordinary English words a reader uses too ("the box filter", "a tent", "cardinal
// splines", "the ends of a curve"): prose, not internal names, when a figure's text has them.
const std::set<std::string> kEnglish = {"box", "tent", "cardinal", "bias", "tension", "ends", "multiplicity"};

// The names the CLI takes for a basis (--basis) or a filter (--filter, zone plates), from the
// spline library's own lists, less the English words.
std::vector<std::string> cli_names() {
  std::vector<std::string> names = splinefig::split_names(splinefig::known_bases());
  for (const std::string& f : splinefig::split_names(splinefig::known_filters())) names.push_back(f);
  std::vector<std::string> out;
  for (const std::string& n : names)
    if (!kEnglish.count(n)) out.push_back(n);
  return out;
}

struct Shown {
  std::string where;  // "title", "caption", "drawn text", "gallery card", ...
  std::string text;
};

// What a reader sees of the gallery page: the text between its tags (the <head> and <script>
// left out) and every alt text, with the entities it uses resolved.
std::vector<std::string> gallery_visible(const std::string& html) {
  std::string body = html.substr(html.find("<body>"));
  body = body.substr(0, body.find("<script>"));
  auto unescape = [](std::string s) {
    for (auto [from, to] : {std::pair<std::string, std::string>{"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""},
                            {"&times;", "×"}, {"&middot;", "·"}, {"&amp;", "&"}})
      for (size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size())) s.replace(p, from.size(), to);
    return s;
  };
  std::vector<std::string> out;
  static const std::regex alt("alt=\"([^\"]*)\"");
  for (std::sregex_iterator it(body.begin(), body.end(), alt), end; it != end; ++it) out.push_back(unescape((*it)[1]));
  std::string text;
  bool tag = false;
  for (char c : body) {
    if (c == '<') tag = true, text += ' ';
    else if (c == '>') tag = false;
    else if (!tag) text += c;
  }
  out.push_back(unescape(text));
  return out;
}

// The internal names in `text`, one line each.
std::vector<std::string> internal_names(const std::string& text, const std::vector<std::string>& stems) {
  std::vector<std::string> found;
  for (const std::string& n : cli_names())
    if (has_token(text, n)) found.push_back("the CLI's name '" + n + "'");
  static const std::regex spec("(^|[^A-Za-z0-9_-])([a-z][a-z0-9-]*:[a-z][a-z0-9]*=)");
  if (std::smatch m; std::regex_search(text, m, spec)) found.push_back("a filter spec '" + m[2].str() + "...'");
  for (const std::string& s : stems)
    if (has_token(text, s)) found.push_back("the file stem '" + s + "'");
  static const std::regex seed("\\b([Ss]eed|s00[0-9])\\b[^.;]*");
  if (std::smatch m; std::regex_search(text, m, seed)) found.push_back("a seed reference '" + m[0].str() + "'");
  return found;
}

}  // namespace

TEST_CASE("no internal name in what a reader sees of the built-in figures: drawn text, titles, captions, sources, gallery cards and alt texts") {
  const std::vector<SpecFile> specs = list_specs(kSpecs);
  REQUIRE(specs.size() >= 30);
  REQUIRE(cli_names().size() >= 7);
  // The figures' file stems (the --only names), less the English words.
  std::vector<std::string> stems;
  for (const SpecFile& f : specs)
    if (!kEnglish.count(f.name)) stems.push_back(f.name);
  REQUIRE(std::count(stems.begin(), stems.end(), "s003-fig16") == 1);
  std::vector<FigureInfo> infos;
  std::vector<std::vector<Shown>> shown(specs.size());
  for (size_t k = 0; k < specs.size(); ++k) {
    const FigureSpec spec = load_spec(specs[k].path);
    FigureScene fs = figure_scene(spec);
    FigureInfo& info = fs.info;
    std::vector<Shown>& s = shown[k];
    s.push_back({"title", info.title});
    s.push_back({"file title (PNG description, SVG <title>, PDF Title)", file_title(spec)});
    s.push_back({"caption", info.caption});
    s.push_back({"source", info.source});
    auto drawn = [&](const splinefig::render::Scene& scene, const std::string& where) {
      for (const auto& item : scene.items())
        if (const auto* t = std::get_if<splinefig::render::TextItem>(&item)) s.push_back({where, t->text});
    };
    drawn(fs.scene, "drawn text");
    // Each card names the source figure it reproduces.
    CHECK_FALSE(info.source.empty());
    info.files = {specs[k].name + ".png", specs[k].name + ".svg"};
    if (const int frames = animation_frames(spec); frames > 0) {
      info.animation.file = specs[k].name + ".webp";
      info.animation.width = info.width;
      info.animation.height = info.height;
      info.animation.frames = frames;
      info.animation.alt = animation_alt(spec);
      s.push_back({"animation alt text", info.animation.alt});
      for (int i : {0, frames / 2, frames - 1}) drawn(figure_scene(animation_frame_spec(spec, i)).scene, "animation frame text");
    }
    infos.push_back(std::move(info));
  }
  const std::string html = gallery_html(infos);
  for (size_t k = 0; k < specs.size(); ++k) {
    // The card of each figure, from its <figure> to the next.
    const size_t from = html.find("<figure id=\"" + specs[k].name + "\"");
    REQUIRE(from != std::string::npos);
    const std::string card = html.substr(from, html.find("</figure>", from) - from);
    CHECK(card.find("<span class=\"source\">") != std::string::npos);
    for (const std::string& t : gallery_visible("<body>" + card)) shown[k].push_back({"gallery card", t});
  }
  for (size_t k = 0; k < specs.size(); ++k)
    for (const Shown& s : shown[k])
      for (const std::string& found : internal_names(s.text, stems)) {
        INFO(specs[k].name << ", " << s.where << ": \"" << s.text << "\"");
        FAIL_CHECK(found);
      }
  // The page around the cards: its heading, section titles and footer.
  for (const std::string& t : gallery_visible(html.substr(0, html.find("<figure"))))
    for (const std::string& found : internal_names(t, stems)) FAIL_CHECK("the gallery page: " << found);
}

TEST_CASE("the internal-name check finds what it guards against") {
  const std::vector<std::string> stems = {"s003-fig16", "cbasis"};
  CHECK(internal_names("strongest for box, weak for the B-spline, Catmull-Rom and Lanczos (a = 3)", stems).empty());
  CHECK(internal_names("The cardinal spline basis function; tensioned B a = 0.5; β-spline b1 = 2", stems).empty());
  CHECK_FALSE(internal_names("in between for Catmull-Rom and lanczos3.", stems).empty());
  CHECK_FALSE(internal_names("catmull-rom", stems).empty());
  CHECK_FALSE(internal_names("bspline, prefiltered", stems).empty());
  CHECK_FALSE(internal_names("a tensioned-bspline", stems).empty());
  CHECK_FALSE(internal_names("filter cardinal:a=1 here", stems).empty());
  CHECK_FALSE(internal_names("as in s003-fig16", stems).empty());
  CHECK_FALSE(internal_names("see seed 003 section 5", stems).empty());
  CHECK(internal_names("Figure CBASIS", stems).empty());
}
