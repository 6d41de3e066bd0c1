// The command's documentation against the command: each synopsis in docs/cli.md,
// docs/resample.md and docs/spec.md shows exactly the flags that command's --help shows and is
// not marked as shell (it is not runnable), every ```sh block of those pages runs when pasted,
// and README.md's build options name every option() of the CMakeLists.txt files, with its default.
#include "cli/run.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>

namespace fs = std::filesystem;
using splinefig::test::run;
using splinefig::test::shell_quote;
using splinefig::test::slurp;

namespace {

const fs::path kSource = SPLINEFIG_SOURCE_DIR;
const std::vector<std::string> kPages = {"docs/cli.md", "docs/resample.md", "docs/spec.md"};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

struct Block {
  std::string page, tag;
  int line = 0;                     // of the opening fence
  std::vector<std::string> lines;   // logical lines: a trailing backslash joins the next one
  std::string code;                 // as written
};

std::vector<Block> blocks(const std::string& page) {
  std::vector<Block> out;
  const auto lines = lines_of(slurp(kSource / page));
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (!lines[i].starts_with("```")) continue;
    Block b{page, lines[i].substr(3), static_cast<int>(i + 1), {}, {}};
    std::string logical;
    for (++i; i < lines.size() && !lines[i].starts_with("```"); ++i) {
      b.code += lines[i] + "\n";
      std::string l = lines[i];
      const bool more = !l.empty() && l.back() == '\\';
      if (more) l.pop_back();
      logical += l;
      if (!more) b.lines.push_back(logical), logical.clear();
    }
    out.push_back(b);
  }
  return out;
}

// The commands (splinefig --help) and, for each, every name of each option its --help shows
// but -h/--help, one set of names per option.
std::vector<std::string> commands() {
  const auto r = run({"--help"});
  REQUIRE(r.code == 0);
  std::vector<std::string> out;
  bool in = false;
  for (const auto& line : lines_of(r.out)) {
    if (!line.empty() && line[0] != ' ') in = line == "Subcommands:";
    std::smatch m;
    if (in && std::regex_search(line, m, std::regex(R"re(^  (\S+))re"))) out.push_back(m[1]);
  }
  REQUIRE(out.size() >= 2);
  return out;
}

std::vector<std::set<std::string>> help_options(const std::string& cmd) {
  const auto r = run({cmd, "--help"});
  REQUIRE(r.code == 0);
  std::vector<std::set<std::string>> out;
  bool in = false;
  for (const auto& line : lines_of(r.out)) {
    if (!line.empty() && line[0] != ' ') in = line == "Options:";
    std::smatch m;
    if (!in || !std::regex_search(line, m, std::regex(R"re(^  (-\S+))re"))) continue;
    std::set<std::string> names;
    std::stringstream s(m[1].str());
    for (std::string n; std::getline(s, n, ',');) names.insert(n);
    if (!names.count("--help")) out.push_back(names);
  }
  return out;
}

// The flags a synopsis line shows: "-o", "--size", "-v" of "[-v|-q]"; not the "-" of "IN|-".
std::set<std::string> flags_in(const std::string& line) {
  std::set<std::string> out;
  const std::regex flag(R"re((?:^|[\s\[\(|])(--?[A-Za-z][A-Za-z0-9-]*))re");
  for (auto it = std::sregex_iterator(line.begin(), line.end(), flag); it != std::sregex_iterator(); ++it) out.insert((*it)[1]);
  return out;
}

// A line "splinefig COMMAND ...".
bool starts_command(const std::string& line, const std::vector<std::string>& cmds) {
  if (!line.starts_with("splinefig ")) return false;
  const std::string word = line.substr(10, line.find(' ', 10) - 10);
  return std::find(cmds.begin(), cmds.end(), word) != cmds.end();
}

// A synopsis: such a line with an optional part in brackets.
bool is_synopsis(const std::string& line, const std::vector<std::string>& cmds) {
  return starts_command(line, cmds) && line.find(" [") != std::string::npos;
}

}  // namespace

TEST_CASE("docs: each synopsis shows the flags its command's --help shows, no more and no fewer, and is not shell") {
  const auto cmds = commands();
  int synopses = 0;
  for (const std::string& page : kPages) {
    // The synopsis lines of each command on this page (kernel's three modes together).
    std::map<std::string, std::set<std::string>> shown;
    for (const Block& b : blocks(page)) {
      // A block with a synopsis line: each of its lines for a command is one (kernel --report).
      if (std::none_of(b.lines.begin(), b.lines.end(), [&](const std::string& l) { return is_synopsis(l, cmds); })) continue;
      for (const std::string& line : b.lines) {
        if (!starts_command(line, cmds)) continue;
        INFO(page << " line " << b.line << ": " << line);
        CHECK(b.tag == "text");  // not ```sh: brackets and alternatives do not run
        const std::string cmd = line.substr(10, line.find(' ', 10) - 10);
        const auto f = flags_in(line);
        shown[cmd].insert(f.begin(), f.end());
        ++synopses;
      }
    }
    for (const auto& [cmd, flags] : shown) {
      INFO(page << ": the synopsis of splinefig " << cmd);
      const auto options = help_options(cmd);
      std::set<std::string> known;
      for (const auto& names : options) known.insert(names.begin(), names.end());
      for (const std::string& f : flags) {
        INFO("the docs show " << f);
        CHECK(known.count(f) == 1);  // the command takes it
      }
      for (const auto& names : options) {
        INFO("--help shows " << *names.rbegin());
        CHECK(std::any_of(names.begin(), names.end(), [&](const std::string& n) { return flags.count(n) > 0; }));
      }
    }
  }
  CHECK(synopses >= 9);  // cli.md: eval, kernel (3), interp, render, figures, resample, diff; and the others
}

