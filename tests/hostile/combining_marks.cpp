// Combining marks: shaping a cluster of n marks took time quadratic in n (200000 marks on one
// letter of a title, a 400 KB spec, took 131 s), and an enclosing mark drawn n times over the
// same pixels more. More than 30 marks in a row (Unicode's stream-safe limit) are refused at load
// with the key, in any text of a spec; 30 render.
#include "hostile.hpp"

using namespace splinefig::hostile;

namespace {

std::string marks(const std::string& mark, int n) {
  std::string s;
  for (int i = 0; i < n; ++i) s += mark;
  return s;
}

const std::string kCanvas = "[canvas]\nwidth = 120\nheight = 60\n";
const std::string kAcute = "\xcc\x81";          // U+0301 COMBINING ACUTE ACCENT
const std::string kCircle = "\xe2\x83\x9d";     // U+20DD COMBINING ENCLOSING CIRCLE

}  // namespace

TEST_CASE("a title with 200000 combining marks on one letter is refused in time, naming the key") {
  check_refused("marks", "title = \"a" + marks(kAcute, 200000) + "\"\n" + kCanvas,
                "marks.toml:1: title: text: more than 30 combining marks in a row (U+0301 at byte 61 of the text");
}

TEST_CASE("more than 30 combining marks are refused in any text, enclosing marks too, 30 render") {
  check_refused("circles", kCanvas + "[[text]]\nat = [10, 30]\ntext = \"o" + marks(kCircle, 31) + "\"\n",
                "circles.toml:4: text[0]: text: more than 30 combining marks in a row (U+20DD");
  check_refused("label", kCanvas + "[[axes]]\nx_label = \"x" + marks(kAcute, 40) + "\"\n",
                "label.toml:4: axes: text: more than 30 combining marks");
  check_renders("thirty", "title = \"a" + marks(kAcute, 30) + "b" + marks(kAcute, 30) + "\"\n" + kCanvas);
}

TEST_CASE("a text of more than 2^20 bytes is refused before it is laid out, naming the key") {
  // 4 * 10^6 characters took 3.4 GB of glyph outlines before the outline limit could count them.
  check_refused("long", kCanvas + "[[text]]\nat = [10, 30]\ntext = \"" + std::string((1 << 20) + 1, 'a') + "\"\n",
                "long.toml:4: text[0]: text: 1048577 bytes, over the limit of 2^20 (1048576) in one text item");
}
