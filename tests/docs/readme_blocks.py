#!/usr/bin/env python3
"""Runs README.md's code blocks as a new user would, in order, in a scratch directory.

Every fenced block tagged sh, cmake or cpp is either run or marked, in an HTML comment on the
line before it, as not runnable with a reason. The markers:

  <!-- readme-run -->              sh: run with bash -eu; HOME is the scratch directory, the
                                   current directory holds `build` (the build tree) and what
                                   earlier blocks left there, and PATH starts with ~/.local/bin
  <!-- readme-file: NAME -->       any block: written to NAME in the current directory
  <!-- readme-test: NAME.cpp -->   cpp: built against the installed package (~/.local) with the
                                   targets of its first line, `// NAME.cpp: target_link_libraries(
                                   NAME PRIVATE ...)`, then run twice in the current directory,
                                   with SPLINEFIG_UPDATE_REFERENCES=1 and then without
  <!-- readme-cmake: NAME.cpp -->  cmake: the block is the CMakeLists.txt of a project whose
                                   program `app` is NAME (an earlier readme-file block), built
  <!-- not-runnable: REASON -->    left out, for REASON (which must be given)

Usage: readme_blocks.py README.md BUILD_DIR WORK_DIR
"""
import os
import re
import shutil
import subprocess
import sys

RUNNABLE = {"sh", "cmake", "cpp"}


def blocks(text):
    """(line number, tag, marker or None, code) of every fenced block."""
    lines = text.split("\n")
    out, i = [], 0
    while i < len(lines):
        m = re.match(r"^```(\w*)\s*$", lines[i])
        if not m:
            i += 1
            continue
        start, tag = i, m.group(1)
        j = i + 1
        while j < len(lines) and not lines[j].startswith("```"):
            j += 1
        k = start - 1
        while k >= 0 and not lines[k].strip():
            k -= 1
        marker = lines[k].strip() if k >= 0 and lines[k].strip().startswith("<!--") else None
        out.append((start + 1, tag, marker, "\n".join(lines[start + 1:j]) + "\n"))
        i = j + 1
    return out


def run(cmd, cwd, env, what):
    r = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=1200)
    if r.returncode != 0:
        sys.exit(f"README.md {what} failed ({r.returncode}):\n{r.stdout}{r.stderr}")
    return r.stdout


def cmake_project(where, name, body, env, what):
    src = os.path.join(where, "src-" + name)
    os.makedirs(src, exist_ok=True)
    with open(os.path.join(src, "CMakeLists.txt"), "w") as f:
        f.write(body)
    prefix = os.path.join(env["HOME"], ".local")
    build = os.path.join(where, "build-" + name)
    run(["cmake", "-S", src, "-B", build, "-DCMAKE_PREFIX_PATH=" + prefix], where, env, what + " (configure)")
    run(["cmake", "--build", build], where, env, what + " (build)")
    return src, build


def main():
    readme, build_dir, work = sys.argv[1:4]
    text = open(readme, encoding="utf-8").read()
    shutil.rmtree(work, ignore_errors=True)
    home = os.path.join(work, "home")
    cwd = os.path.join(home, "project")
    os.makedirs(cwd)
    os.symlink(os.path.abspath(build_dir), os.path.join(cwd, "build"))
    env = dict(os.environ)
    env["HOME"] = home
    env["PATH"] = os.path.join(home, ".local", "bin") + os.pathsep + env.get("PATH", "")
    env.pop("SPLINEFIG_TEST_RESULTS", None)
    env.pop("SPLINEFIG_UPDATE_REFERENCES", None)
    ran = skipped = 0
    for line, tag, marker, code in blocks(text):
        what = f"line {line} ({tag} block)"
        m = re.match(r"<!--\s*([a-z-]+)(?::\s*(.*?))?\s*-->$", marker or "")
        kind, arg = (m.group(1), m.group(2)) if m else (None, None)
        if kind == "not-runnable":
            if not arg:
                sys.exit(f"README.md {what}: not-runnable needs a reason")
            skipped += 1
            print(f"{what}: not run: {arg}")
            continue
        if kind == "readme-file":
            with open(os.path.join(cwd, arg), "w") as f:
                f.write(code)
            print(f"{what}: written to {arg}")
            continue
        if tag not in RUNNABLE:
            continue
        if kind == "readme-run" and tag == "sh":
            out = run(["bash", "-euc", code], cwd, env, what)
            print(f"{what}: ran\n{out}", end="" if out.endswith("\n") or not out else "\n")
        elif kind == "readme-test" and tag == "cpp":
            name = os.path.splitext(arg)[0]
            first = re.match(r"//\s*" + re.escape(arg) + r":\s*(target_link_libraries\(" + re.escape(name) +
                             r"\s+PRIVATE[^)]*\))", code)
            if not first:
                sys.exit(f"README.md {what}: the first line must be // {arg}: target_link_libraries({name} PRIVATE ...)")
            body = ("cmake_minimum_required(VERSION 3.25)\nproject(readme_" + name + " LANGUAGES CXX)\n"
                    "find_package(splinefig REQUIRED)\nfind_package(GTest CONFIG QUIET)\n"
                    f"add_executable({name} {os.path.join(cwd, arg)})\n{first.group(1)}\n")
            with open(os.path.join(cwd, arg), "w") as f:
                f.write(code)
            _, build = cmake_project(work, name, body, env, what)
            exe = os.path.join(build, name)
            for update in ("1", "0"):
                e = dict(env)
                if update == "1":
                    e["SPLINEFIG_UPDATE_REFERENCES"] = "1"
                run([exe], cwd, e, f"{what}: {name} (SPLINEFIG_UPDATE_REFERENCES={update})")
            print(f"{what}: {arg} built and passed twice (writing its reference, then against it)")
        elif kind == "readme-cmake" and tag == "cmake":
            body = ("cmake_minimum_required(VERSION 3.25)\nproject(readme_cmake LANGUAGES CXX)\n"
                    f"add_executable(app {os.path.join(cwd, arg)})\n" + code)
            _, build = cmake_project(work, "cmake", body, env, what)
            run([os.path.join(build, "app")], cwd, env, what + " (app)")
            print(f"{what}: configured, built and ran app from {arg}")
        else:
            sys.exit(f"README.md {what}: neither run nor marked <!-- not-runnable: REASON --> "
                     f"(marker: {marker or 'none'})")
        ran += 1
    if ran == 0:
        sys.exit("README.md: no block was run")
    print(f"README.md: {ran} blocks run, {skipped} not runnable (with their reasons)")


if __name__ == "__main__":
    main()
