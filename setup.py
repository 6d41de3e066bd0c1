"""pip's build of the Python package (pyproject.toml): setuptools drives CMake.

The wheel holds one directory, splinefig/, laid out as the build tree has it: the pure-Python
files and the extension module splinefig._core, the image I/O module in
splinefig/<libdir>/splinefig/ (where the extension looks near itself, docs/image.md) and the
built-in specs in splinefig/share/specs. So `pip uninstall splinefig` removes all of it.

By default CMake configures and builds the package in a temporary directory (Release, no
tests) for the interpreter running pip. SPLINEFIG_BUILD_DIR=DIR uses the module an existing
build tree has built instead (`cmake --build DIR` first; nothing is built there).
"""
import atexit
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tempfile

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
    VERSION = re.search(r"project\(splinefig VERSION ([0-9.]+)", f.read()).group(1)


def cache_value(build_dir, name):
    with open(os.path.join(build_dir, "CMakeCache.txt"), encoding="utf-8") as f:
        for line in f:
            m = re.match(re.escape(name) + r"(?::[A-Z]+)?=(.*)", line.rstrip("\n"))
            if m:
                return m.group(1)
    return None


class CMakeBuild(build_ext):
    """Builds (or finds) the CMake targets and copies the package into build_lib."""

    def build_extension(self, ext):
        build_dir = os.environ.get("SPLINEFIG_BUILD_DIR")
        if build_dir:
            build_dir = os.path.abspath(build_dir)
            if not os.path.isfile(os.path.join(build_dir, "CMakeCache.txt")):
                sys.exit("SPLINEFIG_BUILD_DIR=%s: not a CMake build tree (no CMakeCache.txt)" % build_dir)
        else:
            build_dir = os.path.join(os.path.abspath(self.build_temp), "cmake")
            self.cmake(build_dir)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        package = os.path.join(build_dir, "python", "splinefig")
        core = os.path.join(package, "_core" + suffix)
        if not os.path.isfile(core):
            sys.exit("%s: not built (a build for this interpreter, %s, with SPLINEFIG_PYTHON on: "
                     "cmake --build %s --target splinefig_python)" % (core, sys.executable, build_dir))
        libdir = cache_value(build_dir, "CMAKE_INSTALL_LIBDIR") or "lib"
        image_module = os.path.join(build_dir, libdir, "splinefig", "libsplinefig_image_oiio.so")
        if not os.path.isfile(image_module):
            sys.exit("%s: not built (cmake --build %s --target splinefig_image_oiio)" % (image_module, build_dir))

        out = os.path.dirname(os.path.abspath(self.get_ext_fullpath(ext.name)))
        shutil.rmtree(out, ignore_errors=True)
        os.makedirs(os.path.join(out, libdir, "splinefig"))
        for name in os.listdir(package):
            if name == "py.typed" or name.endswith((".py", ".pyi")) and name != "_paths.py":
                shutil.copy2(os.path.join(package, name), out)
        shutil.copy2(core, out)
        shutil.copy2(image_module, os.path.join(out, libdir, "splinefig"))
        shutil.copytree(os.path.join(ROOT, "figures", "specs"), os.path.join(out, "share", "specs"))
        with open(os.path.join(out, "_paths.py"), "w", encoding="utf-8") as f:
            f.write("import os\nspecs_dir = os.path.join(os.path.dirname(__file__), 'share', 'specs')\n")

    def cmake(self, build_dir):
        cmake = shutil.which("cmake") or sys.exit("cmake is needed to build splinefig (apt install cmake)")
        args = [cmake, "-S", ROOT, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release", "-DSPLINEFIG_BUILD_TESTS=OFF",
                "-DSPLINEFIG_PYTHON=ON", "-DPython3_EXECUTABLE=" + sys.executable]
        try:  # pybind11 from the build environment (pip's isolated one), else CMake finds Debian's
            import pybind11
            args.append("-Dpybind11_DIR=" + pybind11.get_cmake_dir())
        except ImportError:
            pass
        subprocess.run(args, check=True)
        jobs = [] if os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") else ["-j", str(self.parallel or os.cpu_count() or 1)]
        subprocess.run([cmake, "--build", build_dir, *jobs, "--target", "splinefig_python", "splinefig_image_oiio"],
                       check=True)


# setuptools' scratch directories (its default is build/, the CMake build tree's usual name,
# and an egg-info in the source tree) go to a temporary directory.
scratch = tempfile.mkdtemp(prefix="splinefig-setup-")
atexit.register(shutil.rmtree, scratch, ignore_errors=True)

setup(
    version=VERSION,
    ext_modules=[Extension("splinefig._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    packages=[],
    zip_safe=False,
    options={"build": {"build_base": os.path.join(scratch, "build")}, "egg_info": {"egg_base": scratch}},
)
