// The man page and the shell completions the build writes (cli/reference.hpp) against the
// parser itself, as --help shows it: every command and every option is in the man page (groff
// reads it without a warning), bash completes commands, options, their values and file names,
// the zsh script names them all, and every value offered for an enumerated option is one its
// command takes.
#include "cli/run.hpp"
#include "skip.hpp"

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

const fs::path kBuilt = fs::path(SPLINEFIG_BINARY_DIR) / "cli";

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("splinefig-reference-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A bash script run in `cwd`: exit code, stdout, stderr.
splinefig::test::Run bash(const std::string& script, const fs::path& cwd) {
  const fs::path file = cwd / "script.sh";
  std::ofstream(file) << script;
  const std::string cmd = "cd " + shell_quote(cwd.string()) + " && bash --norc --noprofile " + shell_quote(file.string()) +
                          " > out.txt 2> err.txt";
  const int status = std::system(cmd.c_str());
  splinefig::test::Run r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(cwd / "out.txt");
  r.err = slurp(cwd / "err.txt");
  return r;
}

bool on_path(const std::string& tool) { return std::system(("command -v " + tool + " > /dev/null 2>&1").c_str()) == 0; }

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// What `splinefig [COMMAND] --help` shows: the commands (top level), the options with every
// name and the default (=VALUE), and the positionals.
struct HelpOption {
  std::vector<std::string> names;  // "-o", "--output"
  std::string default_value;       // "16" for "--grain INT=16"
  bool takes_value = false;        // a type is shown ("--grain INT=16"), not for a flag ("--linear")
};
struct Help {
  std::vector<std::string> commands, positionals;
  std::vector<HelpOption> options;
};

Help help_of(const std::vector<std::string>& command) {
  std::vector<std::string> args = command;
  args.push_back("--help");
  const auto r = run(args);
  REQUIRE(r.code == 0);
  Help h;
  std::string section;
  const std::regex entry(R"re(^  (\S+)(?: (\S+))?)re");
  for (const std::string& line : lines_of(r.out)) {
    if (!line.empty() && line[0] != ' ') {
      section = line;
      continue;
    }
    std::smatch m;
    if (!std::regex_search(line, m, entry)) continue;
    const std::string first = m[1];
    if (section == "Subcommands:") h.commands.push_back(first);
    if (section == "Positionals:") h.positionals.push_back(first);
    if (section == "Options:" && first[0] == '-') {
      HelpOption o;
      std::stringstream names(first);
      for (std::string n; std::getline(names, n, ',');) o.names.push_back(n);
      const std::string type = m[2];
      o.takes_value = !type.empty();
      if (const auto eq = type.find('='); eq != std::string::npos) o.default_value = type.substr(eq + 1);
      h.options.push_back(o);
    }
  }
  return h;
}

// Whether `word` stands on its own in `text` (not part of a longer flag or name).
bool has_word(const std::string& text, const std::string& word) {
  const auto part = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_'; };
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    const bool before = at == 0 || !part(text[at - 1]);
    const bool after = at + word.size() == text.size() || !part(text[at + word.size()]);
    if (before && after) return true;
  }
  return false;
}

// `text` with each run of blanks and line ends one space, as a filled paragraph reads.
std::string flowed(const std::string& text) {
  std::string out;
  for (char c : text) {
    const bool blank = c == ' ' || c == '\n';
    if (!blank || (!out.empty() && out.back() != ' ')) out += blank ? ' ' : c;
  }
  return out;
}

// The man page as groff renders it for a terminal, plain text; its warnings in `warnings`.
std::string rendered_man_page(const fs::path& dir, std::string& warnings) {
  const auto r = bash("groff -man -Tutf8 -ww -P-cbou " + shell_quote((kBuilt / "splinefig.1").string()) + "\n", dir);
  REQUIRE(r.code == 0);
  warnings = r.err;
  return r.out;
}

// The text of each command's part of the rendered page, from its heading "splinefig NAME" to
// the next heading (and "" for the part before the first command: NAME, SYNOPSIS, OPTIONS).
std::map<std::string, std::string> man_sections(const std::string& page, const std::vector<std::string>& commands) {
  std::map<std::string, std::string> out;
  std::string current;
  for (const std::string& line : lines_of(page)) {
    const auto first = line.find_first_not_of(' ');
    const std::string text = first == std::string::npos ? "" : line.substr(first);
    if (line.rfind("   splinefig ", 0) == 0 && first == 3) {
      const std::string name = text.substr(std::string("splinefig ").size());
      if (std::find(commands.begin(), commands.end(), name) != commands.end()) {
        current = name;
        continue;
      }
    }
    if (!line.empty() && line[0] != ' ') current = line == "COMMANDS" || current.empty() ? "" : "(after)";
    out[current] += line + "\n";
  }
  return out;
}

}  // namespace

