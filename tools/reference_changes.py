#!/usr/bin/env python3
"""Every reference row changed between two revisions, with what changed and the commits that changed it.

    tools/reference_changes.py BASE [HEAD]      (markdown on stdout)

A closing note must list every reference row it changed, before and after, and why (issue 14): this lists the
rows added, removed and changed in reference/*.csv, the check fields that differ (published, compare,
tolerance, expect, kind, alt_quantity, analysis_value, own_band, quick, settings; a changed explanation or
why_tolerance is named, not printed), and each commit between the two that touched the row, by subject.
"""
import csv
import io
import subprocess
import sys

CHECK_FIELDS = ["published", "compare", "tolerance", "expect", "kind", "alt_quantity", "analysis_value",
                "own_band", "quick", "settings"]
TEXT_FIELDS = ["explanation", "why_tolerance", "source", "unit"]


def git(*args):
    return subprocess.run(["git", *args], check=True, capture_output=True, text=True).stdout


def rows_at(rev):
    out = {}
    names = [n for n in git("ls-tree", "--name-only", rev, "reference/").split() if n.endswith(".csv")]
    for name in names:
        text = "".join(l + "\n" for l in git("show", f"{rev}:{name}").splitlines() if not l.startswith("#"))
        for r in csv.DictReader(io.StringIO(text)):
            # a column added to a file (kind, own_band, settings) is empty in its old rows: not a change
            out[(r["target"], r["quantity"])] = {k: (v or "") for k, v in r.items() if v}
    return out


def short(v, n=60):
    v = v or "-"
    return v if len(v) <= n else v[:n - 3] + "..."


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    base, head = sys.argv[1], sys.argv[2] if len(sys.argv) == 3 else "HEAD"
    commits = git("rev-list", "--reverse", f"{base}..{head}", "--", "reference/").split()
    snap = {c: rows_at(c) for c in commits}
    touched = {}
    prev = rows_at(base)
    for c in commits:
        cur = snap[c]
        for key in set(prev) | set(cur):
            if prev.get(key) != cur.get(key):
                touched.setdefault(key, []).append(c)
        prev = cur
    before, after = rows_at(base), rows_at(head)
    subject = {c: git("log", "-1", "--format=%h %s", c).strip() for c in commits}
    keys = sorted(k for k in set(before) | set(after) if before.get(k) != after.get(k))
    print(f"# Reference rows changed from {git('rev-parse', '--short', base).strip()} to "
          f"{git('rev-parse', '--short', head).strip()}: {len(keys)} rows "
          f"({sum(k not in before for k in keys)} added, {sum(k not in after for k in keys)} removed)\n")
    for key in keys:
        b, a = before.get(key), after.get(key)
        what = "added" if b is None else "removed" if a is None else "changed"
        print(f"- **{key[0]} {key[1]}** ({what})")
        if b is not None and a is not None:
            for f in CHECK_FIELDS:
                if (b.get(f) or "") != (a.get(f) or ""):
                    print(f"  - {f}: {short(b.get(f))} -> {short(a.get(f))}")
            texts = [f for f in TEXT_FIELDS if (b.get(f) or "") != (a.get(f) or "")]
            if texts:
                print(f"  - rewritten: {', '.join(texts)}")
        elif a is not None:
            print("  - " + ", ".join(f"{f} {short(a.get(f), 30)}" for f in ("published", "compare", "tolerance",
                                                                            "expect", "kind", "own_band")
                                     if a.get(f)))
        for c in touched.get(key, []):
            print(f"  - by {short(subject[c], 150)}")


if __name__ == "__main__":
    main()
