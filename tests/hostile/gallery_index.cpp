// The index a previous `figures` run left in --out is read strictly: a symbolic link to
// /dev/zero, a FIFO, a directory or a file over 64 MiB is not read (one line says so, a new
// index is written, nothing blocks or grows). Its entries reach index.html only as files of the
// directory itself, with '#', '?' and '%' percent-encoded in links and control characters of
// captions replaced. Runs into one directory at the same time merge their entries under a lock.
#include "hostile.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <thread>

using namespace splinefig::hostile;

namespace {

const std::string kSpecs = std::string(SPLINEFIG_SOURCE_DIR) + "/figures/specs";

Outcome figures(const fs::path& dir, const std::string& only) {
  return run_in(dir, {"figures", "--specs", kSpecs, "--out", "out", "--only", only});
}

// The "name" values of an index.json, in order (its "name" keys are the entries').
std::vector<std::string> names_in(const std::string& json) {
  std::vector<std::string> out;
  const std::string key = "\n      \"name\": \"";
  for (std::size_t k = json.find(key); k != std::string::npos; k = json.find(key, k + 1)) {
    const std::size_t b = k + key.size();
    out.push_back(json.substr(b, json.find('"', b) - b));
  }
  return out;
}

void check_replaced(const fs::path& dir, const std::string& says) {
  const Outcome o = figures(dir, "bias");
  INFO(o.seconds << " s: " << o.err);
  CHECK_FALSE(o.killed);
  CHECK(o.seconds < 30);
  CHECK(o.code == 0);
  CHECK(splinefig::test::count_lines(o.err) == 1);
  CHECK_THAT(o.err, Catch::StartsWith("splinefig figures: out/index.json: ") && Catch::Contains(says) &&
                        Catch::Contains("writing a new one"));
  CHECK(fs::is_regular_file(fs::symlink_status(dir / "out" / "index.json")));
  CHECK(names_in(splinefig::test::slurp(dir / "out" / "index.json")) == std::vector<std::string>{"bias"});
}

}  // namespace

TEST_CASE("an index.json that is a link to /dev/zero, a FIFO, a directory or over 64 MiB is not read") {
  const fs::path dir = scratch();
  fs::create_directories(dir / "out");
  fs::create_symlink("/dev/zero", dir / "out" / "index.json");
  check_replaced(dir, "not a regular file");
  fs::remove(dir / "out" / "index.json");
  REQUIRE(::mkfifo((dir / "out" / "index.json").c_str(), 0644) == 0);
  check_replaced(dir, "not a regular file");
  fs::remove(dir / "out" / "index.json");
  fs::create_directories(dir / "out" / "index.json");
  // A directory cannot be replaced by the index: the run names it and fails.
  const Outcome o = figures(dir, "bias");
  CHECK_FALSE(o.killed);
  CHECK(o.code != 0);
  CHECK_THAT(o.err, Catch::Contains("out/index.json: a directory, not a file"));
  fs::remove(dir / "out" / "index.json");
  {  // sparse: no disk used
    const int fd = ::open((dir / "out" / "index.json").c_str(), O_WRONLY | O_CREAT, 0644);
    REQUIRE(fd >= 0);
    REQUIRE(::ftruncate(fd, (off_t(1) << 26) + 1) == 0);
    ::close(fd);
  }
  check_replaced(dir, "has 67108865 bytes, over the limit of 64 MiB");
  fs::remove_all(dir);
}