TEST_CASE("reference: the man page names every command and every option --help shows, and groff reads it without a warning") {
  REQUIRE(fs::exists(kBuilt / "splinefig.1"));
  // The page the build wrote is the one the command prints (not a stale copy).
  const auto printed = run({"--help-man"});
  REQUIRE(printed.code == 0);
  CHECK(slurp(kBuilt / "splinefig.1") == printed.out);
  if (!on_path("groff")) {
    splinefig::testing_support::skip("groff not found");
    return;
  }
  const fs::path dir = scratch("man");
  std::string warnings;
  const std::string page = rendered_man_page(dir, warnings);
  CHECK(warnings.empty());
  INFO(page);

  const Help top = help_of({});
  REQUIRE(top.commands.size() >= 2);
  const auto sections = man_sections(page, top.commands);
  // splinefig's own options, before the commands.
  REQUIRE(sections.count(""));
  for (const HelpOption& o : top.options)
    for (const auto& n : o.names) CHECK(has_word(sections.at(""), n));
  for (const std::string& cmd : top.commands) {
    INFO("splinefig " << cmd);
    REQUIRE(sections.count(cmd));
    const std::string& text = sections.at(cmd);
    const Help h = help_of({cmd});
    for (const std::string& p : h.positionals) CHECK(has_word(text, p));
    for (const HelpOption& o : h.options) {
      for (const auto& n : o.names) {
        INFO(n);
        CHECK(has_word(text, n));
      }
      if (!o.default_value.empty()) CHECK_THAT(flowed(text), Catch::Contains("Default: " + o.default_value + "."));
    }
  }
  // In the page's source, each option's entry: its names in bold, then its value for an option
  // that takes one, nothing for a flag.
  const std::string source = slurp(kBuilt / "splinefig.1");
  for (const std::string& cmd : top.commands) {
    const auto at = source.find("\n.SS splinefig " + cmd + "\n");
    REQUIRE(at != std::string::npos);
    const std::string part = source.substr(at, source.find("\n.SS ", at + 1) - at);
    for (const HelpOption& o : help_of({cmd}).options) {
      std::string head;
      for (const auto& n : o.names) {
        std::string r;
        for (char c : n) r += c == '-' ? "\\-" : std::string(1, c);
        head += (head.empty() ? "" : ", ") + ("\\fB" + r + "\\fR");
      }
      INFO(cmd << " " << head);
      const auto h = part.find("\n.TP\n" + head);
      REQUIRE(h != std::string::npos);
      const char next = part[h + 5 + head.size()];
      CHECK(next == (o.takes_value ? ' ' : '\n'));
    }
  }
  // Options are typed with ASCII dashes (\-), so a flag copied from the page is the flag.
  CHECK_THAT(page, !Catch::Contains("\u2010"));
  CHECK_THAT(page, !Catch::Contains("\u2212"));
  fs::remove_all(dir);
}

TEST_CASE("reference: a roff mistake in the man page is a groff warning (the check above can fail)") {
  if (!on_path("groff")) {
    splinefig::testing_support::skip("groff not found");
    return;
  }
  const fs::path dir = scratch("man-bad");
  std::ofstream(dir / "bad.1") << ".TH X 1\n.SH NAME\nx \\- y\n.XY undefined macro\n\\fBbold\n";
  const auto r = bash("groff -man -Tutf8 -ww -P-cbou bad.1\n", dir);
  CHECK_THAT(r.err, Catch::Contains("warning"));
  fs::remove_all(dir);
}

