#pragma once
// The man page and the shell completions, written from the parser's own tables: the App's
// subcommands and options (names, descriptions, types, defaults, whether a value is taken),
// so that they cannot disagree with the parser. `splinefig --help-man` and `splinefig
// --completion bash|zsh` print them (hidden options); the build writes them into the build tree
// (cli/CMakeLists.txt) and installs them.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace splinefig::cli {

// The values an enumerated option takes (--ends: open, double, closed), offered by the
// completions and named in the man page. The command still checks the value itself, in its
// own words; tests/cli/reference.cpp gives each listed value to its command.
CLI::Option* choices(CLI::Option* option, std::vector<std::string> values);
const std::vector<std::string>& choices_of(const CLI::Option* option);

// Whether an option is shown (in --help, the man page, the completions): hidden options have
// an empty group.
inline bool shown(const CLI::Option* o) { return !o->get_group().empty(); }

std::string man_page(const CLI::App& app, const std::string& version);
std::string bash_completion(const CLI::App& app);
std::string zsh_completion(const CLI::App& app);

}  // namespace splinefig::cli
