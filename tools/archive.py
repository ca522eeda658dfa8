#!/usr/bin/env python3
"""A citable archive of one reproduction (`make archive`) and its verification (`make verify-archive`).

    archive.py create --results DIR --figures DIR --report FILE --out FILE.tar.gz [--packages P ...]
    archive.py verify FILE.tar.gz

`create` writes one gzipped tarball holding, under one top-level folder named after the archive:
  results/      every file of the results directory (the drivers' CSVs and snapshots, check.csv, timings.csv, the
                run jobs' folders under .runs); not Make's markers (.done, .figures_start) nor a store of runs
                left by versions before issue 45 (.run_cache: binary, intermediate)
  figures/      the figures
  report/       the report (its HTML file)
  PROVENANCE.json   the code version (git commit, whether the checkout had uncommitted changes and which files),
                the code versions and drivers recorded in the results' own headers, every driver command line
                (rebuilt from those headers: the driver, its output folder and every parameter given on its
                command line with its value), the versions of the Debian packages the build and plots use, the
                compiler, the machine (CPU model, cores, memory, kernel) and the date
  commands.txt  the command lines alone, one per line, in the order of PROVENANCE.json
  SHA256SUMS    the SHA-256 of every other file, in `sha256sum -c` format (paths relative to the top folder)
`verify` recomputes every checksum from the tarball and fails (exit 1) on a changed, missing or unlisted file,
or on a member that is not a plain file or directory inside the top folder; it prints what it found. SHA256SUMS
cannot reveal a change made together with a rewritten SHA256SUMS: `create` prints the SHA-256 of the tarball
itself, to be cited with it, and `verify --sha256 HEX` checks that as well.
"""
import argparse
import hashlib
import io
import json
import os
import platform
import re
import subprocess
import sys
import tarfile
import time

SKIP_NAMES = {".done", ".figures_start"}
SKIP_DIRS = {".run_cache"}


def sha256(data):
    return hashlib.sha256(data).hexdigest()


def run(cmd, cwd=None):
    try:
        return subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return None


def files_under(root):
    """Every regular file under root (sorted, relative paths), without the skipped names."""
    out = []
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = sorted(d for d in dirnames if d not in SKIP_DIRS)
        for f in sorted(filenames):
            if f in SKIP_NAMES:
                continue
            p = os.path.join(dirpath, f)
            if os.path.isfile(p) and not os.path.islink(p):
                out.append(os.path.relpath(p, root))
    return out


def header_of(path):
    """The '# key = value' header of a CSV written by the driver frame ({} for other files)."""
    head = {}
    try:
        with open(path, errors="replace") as f:
            for line in f:
                if not line.startswith("# "):
                    break
                m = re.match(r"# ([^=]+?) = (.*)$", line.rstrip("\n"))
                if m:
                    head[m.group(1)] = m.group(2)
    except OSError:
        pass
    return head


def command_of(head, out_dir):
    """The driver's command line rebuilt from its header: the parameters in `given`, with their values."""
    args = [f"build/bin/{head['driver']}", "--out", out_dir]
    for name in head.get("given", "").split():
        value = head.get(f"param.{name}")
        if value in (None, "true"):
            args.append(f"--{name}")
        elif value == "false":
            args.append(f"--{name}=false")
        else:
            args += [f"--{name}"] + value.split(" ")
    return " ".join(args)


def provenance(results, packages, repo):
    runs = {}
    versions = set()
    for rel in files_under(results):
        if not rel.endswith(".csv"):
            continue
        head = header_of(os.path.join(results, rel))
        if "driver" not in head:
            continue
        versions.add(head.get("code_version", "unknown"))
        out_dir = os.path.join("results", os.path.dirname(rel))
        cmd = command_of(head, out_dir)
        runs.setdefault(cmd, {"driver": head["driver"], "target": head.get("target", ""),
                              "code_version": head.get("code_version", ""), "command": cmd})
    status = run(["git", "status", "--porcelain"], cwd=repo)
    cpu = "unknown"
    mem = None
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next((l.split(":", 1)[1].strip() for l in f if l.startswith("model name")), cpu)
        with open("/proc/meminfo") as f:
            mem = next((l.split(":", 1)[1].strip() for l in f if l.startswith("MemTotal")), None)
    except OSError:
        pass
    pkgs = {}
    for p in packages:
        v = run(["dpkg-query", "-W", "-f=${Version}", p])
        pkgs[p] = v if v else "not installed"
    return {
        "archive_format": 1,
        "created_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
        "code": {
            "commit": run(["git", "rev-parse", "HEAD"], cwd=repo),
            "describe": run(["git", "describe", "--always", "--dirty"], cwd=repo),
            "uncommitted_changes": [l[3:] for l in status.splitlines()] if status else [],
            "versions_in_results": sorted(versions),
        },
        "runs": sorted(runs.values(), key=lambda r: (r["driver"], r["command"])),
        "environment": {
            "debian_packages": pkgs,
            "compiler": (run(["c++", "--version"]) or "unknown").splitlines()[0],
            "python": sys.version.split()[0],
            "os": (run(["sh", "-c", ". /etc/os-release && echo $PRETTY_NAME"]) or platform.platform()),
        },
        "machine": {"cpu_model": cpu, "cores": os.cpu_count(), "memory": mem, "kernel": platform.release(),
                    "architecture": platform.machine()},
    }


