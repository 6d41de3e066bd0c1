#pragma once
// A built-in figure, rendered at 1x in this process, against tests/reference/figures/NAME.png
// (tests/reference_check.hpp).
#include "reference_check.hpp"

#include <splinefig/figures/figure.hpp>
#include <splinefig/figures/spec.hpp>

#include <catch2/catch.hpp>

#include <string>

namespace figtest {

inline splinefig::Image render_builtin_figure(const std::string& name) {
  return splinefig::figures::render_spec_to_image(std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs/" + name + ".toml");
}

inline void check_figure_reference(const std::string& name) {
  INFO("figure " << name);
  CHECK_THAT(render_builtin_figure(name),
             splinefig::testing::MatchesReference(reference_check::path("figures/" + name + ".png"),
                                                  reference_check::figure()));
}

}  // namespace figtest