TEST_CASE("reference: bash completes commands, every option, enumerated values and file names") {
  const fs::path file = kBuilt / "completions" / "splinefig";
  REQUIRE(fs::exists(file));
  const auto printed = run({"--completion", "bash"});
  REQUIRE(printed.code == 0);
  CHECK(slurp(file) == printed.out);

  const fs::path dir = scratch("bash");
  std::ofstream(dir / "fig.toml") << "[canvas]\nwidth = 8\nheight = 8\n";
  std::ofstream(dir / "figure notes.txt") << "x\n";
  // Each case: the words typed, the last one being completed; one output line per case,
  // "WORDS|REPLY REPLY ..." (the function found through `complete -p`, as bash finds it).
  std::vector<std::vector<std::string>> cases = {
      {"splinefig", "re"}, {"splinefig", "render", "--sc"}, {"splinefig", "resample", "in.png", "--edge", "m"},
      {"splinefig", "eval", "--ends", ""}, {"splinefig", "render", "fi"}, {"splinefig", "render", "x.toml", "-o", "fig"},
      {"splinefig", "render", "x.toml", "--scale", ""}, {"splinefig", "--ver"}, {"splinefig", "version", ""},
      {"splinefig", "diff", "--linear", "--ig"}, {"splinefig", "diff", "--json", "fi"}};
  // Every option of every command from the prefix of its long name (all but its last letter).
  const Help top = help_of({});
  std::vector<std::pair<std::string, std::string>> every;
  for (const std::string& cmd : top.commands)
    for (const HelpOption& o : help_of({cmd}).options)
      for (const std::string& n : o.names)
        if (n.size() > 3) {
          every.emplace_back(cmd, n);
          cases.push_back({"splinefig", cmd, n.substr(0, n.size() - 1)});
        }
  std::string script = "source " + shell_quote(file.string()) +
                       "\nspec=$(complete -p splinefig) || exit 3\nfn=${spec##*-F }; fn=${fn%% *}\n"
                       "c() { COMP_WORDS=(\"$@\"); COMP_CWORD=$(( $# - 1 )); COMP_LINE=\"$*\"; COMP_POINT=${#COMP_LINE};"
                       " COMPREPLY=(); \"$fn\" splinefig \"${COMP_WORDS[COMP_CWORD]}\" \"${COMP_WORDS[COMP_CWORD-1]}\";"
                       " local IFS='|'; echo \"$*|${COMPREPLY[*]}\"; }\n";
  for (const auto& words : cases) {
    script += "c";
    for (const auto& w : words) script += " " + shell_quote(w);
    script += "\n";
  }
  const auto r = bash(script, dir);
  INFO(r.err);
  REQUIRE(r.code == 0);
  std::map<std::string, std::set<std::string>> reply;
  for (const std::string& line : lines_of(r.out)) {
    // "splinefig|render|--sc|--scale": the words, then the replies, all split at '|'.
    std::vector<std::string> parts;
    std::stringstream s(line);
    for (std::string p; std::getline(s, p, '|');) parts.push_back(p);
    for (const auto& words : cases) {
      if (parts.size() < words.size() || !std::equal(words.begin(), words.end(), parts.begin())) continue;
      std::string key;
      for (const auto& w : words) key += w + " ";
      reply[key] = std::set<std::string>(parts.begin() + static_cast<long>(words.size()), parts.end());
    }
  }
  using Set = std::set<std::string>;
  CHECK(reply["splinefig re "] == Set{"render", "resample"});
  CHECK(reply["splinefig render --sc "] == Set{"--scale"});
  CHECK(reply["splinefig resample in.png --edge m "] == Set{"mirror"});
  CHECK(reply["splinefig eval --ends  "] == Set{"open", "double", "closed"});  // docs/cli.md: --ends open|double|closed
  CHECK(reply["splinefig render fi "] == Set{"fig.toml", "figure notes.txt"});
  CHECK(reply["splinefig render x.toml -o fig "] == Set{"fig.toml", "figure notes.txt"});
  CHECK(reply["splinefig render x.toml --scale  "].empty());  // a number: nothing to offer
  CHECK(reply["splinefig --ver "] == Set{"--version"});
  CHECK(reply["splinefig version  "] == Set{"-h", "--help"});
  // A flag takes no value: what follows it is completed as anywhere else.
  CHECK(reply["splinefig diff --linear --ig "] == Set{"--ignore-alpha"});
  CHECK(reply["splinefig diff --json fi "] == Set{"fig.toml", "figure notes.txt"});
  for (const auto& [cmd, flag] : every) {
    INFO("splinefig " << cmd << " " << flag.substr(0, flag.size() - 1) << "<TAB>");
    CHECK(reply["splinefig " + cmd + " " + flag.substr(0, flag.size() - 1) + " "].count(flag) == 1);
  }
  fs::remove_all(dir);
}

TEST_CASE("reference: the zsh completion names every command and, in its part, every option") {
  const fs::path file = kBuilt / "completions" / "_splinefig";
  REQUIRE(fs::exists(file));
  const auto printed = run({"--completion", "zsh"});
  REQUIRE(printed.code == 0);
  const std::string z = slurp(file);
  CHECK(z == printed.out);
  CHECK(z.starts_with("#compdef splinefig\n"));
  const Help top = help_of({});
  for (const std::string& cmd : top.commands) {
    INFO(cmd);
    const auto at = z.find("\n        '" + cmd + "')\n");
    REQUIRE(at != std::string::npos);
    const std::string part = z.substr(at, z.find(";;", at) - at);
    for (const HelpOption& o : help_of({cmd}).options)
      for (const std::string& n : o.names) {
        INFO(n);
        CHECK(has_word(part, n));
      }
  }
}

