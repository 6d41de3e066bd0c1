"""`pip install --no-build-isolation .` into a virtual environment made with
--system-site-packages (Debian's setuptools, wheel and numpy; no package index), then
`pip uninstall splinefig`.

usage: pip_venv.py PYTHON SOURCE_DIR BUILD_DIR WORK_DIR

The build backend (setup.py) reuses BUILD_DIR's compiled module (SPLINEFIG_BUILD_DIR), so the
test takes seconds. Installed, `import splinefig` from another directory gives the venv's
package, which renders a built-in figure from its own specs, writes an EXR through its own image
I/O module and plugs into pytest; uninstalled, nothing of it is left. Prints SPLINEFIG-SKIPPED
when venv or pip is missing.
"""
import os
import shutil
import subprocess
import sys

python, source, build, work = sys.argv[1:5]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)


def skip(why):
    print("SPLINEFIG-SKIPPED: " + why)
    sys.exit(0)


def run(args, **kw):
    return subprocess.run(args, capture_output=True, text=True, **kw)


env = {k: v for k, v in os.environ.items()
       if k not in ("PYTHONPATH", "PYTHONUSERBASE", "SPLINEFIG_SPECS_DIR", "SPLINEFIG_IMAGE_MODULE")}
env["HOME"] = os.path.join(work, "home")  # no user site or pip configuration of the caller's
env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
os.makedirs(env["HOME"])
if run([python, "-c", "import venv, ensurepip"], env=env).returncode != 0:
    skip("%s has no venv or ensurepip (Debian: python3-venv)" % python)
venv = os.path.join(work, "venv")
r = run([python, "-m", "venv", "--system-site-packages", venv], env=env)
if r.returncode != 0:
    skip("python3 -m venv failed (Debian: python3-venv): " + (r.stderr.strip().splitlines() or [""])[-1])
vpy = os.path.join(venv, "bin", "python")
if run([vpy, "-m", "pip", "--version"], env=env).returncode != 0:
    skip("pip is missing in the virtual environment (Debian: python3-pip)")
if run([vpy, "-c", "import setuptools, wheel"], env=env).returncode != 0:
    skip("setuptools or wheel is missing (Debian: python3-setuptools python3-wheel)")

r = run([vpy, "-m", "pip", "install", "--no-build-isolation", "--no-index", source],
        env=dict(env, SPLINEFIG_BUILD_DIR=build), cwd=work)
if r.returncode != 0:
    sys.exit("pip install failed:\n" + r.stdout + r.stderr)
print(r.stdout.strip().splitlines()[-1])
site = run([vpy, "-c", "import sysconfig; print(sysconfig.get_path('platlib'))"], env=env, check=True).stdout.strip()
if not site.startswith(venv + os.sep):
    sys.exit("the venv's platlib %s is not in the venv" % site)

failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL: " + msg)


# setuptools left nothing in the source tree (its default build/ is the CMake build tree's name).
for left in ("splinefig.egg-info", "build/bdist.linux-x86_64"):
    if os.path.exists(os.path.join(source, left)):
        fail("the build left %s in the source tree" % left)
for left in os.listdir(build):
    if left.startswith(("lib.", "temp.", "bdist.")):
        fail("the build left %s in the build tree" % left)

elsewhere = os.path.join(work, "elsewhere")
os.makedirs(elsewhere)
probe = """
import importlib.metadata as m, numpy as np, splinefig
print(splinefig.__file__)
print(splinefig.specs_dir())
print(splinefig.render_figure('bias').shape)
splinefig.write_image('x.exr', np.full((2, 3, 4), 0.5, np.float32))
print(splinefig.read_image('x.exr').shape)
print(*[l.split()[-1] for l in open('/proc/self/maps') if 'libsplinefig_image_oiio' in l][:1])
print([e.value for e in m.entry_points(group='pytest11') if e.name.startswith('splinefig')])
"""
r = run([vpy, "-c", probe], env=env, cwd=elsewhere)
if r.returncode != 0:
    fail("import splinefig in the venv failed: " + r.stderr)
else:
    init, specs, shape, read, module, plugins = r.stdout.splitlines()
    pkg = os.path.join(site, "splinefig")
    expected = [os.path.join(pkg, "__init__.py"), os.path.join(pkg, "share", "specs"), "(500, 800, 4)", "(2, 3, 4)",
                os.path.join(pkg, "lib", "splinefig", "libsplinefig_image_oiio.so"), "['splinefig.pytest_plugin']"]
    for what, got, want in zip(("the package", "specs_dir()", "render_figure('bias').shape", "the EXR read back",
                                "the image I/O module loaded", "the pytest11 entry points"),
                               (init, specs, shape, read, module, plugins), expected):
        if got != want:
            fail("%s is %s, not %s" % (what, got, want))
        else:
            print("ok: %s is %s" % (what, got))
r = run([vpy, "-m", "pytest", "-p", "splinefig.pytest_plugin", "-p", "no:cacheprovider", "--help"], env=env, cwd=elsewhere)
if r.returncode != 0 or "--splinefig-results" not in r.stdout:
    fail("pytest -p splinefig.pytest_plugin --help in the venv: exit %d %s" % (r.returncode, r.stderr))

r = run([vpy, "-m", "pip", "uninstall", "-y", "splinefig"], env=env, cwd=work)
if r.returncode != 0:
    fail("pip uninstall failed: " + r.stdout + r.stderr)
left = [n for n in os.listdir(site) if n.startswith("splinefig")]
if left:
    fail("pip uninstall left %s in %s" % (left, site))
r = run([vpy, "-c", "import splinefig; print(splinefig.__file__)"], env=env, cwd=elsewhere)
if r.returncode == 0 and r.stdout.startswith(venv):
    fail("after pip uninstall the venv still imports " + r.stdout.strip())
if not failures:
    print("ok: pip uninstall splinefig removed", site + "/splinefig*")
sys.exit("%d failure(s)" % len(failures) if failures else 0)
