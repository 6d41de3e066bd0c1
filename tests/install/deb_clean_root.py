"""The .deb installed into a clean root holding only what it declares, then used there.

usage: deb_clean_root.py PACKAGE_DIR SOURCE_DIR WORK_DIR

The root holds the files of the packages the .deb Depends on and Recommends (what `apt install
./splinefig_*.deb` installs), closed over their own Depends and Pre-Depends, with Debian's
Essential packages, and the build tools a C++ user brings (cmake, g++, make) and catch2, which
the package Suggests for its matcher. Their files come from this machine's installed packages
(dpkg-query -L, hard links where possible), the dpkg database of the root lists exactly them, and
`dpkg --root ROOT -i` installs the .deb, so dpkg itself checks that its Depends are met there.
Then, chrooted into the root (a private mount namespace holding /proc and /dev), the package's
command draws a built-in figure, the consumer project builds with find_package(splinefig) and
runs (its PNG through the installed image I/O module), its Catch2 matcher test runs, a plain
c++ build with pkg-config --cflags --libs splinefig links and runs, and the Python package (when
the package holds it) imports and draws a figure. A -dev package the
CMake package or splinefig.pc needs and the .deb does not declare fails the build in the root.

Prints SPLINEFIG-SKIPPED (and exits 0) when the test cannot run here: not root, no chroot or
unshare, no package built (its test skipped without dpkg-dev), or a package to put in the root
is not installed on this machine.
"""
import glob
import os
import re
import shutil
import subprocess
import sys

package_dir, source, work = sys.argv[1:4]


def skip(why):
    print("SPLINEFIG-SKIPPED: " + why)
    sys.exit(0)


def run(args, **kw):
    return subprocess.run(args, capture_output=True, text=True, **kw)


if os.geteuid() != 0:
    skip("building a root to chroot into needs root")
for tool in ("dpkg", "dpkg-deb", "dpkg-query", "unshare", "chroot", "ldconfig", "mount"):
    if not shutil.which(tool):
        skip(tool + " not found")
debs = glob.glob(os.path.join(package_dir, "splinefig_*.deb"))
if not debs:
    skip("no package in %s (the test that builds it was skipped)" % package_dir)
if len(debs) != 1:
    sys.exit("expected one splinefig_*.deb in %s, found %s" % (package_dir, debs))
deb = debs[0]

# The installed packages: their dependencies, what they provide, whether they are Essential.
fmt = "${Package}\\t${db:Status-Abbrev}\\t${Essential}\\t${Provides}\\t${Depends}, ${Pre-Depends}\\n"
installed, provided_by, depends = {}, {}, {}
for line in run(["dpkg-query", "-W", "-f", fmt], check=True).stdout.splitlines():
    name, status, essential, provides, deps = line.split("\t")
    if not status.startswith("ii"):
        continue
    installed[name] = essential == "yes"
    depends[name] = deps
    for p in provides.split(","):
        p = re.sub(r"\(.*?\)", "", p).strip().split(":")[0]
        if p:
            provided_by.setdefault(p, name)


def names(field):
    """The alternatives of each entry of a Depends-like field, without versions or qualifiers."""
    out = []
    for entry in field.split(","):
        alts = [re.sub(r"\(.*?\)|\[.*?\]|<.*?>", "", a).strip().split(":")[0] for a in entry.split("|")]
        alts = [a for a in alts if a]
        if alts:
            out.append(alts)
    return out


def resolve(alts):
    for a in alts:
        if a in installed:
            return a
    for a in alts:
        if a in provided_by:
            return provided_by[a]
    return None


fields = run(["dpkg-deb", "-f", deb, "Depends", "Recommends"], check=True).stdout
declared = {}
for line in fields.splitlines():
    key, _, value = line.partition(": ")
    declared[key] = value
wanted = names(declared.get("Depends", "")) + names(declared.get("Recommends", ""))
wanted += [["cmake"], ["g++"], ["make"], ["catch2"]]  # the user's build tools; the Suggested matcher framework
wanted += [[p] for p, essential in installed.items() if essential]
closure, todo = set(), []
for alts in wanted:
    p = resolve(alts)
    if p is None:
        skip("%s, which the root needs, is not installed here" % " | ".join(alts))
    todo.append(p)
while todo:
    p = todo.pop()
    if p in closure:
        continue
    closure.add(p)
    for alts in names(depends[p]):
        d = resolve(alts)
        if d is None:
            sys.exit("%s depends on %s, which is not installed here" % (p, " | ".join(alts)))
        todo.append(d)
closure = sorted(closure)

def remove_work():
    """Removes WORK_DIR, never through a mount (the root's /dev and /proc are mounted only in the
    private namespace of the chroot, but a mount seen here would lead into this machine's)."""
    for d in ("dev", "proc"):
        if os.path.ismount(os.path.join(work, "root", d)):
            sys.exit("%s/root/%s is a mount point here: not removing %s" % (work, d, work))
    shutil.rmtree(work, ignore_errors=True)


