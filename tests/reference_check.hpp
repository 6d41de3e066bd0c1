#pragma once
// The suite's one reference-image check. Every test that holds a picture against a file in
// tests/reference/ goes through splinefig::testing::MatchesReference (splinefig/testing.hpp: the
// comparison of `splinefig diff`, the failure artefacts, SPLINEFIG_UPDATE_REFERENCES=1) with
// one of the tolerances below, so that a reference means the same thing in every area.
//
// A picture is compared as the 8-bit sRGB PNG splinefig writes. Rendering is deterministic, so
// a correct picture matches its reference exactly; the tolerances leave room only for a
// different rounding of a few values (1-2 of 255) and reject a wrong colour: a series drawn in
// #c03030 instead of #d62728 (22/255 off in red) fails, as does a curve moved by 1/4 pixel.
#include <splinefig/image/image.hpp>
#include <splinefig/testing.hpp>

#include <string>

namespace reference_check {

// Drawings: no pixel may differ by more than 2/255.
inline splinefig::testing::Tolerance drawing() {
  splinefig::testing::Tolerance t;
  t.fail = 2.5f / 255;
  t.warn = 1.5f / 255;
  return t;
}

// Figures, and drawings with text: at most 0.01% of the pixels (40 of an 800 x 500 figure) may
// differ by more than 2/255 (glyph edges, where the font library's rounding may differ).
inline splinefig::testing::Tolerance figure() {
  splinefig::testing::Tolerance t = drawing();
  t.failpercent = 0.01f;
  t.warnpercent = 0.01f;
  return t;
}

// tests/reference/<relative>, in the source tree.
inline std::string path(const std::string& relative) {
  return std::string(SPLINEFIG_SOURCE_DIR) + "/tests/reference/" + relative;
}

}  // namespace reference_check