TEST_CASE("index.json entries outside the output directory, with #?% in names or control bytes, never reach index.html raw") {
  const fs::path dir = scratch();
  REQUIRE(figures(dir, "bias").code == 0);
  std::string json = splinefig::test::slurp(dir / "out" / "index.json");
  // Entries added by hand: each a copy of bias's with another name, files and caption.
  const std::size_t b = json.find("    {"), e = json.rfind("    }");
  REQUIRE(b != std::string::npos);
  const std::string entry = json.substr(b, e + 5 - b);
  auto with = [&](const std::string& name, const std::string& file, const std::string& caption) {
    std::string s = entry;
    s.replace(s.find("\"bias\""), 6, "\"" + name + "\"");
    s.replace(s.find("\"bias.png\""), 10, "\"" + file + "\"");
    const std::size_t c = s.find("\"caption\": \"") + 12;
    s.replace(c, s.find("\",\n", c) - c, caption);
    return s;
  };
  std::string added;
  added += ",\n" + with("up", "../../../../etc/passwd", "up");
  added += ",\n" + with("absolute", "/etc/hostname", "absolute");
  added += ",\n" + with("linked", "linked.png", "a link out of the directory");
  added += ",\n" + with("odd", "a#b?c%d.png", "cap\\u0000tion \\u001b[31m red \\u009b");
  json.insert(e + 5, added);
  write_file(dir / "out" / "index.json", json);
  write_file(dir / "out" / "a#b?c%d.png", "not looked at");
  fs::create_symlink("/etc/hostname", dir / "out" / "linked.png");
  const Outcome o = figures(dir, "arclength");
  INFO(o.err);
  REQUIRE(o.code == 0);
  CHECK(o.err.empty());
  CHECK(names_in(splinefig::test::slurp(dir / "out" / "index.json")) ==
        std::vector<std::string>{"bias", "arclength", "odd"});
  const std::string html = splinefig::test::slurp(dir / "out" / "index.html");
  CHECK(html.find("etc/") == std::string::npos);
  CHECK(html.find("linked") == std::string::npos);
  CHECK(html.find("href=\"a%23b%3Fc%25d.png\"") != std::string::npos);
  CHECK(html.find("a#b") == std::string::npos);
  CHECK(html.find('\0') == std::string::npos);
  CHECK(html.find('\x1b') == std::string::npos);
  CHECK(html.find("\xc2\x9b") == std::string::npos);
  CHECK(html.find("cap\xef\xbf\xbdtion \xef\xbf\xbd[31m red \xef\xbf\xbd") != std::string::npos);
  fs::remove_all(dir);
}

namespace {

// `figures --only ONLY` started in the background; its exit code lands in TAG.rc.
void start(const fs::path& dir, const std::string& only, const std::string& tag) {
  using splinefig::test::shell_quote;
  const std::string cmd = "cd " + shell_quote(dir.string()) + " && (timeout -s KILL " + std::to_string(kTimeLimit) + " " +
                          shell_quote(SPLINEFIG_EXE) + " figures --specs " + shell_quote(kSpecs) +
                          " --out out --only " + only + " > " + tag + ".out 2> " + tag + ".err; echo $? > " + tag +
                          ".rc.tmp && mv " + tag + ".rc.tmp " + tag + ".rc) &";
  REQUIRE(std::system(cmd.c_str()) == 0);
}

int finish(const fs::path& dir, const std::string& tag) {
  for (int i = 0; i < 100 * (kTimeLimit + 5) && !fs::exists(dir / (tag + ".rc")); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  INFO(tag << ": " << splinefig::test::slurp(dir / (tag + ".err")));
  const std::string rc = splinefig::test::slurp(dir / (tag + ".rc"));
  REQUIRE_FALSE(rc.empty());
  return std::stoi(rc);
}

bool wait_for(const fs::path& p) {
  for (int i = 0; i < 100 * kTimeLimit; ++i) {
    if (fs::exists(p)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

}  // namespace

TEST_CASE("figures runs into one directory wait for the index lock and keep each other's entries") {
  const fs::path dir = scratch();
  fs::create_directories(dir / "out");
  // The test holds the lock: both runs render, then wait for it before touching the index.
  const int fd = ::open((dir / "out" / ".index.lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  REQUIRE(fd >= 0);
  REQUIRE(::flock(fd, LOCK_EX) == 0);
  start(dir, "bias,arclength", "a");
  start(dir, "cbasis", "b");
  CHECK(wait_for(dir / "out" / "arclength.png"));
  CHECK(wait_for(dir / "out" / "cbasis.png"));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  CHECK_FALSE(fs::exists(dir / "out" / "index.json"));
  CHECK_FALSE(fs::exists(dir / "a.rc"));
  CHECK_FALSE(fs::exists(dir / "b.rc"));
  ::close(fd);
  CHECK(finish(dir, "a") == 0);
  CHECK(finish(dir, "b") == 0);
  std::vector<std::string> names = names_in(splinefig::test::slurp(dir / "out" / "index.json"));
  std::sort(names.begin(), names.end());
  CHECK(names == std::vector<std::string>{"arclength", "bias", "cbasis"});
  fs::remove_all(dir);
}

TEST_CASE("concurrent figures runs with disjoint --only lists leave every entry in index.json") {
  for (int trial = 0; trial < 6; ++trial) {
    const fs::path dir = scratch();
    fs::create_directories(dir / "out");
    start(dir, "bias", "a");
    start(dir, "arclength", "b");
    CHECK(finish(dir, "a") == 0);
    CHECK(finish(dir, "b") == 0);
    std::vector<std::string> names = names_in(splinefig::test::slurp(dir / "out" / "index.json"));
    std::sort(names.begin(), names.end());
    INFO("trial " << trial);
    CHECK(names == std::vector<std::string>{"arclength", "bias"});
    fs::remove_all(dir);
  }
}
