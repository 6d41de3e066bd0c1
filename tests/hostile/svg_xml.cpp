// An SVG is well-formed XML whatever its title holds: C0 control characters (which a TOML
// string may hold as \u0001), U+FFFE and U+FFFF become U+FFFD. The file is parsed by Python's
// xml.etree (expat), an independent XML parser, and its <title> read back.
#include "hostile.hpp"

using namespace splinefig::hostile;

TEST_CASE("an SVG whose title holds control characters parses as XML, each one U+FFFD") {
  const fs::path dir = scratch();
  fs::create_directories(dir / "specs");
  write_file(dir / "specs" / "ctl.toml",
             "title = \"a\\u0001b\\u001bc\\uFFFEd\\u001fe\\tf\"\nshow_title = false\n[canvas]\nwidth = 24\nheight = 24\n");
  const Outcome o = run_in(dir, {"figures", "--specs", "specs", "--out", "out", "--format", "svg"});
  INFO(o.err);
  REQUIRE(o.code == 0);
  write_file(dir / "parse.py",
             "import sys, xml.etree.ElementTree as E\n"
             "t = E.parse(sys.argv[1]).getroot().find('{http://www.w3.org/2000/svg}title').text\n"
             "print(ascii(t))\n");
  const std::string cmd = "cd " + splinefig::test::shell_quote(dir.string()) +
                          " && python3 parse.py out/ctl.svg > parsed.txt 2>&1";
  const int rc = std::system(cmd.c_str());
  const std::string parsed = splinefig::test::slurp(dir / "parsed.txt");
  INFO(parsed);
  CHECK(rc == 0);
  CHECK(parsed == "'a\\ufffdb\\ufffdc\\ufffdd\\ufffde\\tf'\n");
  fs::remove_all(dir);
}
