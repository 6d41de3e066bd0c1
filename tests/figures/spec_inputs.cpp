// The files a spec reads (batch.hpp, spec_inputs): every `file` and KEY_file string at any depth,
// resolved against the spec's directory, with its line and key; an image's `file` is marked as
// one (the batch loads the image I/O module before its workers for it), a data file is not, and
// the words "file =" in a comment or a string name nothing.
#include <catch2/catch.hpp>

#include <splinefig/figures/batch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace splinefig::figures;

TEST_CASE("spec_inputs: every file a spec names with an image file marked as an image") {
  const fs::path dir = fs::temp_directory_path() / ("splinefig-specinputs-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string spec = (dir / "s.toml").string();
  std::ofstream(spec, std::ios::binary) << "# file = \"comment.png\"\n"              // 1
                                        << "title = \"a file = \\\"string.png\\\"\"\n"  // 2
                                        << "[[image]]\n"                               // 3
                                        << "file = \"pic.exr\"\n"                      // 4
                                        << "[[axes]]\n"                                // 5
                                        << "[[axes.curve]]\n"                          // 6
                                        << "knots_file = \"knots.csv\"\n"              // 7
                                        << "[[axes.image]]\n"                          // 8
                                        << "extent = [0, 1, 0, 1]\n"                   // 9
                                        << "file = \"sub/pic2.png\"\n"                 // 10
                                        << "[[axes.series]]\n"                         // 11
                                        << "points_file = \"/abs/points.csv\"\n";      // 12
  std::map<std::string, std::pair<std::string, bool>> found;  // path -> where, image
  for (const SpecInput& in : spec_inputs(spec)) found[in.path] = {in.where, in.image};
  const std::map<std::string, std::pair<std::string, bool>> want{
      {(dir / "pic.exr").string(), {spec + ":4: image.file = \"pic.exr\"", true}},
      {(dir / "knots.csv").string(), {spec + ":7: axes.curve.knots_file = \"knots.csv\"", false}},
      {(dir / "sub/pic2.png").string(), {spec + ":10: axes.image.file = \"sub/pic2.png\"", true}},
      {"/abs/points.csv", {spec + ":12: axes.series.points_file = \"/abs/points.csv\"", false}}};
  CHECK(found == want);
  fs::remove_all(dir);
}