remove_work()
root = os.path.join(work, "root")
os.makedirs(root)
for top in ("bin", "sbin", "lib", "lib32", "lib64", "libx32"):  # merged /usr: the same links as here
    if os.path.islink("/" + top):
        target = os.readlink("/" + top)
        os.makedirs(os.path.join(root, target.lstrip("/")), exist_ok=True)
        os.symlink(target, os.path.join(root, top))
linked = copied = 0


def place(path):
    """Puts this machine's file `path` (a directory, symbolic link or file) into the root."""
    global linked, copied
    dest = root + path
    if os.path.lexists(dest) or not os.path.lexists(path):
        return
    if os.path.islink(path):
        os.makedirs(os.path.dirname(dest), exist_ok=True)
        os.symlink(os.readlink(path), dest)
    elif os.path.isdir(path):
        os.makedirs(dest, exist_ok=True)
    elif os.path.isfile(path):
        os.makedirs(os.path.dirname(dest), exist_ok=True)
        try:
            os.link(path, dest)
            linked += 1
        except OSError:
            shutil.copy2(path, dest)
            copied += 1


listing = run(["dpkg-query", "-L"] + closure, check=True).stdout
for path in listing.splitlines():
    if path.startswith("/"):
        place(path)
# The alternatives their maintainer scripts chose here (c++, cc, pkg-config, ...), where the root holds the target.
for name in os.listdir("/etc/alternatives"):
    alt = os.path.join("/etc/alternatives", name)
    if os.path.islink(alt) and os.path.lexists(root + os.readlink(alt)):
        place(alt)
for d in ("/usr/bin", "/usr/sbin", "/usr/lib/x86_64-linux-gnu"):
    for name in os.listdir(d):
        p = os.path.join(d, name)
        if os.path.islink(p) and os.readlink(p).startswith("/etc/alternatives/") and os.path.lexists(root + os.readlink(p)):
            place(p)
for d in ("tmp", "proc", "dev", "src"):
    os.makedirs(os.path.join(root, d), exist_ok=True)
os.chmod(os.path.join(root, "tmp"), 0o1777)
for f in ("/etc/passwd", "/etc/group"):
    if not os.path.exists(root + f):
        shutil.copy2(f, root + f)
print("the root holds %d packages (%d files linked, %d copied)" % (len(closure), linked, copied))

# dpkg's database in the root lists exactly those packages; dpkg --root checks the .deb's Depends against it.
db = os.path.join(root, "var", "lib", "dpkg")
for d in ("info", "updates", "triggers"):
    os.makedirs(os.path.join(db, d), exist_ok=True)
with open(os.path.join(db, "status"), "w") as f:
    f.write(run(["dpkg-query", "-s"] + closure, check=True).stdout)
open(os.path.join(db, "available"), "w").close()
r = run(["dpkg", "--root=" + root, "--log=/dev/null", "--force-script-chrootless", "-i", deb],
        env=dict(os.environ, PATH=os.environ.get("PATH", "") + ":/usr/sbin:/sbin"))
if r.returncode != 0:
    sys.exit("dpkg --root ROOT -i %s failed (exit %d):\n%s%s" % (deb, r.returncode, r.stdout, r.stderr))
run(["ldconfig", "-r", root], check=True)
shutil.copytree(os.path.join(source, "tests", "install", "consumer"), os.path.join(root, "src", "consumer"))

script = r"""
set -e
cd /tmp
splinefig --version
splinefig render /usr/share/splinefig/specs/bias.toml -o /tmp/bias.png
splinefig resample /tmp/bias.png -o /tmp/half.exr --scale 0.5 --filter mitchell
cmake -S /src/consumer -B /tmp/consumer > /tmp/configure.log 2>&1 || { cat /tmp/configure.log; exit 1; }
cmake --build /tmp/consumer > /tmp/build.log 2>&1 || { cat /tmp/build.log; exit 1; }
/tmp/consumer/consumer /tmp
(cd /tmp && /tmp/consumer/matcher_test)
c++ -O1 -o /tmp/pc_consumer /src/consumer/main.cpp $(pkg-config --cflags --libs splinefig)
/tmp/pc_consumer /tmp
if [ -d /usr/lib/python3/dist-packages/splinefig ]; then
  (cd /tmp && python3 -c "import splinefig; print('python:', splinefig.__file__, splinefig.render_figure('bias').shape)")
fi
echo all-ran
"""
mounts = "mount --rbind /dev {r}/dev && mount -t proc proc {r}/proc && exec chroot {r} /bin/sh -c \"$1\"".format(r=root)
env = {"PATH": "/usr/local/bin:/usr/bin:/bin:/usr/sbin:/sbin", "HOME": "/tmp", "LANG": "C.UTF-8"}
r = run(["unshare", "--mount", "--propagation", "private", "--pid", "--fork", "sh", "-c", mounts, "sh", script], env=env)
print(r.stdout)
if r.returncode != 0 or "all-ran" not in r.stdout:
    sys.exit("in the clean root (exit %d):\n%s" % (r.returncode, r.stderr))
print("ok: in a root of the package's Depends and Recommends only, the command ran and the consumer built and ran "
      "with find_package and with pkg-config")
remove_work()
