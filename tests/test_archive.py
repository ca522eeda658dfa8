#!/usr/bin/env python3
"""make archive / make verify-archive (tools/archive.py; issue 17): an archive of a small results folder
verifies, and each kind of tampering fails the verification: a changed byte in a result, a removed file, an
added file, a member outside the archive's folder, a changed file with SHA256SUMS rewritten to match (caught
only by the tarball's cited SHA-256), and a tarball cut short. Also: the provenance names the code version
and rebuilds the driver's command line from its CSV header."""
import hashlib
import io
import json
import os
import subprocess
import sys
import tarfile
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.path.join(HERE, "..", "tools", "archive.py")
failures = []


def check(cond, what):
    print(("ok    " if cond else "FAIL  ") + what)
    if not cond:
        failures.append(what)


def verify(path, *extra):
    r = subprocess.run([sys.executable, TOOL, "verify", path, *extra], capture_output=True, text=True)
    return r.returncode, r.stdout + r.stderr


def rewrite(src, dst, change):
    """Copies tarball src to dst, passing every (TarInfo, bytes) through change(), which returns a list of them."""
    with tarfile.open(src, "r:gz") as a, tarfile.open(dst, "w:gz") as b:
        for m in a.getmembers():
            data = a.extractfile(m).read() if m.isfile() else b""
            for info, d in change(m, data):
                info.size = len(d)
                b.addfile(info, io.BytesIO(d))


def main():
    with tempfile.TemporaryDirectory() as tmp:
        res = os.path.join(tmp, "results")
        os.makedirs(os.path.join(res, "G-fig4"))
        os.makedirs(os.path.join(res, ".run_cache"))
        with open(os.path.join(res, "G-fig4", "values_x.csv"), "w") as f:
            f.write("# driver = gray2001_fig4_plate_resolution\n# target = G-fig4\n# code_version = abc123\n"
                    "# param.n = 10 20\n# param.cfl = 0.5\n# param.quick = true\n# given = quick n\n"
                    "quantity,value,note\nperiod,1135.7,x\n")
        with open(os.path.join(res, "check.csv"), "w") as f:
            f.write("target,quantity,status\nG-fig4,period,PASS\n")
        open(os.path.join(res, "G-fig4", ".done"), "w").close()
        open(os.path.join(res, ".run_cache", "big.bin"), "w").write("intermediate")
        figs = os.path.join(tmp, "figures")
        os.makedirs(figs)
        open(os.path.join(figs, "G-fig4.png"), "wb").write(b"\x89PNG fake")
        report = os.path.join(tmp, "index.html")
        open(report, "w").write("<html>report</html>")
        out = os.path.join(tmp, "repro.tar.gz")
        r = subprocess.run([sys.executable, TOOL, "create", "--results", res, "--figures", figs, "--report", report,
                            "--out", out, "--repo", os.path.join(HERE, ".."), "--packages", "make"],
                           capture_output=True, text=True)
        check(r.returncode == 0, "create exits 0: " + (r.stdout + r.stderr).strip().splitlines()[0])
        digest = hashlib.sha256(open(out, "rb").read()).hexdigest()
        check(digest in r.stdout, "create prints the tarball's SHA-256")
        with tarfile.open(out) as t:
            names = sorted(m.name for m in t.getmembers())
            prov = json.loads(t.extractfile("repro/PROVENANCE.json").read())
            commands = t.extractfile("repro/commands.txt").read().decode()
        check(names == sorted(["repro/results/G-fig4/values_x.csv", "repro/results/check.csv",
                               "repro/figures/G-fig4.png", "repro/report/index.html", "repro/PROVENANCE.json",
                               "repro/commands.txt", "repro/SHA256SUMS"]),
              f"the archive holds results, figures, report, provenance, commands, checksums, not .run_cache or .done: {names}")
        check(prov["code"]["commit"] and len(prov["code"]["commit"]) == 40, "provenance: the git commit")
        check(prov["code"]["versions_in_results"] == ["abc123"], "provenance: the code version of the results' headers")
        check(commands.strip() == "build/bin/gray2001_fig4_plate_resolution --out results/G-fig4 --quick --n 10 20",
              f"the command line rebuilt from the header: {commands.strip()!r}")
        check(prov["machine"]["cores"] and prov["machine"]["cpu_model"], "provenance: the machine")
        check("make" in prov["environment"]["debian_packages"], "provenance: the package versions")

        rc, text = verify(out)
        check(rc == 0 and "OK" in text, "the archive verifies: " + text.strip().splitlines()[0])
        rc, text = verify(out, "--sha256", digest)
        check(rc == 0, "and against its cited SHA-256")

        def changed_byte(m, d):
            if m.name.endswith("values_x.csv"):
                d = d.replace(b"1135.7", b"1135.8")
            return [(m, d)]
        bad = os.path.join(tmp, "changed.tar.gz")
        rewrite(out, bad, changed_byte)
        rc, text = verify(bad)
        check(rc == 1 and "changed: results/G-fig4/values_x.csv" in text, "a changed value fails: " + text.strip().splitlines()[-1])

        rewrite(out, bad, lambda m, d: [] if m.name.endswith("G-fig4.png") else [(m, d)])
        rc, text = verify(bad)
        check(rc == 1 and "missing: figures/G-fig4.png" in text, "a removed file fails")

        def added(m, d):
            extra = tarfile.TarInfo("repro/results/extra.csv")
            return [(m, d)] + ([(extra, b"a,b\n")] if m.name.endswith("check.csv") else [])
        rewrite(out, bad, added)
        rc, text = verify(bad)
        check(rc == 1 and "not in SHA256SUMS: results/extra.csv" in text, "an added file fails")

        def escape(m, d):
            if m.name.endswith("check.csv"):
                m.name = "../check.csv"
            return [(m, d)]
        rewrite(out, bad, escape)
        rc, text = verify(bad)
        check(rc == 1 and "outside" in text, "a member outside the archive's folder fails")

        def consistent(m, d):  # the value changed and SHA256SUMS rewritten to match it
            if m.name.endswith("values_x.csv"):
                d = d.replace(b"1135.7", b"1135.8")
            return [(m, d)]
        rewrite(out, bad, consistent)
        with tarfile.open(bad) as t:
            files = {m.name: t.extractfile(m).read() for m in t.getmembers() if m.isfile()}
        sums = "".join(f"{hashlib.sha256(d).hexdigest()}  {n.split('/', 1)[1]}\n" for n, d in files.items()
                       if not n.endswith("SHA256SUMS"))
        files["repro/SHA256SUMS"] = sums.encode()
        with tarfile.open(bad, "w:gz") as t:
            for n, d in files.items():
                info = tarfile.TarInfo(n)
                info.size = len(d)
                t.addfile(info, io.BytesIO(d))
        rc, _ = verify(bad)
        check(rc == 0, "a change with SHA256SUMS rewritten passes the inner checksums (by construction) ...")
        rc, text = verify(bad, "--sha256", digest)
        check(rc == 1 and "not the cited" in text, "... and fails against the tarball's cited SHA-256")

        data = open(out, "rb").read()
        open(bad, "wb").write(data[: len(data) // 2])
        rc, text = verify(bad)
        check(rc == 1, "a tarball cut short fails")
    print(f"test_archive: {'FAILED ' + str(len(failures)) if failures else 'every check passed'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
