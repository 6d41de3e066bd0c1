// Finding and opening the image codec module (see codec.hpp).
//
// Candidates, first found wins:
//   1. $SPLINEFIG_IMAGE_MODULE, when set (then the only candidate);
//   2. the bare file name, which the dynamic loader looks up in the program's RUNPATH (set by
//      the package config for programs linking splinefig::image: they load the module of the
//      install they were built against) and LD_LIBRARY_PATH;
//   3. near the object holding this code (a shared library or Python extension it was linked
//      into) and near the running program (/proc/self/exe): <A>/<libdir>/splinefig/ for the
//      directories A above it (add_near) -- so an installed tree works wherever it is moved.
// No absolute path is compiled in: the build tree puts the module in <build>/<libdir>/splinefig,
// where rule 3 finds it for the build tree's programs, tests and Python package, and an
// installed program never looks into the tree it was built in.
#include "codec.hpp"

#include <splinefig/image/io.hpp>

#include <dlfcn.h>
#include <sys/resource.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#ifndef SPLINEFIG_IMAGE_MODULE_NAME
#error "SPLINEFIG_IMAGE_MODULE_NAME must name the module file"
#endif

namespace splinefig::detail {
namespace {

namespace fs = std::filesystem;

// <A>/<libdir>/splinefig/<module> for the directories A above `object`, nearest first, up to
// five levels and never the root: a program in <prefix>/bin, a library in <prefix>/<libdir>
// and a Python extension in <prefix>/lib/python3.X/dist-packages/splinefig all find
// <prefix>/<libdir>/splinefig.
void add_near(std::vector<std::string>& out, const fs::path& object) {
  std::error_code ec;
  fs::path dir = fs::weakly_canonical(object, ec).parent_path();
  if (ec) return;
  for (int level = 0; level < 5 && !dir.empty() && dir != dir.root_path(); ++level, dir = dir.parent_path())
    out.push_back((dir / SPLINEFIG_LIBDIR / "splinefig" / SPLINEFIG_IMAGE_MODULE_NAME).string());
}

std::vector<std::string> candidates() {
  std::vector<std::string> out{SPLINEFIG_IMAGE_MODULE_NAME};
  // For the program itself dladdr gives argv[0], which may be relative or a bare name found
  // in PATH: only an absolute name (a shared object's) is used; /proc/self/exe names the program.
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&image_codec), &info) != 0 && info.dli_fname && info.dli_fname[0] == '/')
    add_near(out, info.dli_fname);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) add_near(out, exe);
  return out;
}

// What loading the module adds to the process, measured on Debian 12 (OpenImageIO 2.4, whose
// dependencies start four logging threads with their stacks and malloc arenas while they load):
// 428 MiB of address space, 98 MiB of it data. Under a limit (ulimit -v, ulimit -d) that leaves
// less, the libraries' own initialisers fail where nothing can catch it: SIGSEGV in
// OpenImageIO's string table or "terminate called without an active exception" in a thread
// start, between the limit at which the loader refuses to map a library (a clean dlerror) and
// the room the module needs. The room is checked first, with a sixteenth to spare.
constexpr std::uint64_t kModuleAddressSpace = (428ull << 20) * 17 / 16, kModuleData = (98ull << 20) * 17 / 16;

// The process's VmSize and VmData in bytes (0 when /proc cannot tell).
void vm_now(std::uint64_t& size, std::uint64_t& data) {
  size = data = 0;
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    std::uint64_t* to = line.rfind("VmSize:", 0) == 0 ? &size : line.rfind("VmData:", 0) == 0 ? &data : nullptr;
    if (to) *to = std::strtoull(line.c_str() + 7, nullptr, 10) << 10;  // "VmSize:   5660 kB"
  }
}

void check_room(const std::string& path) {
  rlimit as{}, data{};
  const bool as_set = getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY;
  const bool data_set = getrlimit(RLIMIT_DATA, &data) == 0 && data.rlim_cur != RLIM_INFINITY;
  if (!as_set && !data_set) return;
  std::uint64_t vm_size = 0, vm_data = 0;
  vm_now(vm_size, vm_data);
  auto mib = [](std::uint64_t b) { return std::to_string(b >> 20) + " MiB"; };
  auto refuse = [&](const char* what, const char* flag, std::uint64_t limit, std::uint64_t used, std::uint64_t need) {
    const std::uint64_t left = limit > used ? limit - used : 0;
    throw std::runtime_error("cannot load the image I/O module " + path + ": it needs about " + mib(need) + " of " + what +
                             " and the limit (" + flag + " " + std::to_string(limit >> 10) + ") leaves " + mib(left));
  };
  if (as_set && (as.rlim_cur < vm_size || as.rlim_cur - vm_size < kModuleAddressSpace))
    refuse("address space", "ulimit -v", as.rlim_cur, vm_size, kModuleAddressSpace);
  if (data_set && (data.rlim_cur < vm_data || data.rlim_cur - vm_data < kModuleData))
    refuse("data", "ulimit -d", data.rlim_cur, vm_data, kModuleData);
}

const ImageCodec* load() {
  std::vector<std::string> tried;
  if (const char* env = std::getenv("SPLINEFIG_IMAGE_MODULE"); env && *env)
    tried.push_back(env);
  else
    tried = candidates();
  std::string failures;
  for (const std::string& path : tried) {
    // A path with a '/' that does not exist is skipped quietly; the bare name is the loader's.
    std::error_code ec;
    if (path.find('/') != std::string::npos && !fs::exists(path, ec)) {
      failures += (failures.empty() ? "" : ", ") + path;
      continue;
    }
    check_room(path);
    void* handle = dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
    if (!handle) {
      const char* why = dlerror();
      if (path.find('/') == std::string::npos && (!why || std::string(why).rfind(path + ":", 0) == 0)) {
        failures += (failures.empty() ? "" : ", ") + path + " (loader path)";
        continue;
      }
      throw std::runtime_error("cannot load the image I/O module " + path + ": " + (why ? why : "dlopen failed"));
    }
    auto entry = reinterpret_cast<ImageCodecEntry>(dlsym(handle, SPLINEFIG_IMAGE_CODEC_SYMBOL));
    const ImageCodec* codec = entry ? entry() : nullptr;
    if (!codec || codec->abi != image_codec_abi)
      throw std::runtime_error("the image I/O module " + path + " is not this version of splinefig's");
    return codec;  // never closed: OpenImageIO keeps threads and caches for the process
  }
  throw std::runtime_error("cannot find the image I/O module " SPLINEFIG_IMAGE_MODULE_NAME " (looked for " + failures +
                           "; set SPLINEFIG_IMAGE_MODULE to its path)");
}

}  // namespace

const ImageCodec& image_codec() {
  static const ImageCodec* const codec = load();  // a failed load throws and is tried again next time
  return *codec;
}

}  // namespace splinefig::detail

namespace splinefig {

void preload_image_io() noexcept {
  try {
    detail::image_codec();
  } catch (...) {  // the first read or write reports it
  }
}

}  // namespace splinefig
