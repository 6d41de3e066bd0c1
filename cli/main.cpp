// splinefig: the command line. Subcommands register themselves (command.hpp).
#include "command.hpp"

#include <splinefig/version.hpp>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <exception>
#include <iostream>
#include <map>

namespace splinefig::cli {
std::vector<Command>& registry() {
  static std::vector<Command> commands;
  return commands;
}
}  // namespace splinefig::cli

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
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    std::replace(msg.begin(), msg.end(), '\n', ' ');
    std::cerr << "splinefig: " << printable(msg) << " (see splinefig --help)\n";
    return 2;
  }

  for (CLI::App* sub : app.get_subcommands()) {
    try {
      return runners.at(sub)();
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
