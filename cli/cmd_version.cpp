// `splinefig version`: the version and the libraries it was built with.
#include "command.hpp"

#include <splinefig/version.hpp>

#include <iostream>

namespace {
const splinefig::cli::Registration reg{"version", "Print the version", [](CLI::App& app) {
  app.footer("Example: splinefig version");
  return splinefig::cli::Runner([] {
    std::cout << "splinefig " << SPLINEFIG_VERSION << "\n";
    return 0;
  });
}};
}  // namespace