def create(args):
    top = os.path.basename(args.out)
    for suffix in (".tar.gz", ".tgz"):
        if top.endswith(suffix):
            top = top[: -len(suffix)]
    if not os.path.isdir(args.results) or not files_under(args.results):
        sys.exit(f"archive: no results under {args.results}: run make figures (or make quick) first")
    members = []  # (path in archive, bytes)
    for rel in files_under(args.results):
        with open(os.path.join(args.results, rel), "rb") as f:
            members.append((f"results/{rel}", f.read()))
    # The figures folder may lie inside the results one (make quick): then they are in results/ already.
    figures_inside = os.path.abspath(args.figures).startswith(os.path.abspath(args.results) + os.sep)
    if os.path.isdir(args.figures) and not figures_inside:
        for rel in files_under(args.figures):
            with open(os.path.join(args.figures, rel), "rb") as f:
                members.append((f"figures/{rel}", f.read()))
    if args.report and os.path.isfile(args.report):
        with open(args.report, "rb") as f:
            members.append((f"report/{os.path.basename(args.report)}", f.read()))
    elif args.report:
        print(f"archive: no report at {args.report} (archived without it)")
    prov = provenance(args.results, args.packages, args.repo)
    members.append(("PROVENANCE.json", (json.dumps(prov, indent=1) + "\n").encode()))
    members.append(("commands.txt", "".join(r["command"] + "\n" for r in prov["runs"]).encode()))
    sums = "".join(f"{sha256(data)}  {path}\n" for path, data in members)
    members.append(("SHA256SUMS", sums.encode()))
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    tmp = args.out + ".partial"
    with tarfile.open(tmp, "w:gz") as tar:
        for path, data in members:
            info = tarfile.TarInfo(f"{top}/{path}")
            info.size = len(data)
            info.mtime = int(time.time())
            info.mode = 0o644
            tar.addfile(info, io.BytesIO(data))
    os.replace(tmp, args.out)
    size = os.path.getsize(args.out)
    with open(args.out, "rb") as f:
        digest = sha256(f.read())
    print(f"archive: {args.out} ({len(members)} files, {size / 1e6:.1f} MB), code {prov['code']['describe']}")
    print(f"archive: SHA-256 of the tarball {digest} (cite it with the archive: SHA256SUMS inside detects a changed"
          " file, this one a rewritten SHA256SUMS too; make verify-archive FILE=... SHA256=... checks both)")
    if prov["code"]["uncommitted_changes"]:
        print(f"archive: NOTE the checkout had uncommitted changes ({len(prov['code']['uncommitted_changes'])} files): "
              "recorded in PROVENANCE.json")
    if len(prov["code"]["versions_in_results"]) > 1:
        print(f"archive: NOTE the results were written by several code versions: {prov['code']['versions_in_results']}")
    return 0


def verify(args):
    problems = []
    if args.sha256:
        try:
            with open(args.file, "rb") as f:
                got = sha256(f.read())
        except OSError as e:
            print(f"verify-archive: cannot read {args.file}: {e}")
            return 1
        if got != args.sha256.lower():
            problems.append(f"the tarball's SHA-256 is {got}, not the cited {args.sha256}")
    try:
        tar = tarfile.open(args.file, "r:*")
    except (OSError, tarfile.TarError) as e:
        print(f"verify-archive: cannot read {args.file}: {e}")
        return 1
    with tar:
        files = {}
        tops = set()
        for m in tar.getmembers():
            parts = m.name.split("/")
            if m.name.startswith("/") or ".." in parts or len(parts) < 2:
                problems.append(f"member outside the archive's folder: {m.name}")
                continue
            tops.add(parts[0])
            if m.isdir():
                continue
            if not m.isfile():
                problems.append(f"not a plain file: {m.name}")
                continue
            rel = "/".join(parts[1:])
            if rel in files:
                problems.append(f"stored twice: {rel}")
            files[rel] = tar.extractfile(m).read()
        if len(tops) > 1:
            problems.append(f"more than one top folder: {sorted(tops)}")
        if "SHA256SUMS" not in files:
            print(f"verify-archive: {args.file}: no SHA256SUMS")
            return 1
        listed = {}
        for line in files["SHA256SUMS"].decode(errors="replace").splitlines():
            m = re.match(r"^([0-9a-f]{64})  (.+)$", line)
            if not m:
                problems.append(f"malformed SHA256SUMS line: {line!r}")
                continue
            listed[m.group(2)] = m.group(1)
        for rel, digest in sorted(listed.items()):
            if rel not in files:
                problems.append(f"missing: {rel}")
            elif sha256(files[rel]) != digest:
                problems.append(f"changed: {rel}")
        for rel in sorted(set(files) - set(listed) - {"SHA256SUMS"}):
            problems.append(f"not in SHA256SUMS: {rel}")
        for must in ("PROVENANCE.json", "commands.txt"):
            if must not in listed:
                problems.append(f"no {must}")
    if problems:
        print(f"verify-archive: {args.file}: FAILED ({len(problems)} problems)")
        for p in problems[:50]:
            print("  " + p)
        return 1
    prov = json.loads(files["PROVENANCE.json"])
    print(f"verify-archive: {args.file}: OK, {len(listed)} files match their SHA-256; code {prov['code']['describe']}, "
          f"{len(prov['runs'])} driver runs, machine {prov['machine']['cpu_model']} ({prov['machine']['cores']} cores)")
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    c = sub.add_parser("create")
    c.add_argument("--results", required=True)
    c.add_argument("--figures", required=True)
    c.add_argument("--report", default="")
    c.add_argument("--out", required=True)
    c.add_argument("--repo", default=".")
    c.add_argument("--packages", nargs="*", default=[])
    v = sub.add_parser("verify")
    v.add_argument("file")
    v.add_argument("--sha256", default="", help="the tarball's cited SHA-256 (optional)")
    args = ap.parse_args()
    return create(args) if args.cmd == "create" else verify(args)


if __name__ == "__main__":
    sys.exit(main())
