"""`cmake --install BUILD --prefix P` puts the Python package where the interpreter reads P.

usage: python_prefix.py PYTHON BUILD_DIR WORK_DIR

1. The README's `cmake --install build --prefix ~/.local`, with HOME a scratch directory:
   `import splinefig` then works from another directory with no PYTHONPATH, finds its built-in
   specs under the prefix, and docs/python.md's `python3 -m pytest -p splinefig.pytest_plugin`
   knows the plugin's options.
2. Any other prefix P gets the layout PYTHONUSERBASE=P reads.
3. Under /usr and /usr/local (installed with DESTDIR), the package lands in a directory on the
   interpreter's own sys.path.
"""
import os
import shutil
import subprocess
import sys

python, build, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
cmake = shutil.which("cmake") or sys.exit("cmake not found")
failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL: " + msg)


def clean_env(**extra):
    env = {k: v for k, v in os.environ.items()
           if k not in ("PYTHONPATH", "PYTHONUSERBASE", "PYTHONNOUSERSITE", "SPLINEFIG_SPECS_DIR", "DESTDIR")}
    env.update(extra)
    return env


def install(prefix, **env):
    r = subprocess.run([cmake, "--install", build, "--prefix", prefix], env=clean_env(**env),
                       capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("cmake --install --prefix %s failed:\n%s%s" % (prefix, r.stdout, r.stderr))


def packages_under(root):
    return sorted(os.path.relpath(d, root) for d, dirs, files in os.walk(root)
                  if os.path.basename(d) == "splinefig" and "__init__.py" in files)


elsewhere = os.path.join(work, "elsewhere")
os.makedirs(elsewhere)
probe = ("import splinefig, importlib.metadata as m; print(splinefig.__file__); print(splinefig.specs_dir()); "
         "print(splinefig.render_figure('bias').shape); "
         "print([e.value for e in m.entry_points(group='pytest11') if e.name.startswith('splinefig')])")


def check_import(prefix, env, what):
    r = subprocess.run([python, "-c", probe], cwd=elsewhere, env=env, capture_output=True, text=True)
    if r.returncode != 0:
        fail("%s: import splinefig failed: %s" % (what, (r.stderr.strip().splitlines() or ["?"])[-1]))
        return
    init, specs, shape, plugins = r.stdout.splitlines()
    if not init.startswith(prefix + os.sep):
        fail("%s: imported %s, not the package under %s" % (what, init, prefix))
    if specs != os.path.join(prefix, "share", "splinefig", "specs"):
        fail("%s: specs_dir() is %s, not %s/share/splinefig/specs" % (what, specs, prefix))
    if shape != "(500, 800, 4)":
        fail("%s: render_figure('bias') gave %s" % (what, shape))
    if plugins != "['splinefig.pytest_plugin']":
        fail("%s: the pytest11 entry points are %s" % (what, plugins))
    print("ok: %s imports %s" % (what, init))


# 1. ~/.local, as the README says, with no PYTHONUSERBASE: the user site.
home = os.path.join(work, "home")
user_base = os.path.join(home, ".local")
install(user_base, HOME=home)
print("installed under ~/.local:", packages_under(user_base))
env = clean_env(HOME=home)
check_import(user_base, env, "--prefix ~/.local")
r = subprocess.run([python, "-m", "pytest", "-p", "splinefig.pytest_plugin", "-p", "no:cacheprovider", "--help"],
                   cwd=elsewhere, env=env, capture_output=True, text=True)
if r.returncode != 0 or "--splinefig-results" not in r.stdout:
    fail("pytest -p splinefig.pytest_plugin --help: exit %d, %s" % (r.returncode, (r.stderr.strip().splitlines() or [""])[-1]))
else:
    print("ok: pytest -p splinefig.pytest_plugin --help lists --splinefig-results")

# 2. Another prefix, read as the user base.
other = os.path.join(work, "prefix")
install(other)
print("installed under another prefix:", packages_under(other))
check_import(other, clean_env(HOME=home, PYTHONUSERBASE=other), "--prefix P with PYTHONUSERBASE=P")

# 3. The system prefixes, staged with DESTDIR: each package directory is on the interpreter's path.
sys_path = subprocess.run([python, "-c", "import sys; print('\\n'.join(sys.path))"], cwd=elsewhere,
                          env=clean_env(), capture_output=True, text=True, check=True).stdout.splitlines()
for prefix in ("/usr", "/usr/local"):
    dest = os.path.join(work, "destdir" + prefix.replace("/", "-"))
    install(prefix, DESTDIR=dest)
    found = packages_under(os.path.join(dest, prefix.lstrip("/")))
    dirs = [os.path.join(prefix, os.path.dirname(p)) for p in found]
    if len(dirs) != 1 or dirs[0] not in sys_path:
        fail("--prefix %s: the package went to %s, not one of the interpreter's %s" % (prefix, dirs, sys_path))
    else:
        print("ok: --prefix %s installs into %s, on sys.path" % (prefix, dirs[0]))

if failures:
    sys.exit("%d failure(s)" % len(failures))
