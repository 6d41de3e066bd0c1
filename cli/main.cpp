// splinefig: the command line. Subcommands register themselves (command.hpp).
#include "command.hpp"
#include "parse_errors.hpp"
#include "reference.hpp"

#include <splinefig/version.hpp>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <map>
#include <optional>
#include <string>

namespace splinefig::cli {
std::vector<Command>& registry() {
  static std::vector<Command> commands;
  return commands;
}
}  // namespace splinefig::cli

namespace {

// A hidden option's output (the man page, a completion script), thrown when it is parsed so that
// no command is required.
struct Reference {
  std::string text;
};

// The one place an error becomes an exit code (docs/conventions.md): 2 for every error of every
// command, but `diff` keeps idiff's 4 for a file or stream it cannot read or write. `command` is
// empty for an error before the command (a bad command name or flag of splinefig's own).
int exit_code(const std::string& command, splinefig::ErrorKind kind) {
  using splinefig::ErrorKind;
  if (command == "diff" && (kind == ErrorKind::unreadable || kind == ErrorKind::unwritable)) return 4;
  return 2;
}

// `code`, once everything written to standard output has reached it; else one line on stderr
// and the exit code of an unwritable output (a full disk, a closed pipe or descriptor: `diff >&-`
// must not look like a match).
int flushed(int code, const std::string& command = "") {
  std::cout.flush();
  const bool ok = !std::cout.fail() && std::fflush(stdout) == 0 && !std::ferror(stdout);
  if (ok) return code;
  const int err = errno;
  std::fprintf(stderr, "%s: cannot write to standard output (%s)\n", (command.empty() ? "splinefig" : "splinefig " + command).c_str(),
               std::strerror(err ? err : EIO));
  return exit_code(command, splinefig::ErrorKind::unwritable);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace splinefig::cli;
  // A write over the file-size limit (ulimit -f) then fails with EFBIG and is reported, its
  // temporary removed, instead of the process dying silently by SIGXFSZ.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"splinefig: cubic splines turned into exact pictures", "splinefig"};
  app.set_version_flag("--version", std::string("splinefig ") + SPLINEFIG_VERSION);
  app.require_subcommand(1);
  app.fallthrough(false);

  auto& commands = registry();
  std::sort(commands.begin(), commands.end(),
            [](const Command& a, const Command& b) { return a.name < b.name; });
  std::map<CLI::App*, Runner> runners;
  std::map<CLI::App*, std::string> names;
  std::vector<std::string> command_names;
  for (auto& c : commands) {
    CLI::App* sub = app.add_subcommand(c.name, c.description);
    runners[sub] = c.setup(*sub);
    names[sub] = c.name;
    command_names.push_back(c.name);
  }
  const std::string commands_list = splinefig::or_list(command_names);
  // The man page and the completions, from the tables above (reference.hpp); the build writes
  // them with these. Hidden: an empty group.
  app.add_flag_callback("--help-man", [&app] { throw Reference{man_page(app, SPLINEFIG_VERSION)}; },
                        "Print the man page (roff)")
      ->group("")
      ->trigger_on_parse();
  app.add_option_function<std::string>(
         "--completion",
         [&app](const std::string& shell) {
           if (shell != "bash" && shell != "zsh") throw CLI::ValidationError("--completion " + printable(shell) + ": not bash or zsh");
           throw Reference{shell == "bash" ? bash_completion(app) : zsh_completion(app)};
         },
         "Print the completion script for bash or zsh")
      ->type_name("SHELL")
      ->group("")
      ->trigger_on_parse();
  // A mistake on the command line: a bad_input error of splinefig itself or of its command.
  const auto fail = [](const std::string& who, const std::string& msg) {
    std::cerr << who << ": " << msg << "\n";
    return exit_code(who == "splinefig" ? "" : who.substr(who.find(' ') + 1), splinefig::ErrorKind::bad_input);
  };

  // What comes before the command: the command itself, or splinefig's own --help and --version.
  if (argc < 2) return fail("splinefig", "a command is required: " + commands_list + " (see splinefig --help)");
  const std::string first = argv[1];
  if (first.empty() || first[0] != '-') {
    if (std::find(command_names.begin(), command_names.end(), first) == command_names.end()) {
      const auto near = splinefig::near_misses(first, command_names);
      return fail("splinefig", "unknown command '" + printable(first) + "' (" +
                                   (near.empty() ? "" : "did you mean " + splinefig::or_list(near) + "? ") + "commands: " + commands_list +
                                   "; see splinefig --help)");
    }
  } else {
    const std::string flag = first.substr(0, first.find('='));
    if (flag == "--completion" && argc == 2 && first == flag) return fail("splinefig", "--completion needs a value: bash or zsh");
    if (const auto all = flag_names(app, true); std::find(all.begin(), all.end(), flag) == all.end()) {
      auto near = near_flags(flag, flag_names(app));
      const auto dashes = flag.find_first_not_of('-');
      if (near.empty() && dashes != std::string::npos) near = splinefig::near_misses(flag.substr(dashes), command_names);
      return fail("splinefig", "unknown option " + printable(flag) + " (" +
                                   (near.empty() ? "splinefig takes a command first: " + commands_list + "; see splinefig --help"
                                                 : "did you mean " + splinefig::or_list(near) + "?") + ")");
    }
  }

  // The first argument a command was given and does not take (CLI11 keeps them in the order
  // typed, also when it stops at another error), preferring a flag: the likeliest cause.
  const auto extra = [](const CLI::App& sub) -> std::optional<std::string> {
    auto left = sub.remaining();
    left.erase(std::remove(left.begin(), left.end(), "--"), left.end());
    for (const auto& a : left)
      if (a.size() > 1 && a[0] == '-') return a;
    if (!left.empty()) return left.front();
    return std::nullopt;
  };
  try {
    app.parse(argc, argv);
  } catch (const Reference& r) {
    std::cout << r.text;
    return flushed(0);
  } catch (const CLI::CallForHelp& e) {
    return flushed(app.exit(e));
  } catch (const CLI::CallForAllHelp& e) {
    return flushed(app.exit(e));
  } catch (const CLI::CallForVersion& e) {
    return flushed(app.exit(e));
  } catch (const CLI::ParseError& e) {
    const auto parsed = app.get_subcommands();
    if (parsed.empty()) {
      std::string msg = e.what();
      std::replace(msg.begin(), msg.end(), '\n', ' ');
      return fail("splinefig", printable(msg) + " (see splinefig --help)");
    }
    const CLI::App& sub = *parsed.front();
    const std::string who = "splinefig " + sub.get_name();
    // (after "--", CLI11 hands what is left over to splinefig itself)
    if (const auto a = extra(sub) ? extra(sub) : extra(app)) return fail(who, extra_argument_message(app, sub, *a));
    if (dynamic_cast<const CLI::RequiredError*>(&e)) return fail(who, missing_message(sub));
    return fail(who, value_message(sub, e));
  }

  for (CLI::App* sub : app.get_subcommands()) {
    try {
      return flushed(runners.at(sub)(), names[sub]);
    } catch (const std::exception& e) {
      std::cerr << "splinefig " << names[sub] << ": " << printable(e.what()) << "\n";
      return exit_code(names[sub], splinefig::error_kind(e));
    }
  }
  return 2;
}
