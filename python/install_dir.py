"""Prints where this interpreter reads packages under the prefix sys.argv[1], relative to it.

Run by `cmake --install` (python/CMakeLists.txt) with the interpreter the module was built for.
The directories the interpreter reads are its sys.path's site directories and its user site
(site.getusersitepackages(), ~/.local/lib/python3.X/site-packages or under $PYTHONUSERBASE,
read once it exists). Of those under the prefix, the nearest is the prefix's own: under /usr,
Debian's python3 reads /usr/lib/python3/dist-packages but also /usr/local/lib/python3.X/dist-packages,
which belongs to the prefix /usr/local. A prefix the interpreter does not read gets the user
scheme's layout (lib/python3.X/site-packages), read with PYTHONUSERBASE=prefix, and the layout a
virtual environment or a non-Debian Python has under its own prefix.
"""
import os
import site
import sys
import sysconfig


def package_dir(prefix):
    prefix = os.path.realpath(prefix)
    read = [p for p in sys.path if os.path.basename(p) in ("site-packages", "dist-packages")]
    read.append(site.getusersitepackages())
    under = []
    for p in read:
        rel = os.path.relpath(os.path.realpath(p), prefix)
        if rel != os.curdir and rel != os.pardir and not rel.startswith(os.pardir + os.sep):
            under.append(rel)
    if under:
        return min(under, key=lambda rel: len(rel.split(os.sep)))
    user = sysconfig.get_path("purelib", "posix_user", vars={"userbase": prefix})
    return os.path.relpath(user, prefix)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: install_dir.py PREFIX")
    print(package_dir(sys.argv[1]))
