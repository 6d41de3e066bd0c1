// splinefig: the command line. Subcommands register themselves (command.hpp).
#include "command.hpp"

#include <splinefig/version.hpp>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <map>
#include <string>

namespace splinefig::cli {
std::vector<Command>& registry() {
  static std::vector<Command> commands;
  return commands;
}
}  // namespace splinefig::cli

namespace {

// `code`, once everything written to standard output has reached it; else one line on stderr
// and `failed` (a full disk, a closed pipe or descriptor: `diff >&-` must not look like a match).
int flushed(int code, const std::string& who, int failed = 2) {
  std::cout.flush();
  const bool ok = !std::cout.fail() && std::fflush(stdout) == 0 && !std::ferror(stdout);
  if (ok) return code;
  const int err = errno;
  std::fprintf(stderr, "%s: cannot write to standard output (%s)\n", who.c_str(), std::strerror(err ? err : EIO));
  return failed;
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
  for (auto& c : commands) {
    CLI::App* sub = app.add_subcommand(c.name, c.description);
    runners[sub] = c.setup(*sub);
    names[sub] = c.name;
  }

  if (argc > 1 && argv[1][0] != '-' &&
      std::none_of(commands.begin(), commands.end(), [&](const Command& c) { return c.name == argv[1]; })) {
    std::string known;
    for (const auto& c : commands) known += (known.empty() ? "" : ", ") + c.name;
    std::cerr << "splinefig: unknown command '" << printable(argv[1]) << "' (commands: " << known << "; see splinefig --help)\n";
    return 2;
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return flushed(app.exit(e), "splinefig");
  } catch (const CLI::CallForAllHelp& e) {
    return flushed(app.exit(e), "splinefig");
  } catch (const CLI::CallForVersion& e) {
    return flushed(app.exit(e), "splinefig");
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    std::replace(msg.begin(), msg.end(), '\n', ' ');
    std::cerr << "splinefig: " << printable(msg) << " (see splinefig --help)\n";
    return 2;
  }

  for (CLI::App* sub : app.get_subcommands()) {
    try {
      return flushed(runners.at(sub)(), "splinefig " + names[sub], names[sub] == "diff" ? 4 : 2);
    } catch (const Failure& e) {
      std::cerr << "splinefig " << names[sub] << ": " << printable(e.what()) << "\n";
      return e.code;
    } catch (const std::exception& e) {
      std::cerr << "splinefig " << names[sub] << ": " << printable(e.what()) << "\n";
      return 2;
    }
  }
  return 2;
}
