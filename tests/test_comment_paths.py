#!/usr/bin/env python3
"""Every path a comment or a docstring names exists (issue 45 item 6): a comment that sends the reader to a file
that has moved or gone is wrong, and no compiler notices.

Scans the project's sources (C++, Python, shell, Make, CMake, LAMMPS inputs) for path-like words in their comments
and docstrings (a file, or a stem with any extension as src/kernels.*), with or without a leading folder: `experiments/gray2001/scenes/plate.hpp`,
`gray2001/scenes/plate.hpp` (an include path, under experiments/), `core/run_loop.hpp` (under src/),
`tools/peers/run_peers.py`. A word counts as a path when it has a folder part and a file extension the project
uses; paths into generated trees (results/, build/, figures/, paper/build/), into other projects' trees (PySPH's,
LAMMPS's: EXTERNAL), with a placeholder (<...>, *, {...}, $, or a one-letter name such as reference/T.csv) are not
checked. Each path must exist relative to
the repository root, or to src/ or experiments/ (the two include roots), or beside the file that names it.
Prints each stale path with its file and line; exits 1 if there is any. Run by ctest.
"""
import glob
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOURCE_DIRS = ["src", "experiments", "tests", "tools", "plots", "reference", "paper", "cmake", ".ci"]
TOP_FILES = ["Makefile", "CMakeLists.txt"]
EXTENSIONS = ("hpp", "cpp", "h", "py", "sh", "mk", "csv", "in", "md", "cmake", "txt", "json")
GENERATED = ("results/", "build/", "build-", "figures/", "paper/build/", "/tmp/", "~/", "../shared/", "./")
# Paths inside other projects' trees, named as those projects name them: PySPH's package and examples, LAMMPS's
# source tree (the MACHDYN plugin is built from it).
EXTERNAL = ("pysph/", "examples/solid_mech/", "solid_mech/", "src/PLUGIN/", "src/MACHDYN/")
PATH = re.compile(r"(?<![\w./<-])((?:[A-Za-z_.][\w.+-]*/)+[\w.+-]+\.(?:%s))(?![\w/])" % "|".join(EXTENSIONS))
# A file named by its stem and any extension: src/kernels.* (checked as a glob: some file must match).
STEM = re.compile(r"(?<![\w./<-])((?:[A-Za-z_.][\w.+-]*/)+[\w+-]+)\.\*")
# A comment's text: C++ // and /* */ lines, '#' lines of Python, shell, Make, CMake and LAMMPS, Python docstrings.
COMMENT_EXT = {".hpp": "cpp", ".cpp": "cpp", ".h": "cpp", ".py": "py", ".sh": "hash", ".mk": "hash", ".in": "hash",
               ".cmake": "hash", ".txt": "hash"}


def comment_lines(path, kind):
    """(line number, text) of the comment and docstring parts of a file."""
    with open(path, errors="replace") as f:
        lines = f.read().split("\n")
    out, in_block, in_doc = [], False, None
    for i, line in enumerate(lines, 1):
        s = line.strip()
        if kind == "cpp":
            if in_block:
                out.append((i, line))
                in_block = "*/" not in line
                continue
            if "/*" in line:
                out.append((i, line[line.index("/*"):]))
                in_block = "*/" not in line[line.index("/*"):]
                continue
            if "//" in line:
                out.append((i, line[line.index("//"):]))
            continue
        if kind == "py":
            if in_doc:
                out.append((i, line))
                if in_doc in line:
                    in_doc = None
                continue
            for q in ('"""', "'''"):
                if q in line:
                    rest = line[line.index(q) + 3:]
                    out.append((i, line))
                    if q not in rest:
                        in_doc = q
                    break
            else:
                if "#" in line:
                    out.append((i, line[line.index("#"):]))
            continue
        if "#" in line:  # shell, Make, CMake, LAMMPS
            out.append((i, line[line.index("#"):]))
    return out


def exists(word, here, stem=False):
    for base in (ROOT, os.path.join(ROOT, "src"), os.path.join(ROOT, "experiments"), here):
        if glob.glob(os.path.join(base, word) + ".*") if stem else os.path.exists(os.path.join(base, word)):
            return True
    return False


def stale_paths():
    files = [os.path.join(ROOT, f) for f in TOP_FILES]
    for d in SOURCE_DIRS:
        for dp, dirs, fs in os.walk(os.path.join(ROOT, d)):
            dirs[:] = [x for x in dirs if x != "__pycache__"]
            files += [os.path.join(dp, f) for f in fs]
    out = []
    for path in sorted(files):
        name = os.path.basename(path)
        kind = "hash" if name in TOP_FILES else COMMENT_EXT.get(os.path.splitext(name)[1])
        if kind is None or path == os.path.abspath(__file__):
            continue
        for lineno, text in comment_lines(path, kind):
            for m in PATH.finditer(text):
                word = m.group(1).rstrip(".")
                if word.startswith(GENERATED + EXTERNAL) or any(c in text[max(0, m.start() - 1):m.end() + 1] for c in "<>*{}$"):
                    continue
                if re.fullmatch(r"[A-Z]", os.path.splitext(os.path.basename(word))[0]):  # reference/T.csv: T a target
                    continue
                if not exists(word, os.path.dirname(path)):
                    out.append(f"{os.path.relpath(path, ROOT)}:{lineno}: {word}")
            for m in STEM.finditer(text):
                word = m.group(1)
                if not word.startswith(GENERATED + EXTERNAL) and not exists(word, os.path.dirname(path), stem=True):
                    out.append(f"{os.path.relpath(path, ROOT)}:{lineno}: {word}.*")
    return out


def main():
    stale = stale_paths()
    for s in stale:
        print(f"stale path in a comment: {s}")
    print(f"test_comment_paths: {len(stale)} stale path(s)")
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