TEST_CASE("reference: zsh reads the zsh completion (zsh -n)") {
  if (!on_path("zsh")) {
    splinefig::testing_support::skip("zsh not found");
    return;
  }
  const fs::path dir = scratch("zsh");
  CHECK(bash("zsh -n " + shell_quote((kBuilt / "completions" / "_splinefig").string()) + "\n", dir).code == 0);
  fs::remove_all(dir);
}

TEST_CASE("reference: every value the man page and the completions offer for an option is one its command takes") {
  if (!on_path("groff")) {
    splinefig::testing_support::skip("groff not found");
    return;
  }
  const fs::path dir = scratch("choices");
  std::ofstream(dir / "tiny.toml") << "[canvas]\nwidth = 8\nheight = 8\n";
  fs::create_directories(dir / "specs");
  fs::copy_file(dir / "tiny.toml", dir / "specs" / "tiny.toml");
  std::ofstream(dir / "x.csv") << "0\n0.5\n";
  REQUIRE(run({"render", (dir / "tiny.toml").string(), "-o", (dir / "tiny.png").string()}).code == 0);
  const std::string knots = "0,0\n1,2\n3,1\n4,3\n0,0\n";
  // A run of each command that works, to which one option is added.
  const std::map<std::string, std::vector<std::string>> base = {
      {"eval", {"eval", "--basis", "catmull-rom"}},
      {"interp", {"interp"}},
      {"kernel", {"kernel", "--basis", "bspline", (dir / "x.csv").string()}},
      {"render", {"render", (dir / "tiny.toml").string(), "-o", (dir / "out").string()}},
      {"figures", {"figures", "--specs", (dir / "specs").string(), "--out", (dir / "figs").string()}},
      {"resample", {"resample", (dir / "tiny.png").string(), "-o", (dir / "small.tif").string(), "--size", "2x2", "--filter", "box"}}};
  std::string warnings;
  const std::string page = rendered_man_page(dir, warnings);
  const Help top = help_of({});
  const auto sections = man_sections(page, top.commands);
  // "--ends open|double|closed": an option's choices, as the page shows them.
  const std::regex listed(R"re(^\s+(?:-\S+, )?(--[a-z-]+) ([a-z0-9]+(?:\|[a-z0-9]+)+)\s*$)re");
  int checked = 0;
  for (const auto& [cmd, text] : sections) {
    for (const std::string& line : lines_of(text)) {
      std::smatch m;
      if (!std::regex_search(line, m, listed)) continue;
      const std::string flag = m[1];
      INFO("splinefig " << cmd << " " << flag);
      REQUIRE(base.count(cmd));
      auto with = [&](const std::string& value) {
        auto args = base.at(cmd);
        args.insert(args.end(), {flag, value});
        return run(args, knots);
      };
      // The refusal of a value that is not one of them, said of the value given.
      const auto bogus = with("zzbogus");
      CHECK(bogus.code == 2);
      REQUIRE_THAT(bogus.err, Catch::Contains("zzbogus"));
      std::stringstream values(m[2].str());
      for (std::string v; std::getline(values, v, '|');) {
        INFO(v);
        std::string refused = bogus.err;
        refused.replace(refused.find("zzbogus"), 7, v);
        CHECK(with(v).err != refused);
        ++checked;
      }
    }
  }
  // eval --ends, --derivative, --spacing, --knot-spacing, --delimiter, interp, kernel, render,
  // figures and resample --format, --edge, --bits: more than 30 values.
  CHECK(checked > 30);
  fs::remove_all(dir);
}

TEST_CASE("reference: --help-man and --completion are hidden, and a bad shell is one line") {
  const auto help = run({"--help"});
  CHECK_THAT(help.out, !Catch::Contains("--help-man"));
  CHECK_THAT(help.out, !Catch::Contains("--completion"));
  const auto near = run({"--hel"});
  CHECK(near.code == 2);
  CHECK_THAT(near.err, Catch::Contains("(did you mean --help?)"));
  for (const auto& [args, says] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--completion", "fish"}, "splinefig: --completion fish: not bash or zsh"},
           {{"--completion"}, "splinefig: --completion needs a value: bash or zsh"}}) {
    const auto r = run(args);
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK(splinefig::test::count_lines(r.err) == 1);
    CHECK_THAT(r.err, Catch::Contains(says));
  }
}