TEST_CASE("docs: the synopsis check sees a flag that is missing and one that is not there") {
  // The check's own parts on known lines: flags are found, [-v|-q] gives both, IN|- gives none.
  CHECK(flags_in("splinefig resample IN|- -o OUT|- [--bits 8|16|float] [-v]") == std::set<std::string>{"-o", "--bits", "-v"});
  CHECK(flags_in("splinefig diff A B [-v|-q] (--size WxH | --scale S)") ==
        std::set<std::string>{"-v", "-q", "--size", "--scale"});
  const auto cmds = commands();
  CHECK(is_synopsis("splinefig render SPEC -o OUT [--scale S]", cmds));
  CHECK(!is_synopsis("splinefig render figures/specs/bias.toml -o bias.png", cmds));
  CHECK(!is_synopsis("$ splinefig render fig.toml -o fig.png --scal 2", cmds));
}

TEST_CASE("docs: every ```sh block of cli.md, resample.md and spec.md runs when pasted") {
  const fs::path dir = fs::temp_directory_path() / ("splinefig-docs-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  // As in a checkout: figures/specs/ beside, the command on PATH.
  fs::create_directory_symlink(kSource / "figures", dir / "figures");
  const std::string path = fs::path(SPLINEFIG_EXE).parent_path().string();
  int ran = 0;
  for (const std::string& page : kPages)
    for (const Block& b : blocks(page)) {
      if (b.tag != "sh") continue;
      INFO(page << " line " << b.line << ":\n" << b.code);
      std::ofstream(dir / "block.sh") << b.code;
      const std::string cmd = "cd " + shell_quote(dir.string()) + " && PATH=" + shell_quote(path) +
                              ":\"$PATH\" bash -euo pipefail block.sh > out.txt 2> err.txt";
      const int status = std::system(cmd.c_str());
      INFO("stderr: " << slurp(dir / "err.txt"));
      CHECK(status == 0);
      ++ran;
    }
  CHECK(ran >= 4);
  fs::remove_all(dir);
}

TEST_CASE("docs: README.md's build options name every option() of the CMakeLists.txt files, with its default") {
  // Every option() and cached setting of the tree's CMakeLists.txt files (not of build trees).
  struct Declared {
    std::set<std::string> defaults;  // ON, OFF, or "" for a cached PATH
  };
  std::map<std::string, Declared> declared;
  const std::regex option(R"re(option\(\s*(\w+)\s+"[^"]*"\s+(ON|OFF)\s*\))re");
  const std::regex cached(R"re(set\(\s*(SPLINEFIG_\w+)\s+"([^"]*)"\s+CACHE\s+\w+)re");
  for (auto it = fs::recursive_directory_iterator(kSource); it != fs::recursive_directory_iterator(); ++it) {
    const std::string name = it->path().filename().string();
    if (it->is_directory() && (name.starts_with("build") || name.starts_with(".") || name == "out")) {
      it.disable_recursion_pending();
      continue;
    }
    if (name != "CMakeLists.txt") continue;
    const std::string text = slurp(it->path());
    for (auto m = std::sregex_iterator(text.begin(), text.end(), option); m != std::sregex_iterator(); ++m)
      declared[(*m)[1]].defaults.insert((*m)[2]);
    for (auto m = std::sregex_iterator(text.begin(), text.end(), cached); m != std::sregex_iterator(); ++m)
      declared[(*m)[1]].defaults.insert((*m)[2]);
  }
  REQUIRE(declared.count("SPLINEFIG_BUILD_TESTS"));
  REQUIRE(declared.count("SPLINEFIG_PORTABLE_RESAMPLE"));  // resample/CMakeLists.txt: below the top

  // README.md's "### Build options" table: | `NAME` | default | what it does |
  const std::string readme = slurp(kSource / "README.md");
  const auto start = readme.find("\n### Build options\n");
  REQUIRE(start != std::string::npos);
  const auto end = readme.find("\n#", start + 1);
  const std::string section = readme.substr(start, end - start);
  std::map<std::string, std::pair<std::string, std::string>> rows;  // name -> default, what
  const std::regex row(R"re(\n\| `(\w+)` \| ([^|\n]*?) \| ([^\n]*?) \|)re");
  for (auto m = std::sregex_iterator(section.begin(), section.end(), row); m != std::sregex_iterator(); ++m)
    rows[(*m)[1]] = {(*m)[2], (*m)[3]};

  for (const auto& [name, d] : declared) {
    INFO(name << " (declared with default " << *d.defaults.begin() << ")");
    REQUIRE(rows.count(name) == 1);
    const auto& [def, what] = rows.at(name);
    CHECK(what.size() > 10);
    if (d.defaults.size() == 1) {  // one declaration: the README gives its default
      const std::string want = d.defaults.begin()->empty() ? "empty" : *d.defaults.begin();
      CHECK(def.starts_with(want));
    } else {  // declared ON or OFF by a condition, which the README states
      CHECK_THAT(def, Catch::Contains("ON") && Catch::Contains("when"));
    }
  }
  for (const auto& [name, r] : rows) {
    INFO("README.md names " << name);
    CHECK(declared.count(name) == 1);  // no option the build no longer has
  }
}
