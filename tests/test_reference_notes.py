#!/usr/bin/env python3
"""The report is for a reader (issue 45 item 5): a target's shared analysis is written once, in
reference/<target>.md (paper/build_report.py shows it in the target's section above the table), and each row's
explanation and why_tolerance in reference/<target>.csv (the note in results/check.csv and the report: the explanation
of a DISCREPANCY row, the why_tolerance of a PASS row and of a peer row) say only what is particular to that row, in at
most NOTE_LIMIT characters each.

Fails, naming file, line, quantity, column and length, for every explanation or why_tolerance longer than NOTE_LIMIT
(read as reference/check.py reads the files), and for a reference/*.md other than README.md whose target is not
declared in experiments/targets.mk (an analysis the report would never show). Run by ctest.
"""
import glob
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(ROOT, "reference"))
import check  # noqa: E402  (reference/check.py: its reader of the reference files)

NOTE_LIMIT = 400
NOTE_COLUMNS = ("explanation", "why_tolerance")  # the cells check.py puts in a row's note


def problems(ref_dir):
    ref = check.load_reference(ref_dir)
    found = [f"reference/{r['ref_file']}:{r['ref_line']} {r['target']}/{r['quantity']}: {column} of "
             f"{len(r[column])} characters (at most {NOTE_LIMIT}: what the row shares with its target's "
             f"other rows belongs in reference/{r['target']}.md)"
             for _, r in ref.iterrows() for column in NOTE_COLUMNS if len(r[column]) > NOTE_LIMIT]
    declared = set(check.declared_targets())
    for path in sorted(glob.glob(os.path.join(ref_dir, "*.md"))):
        name = os.path.basename(path)[:-len(".md")]
        if name != "README" and name not in declared:
            found.append(f"reference/{name}.md: not a target declared in experiments/targets.mk")
    return found


def main():
    found = problems(os.path.join(ROOT, "reference"))
    for p in found:
        print(p)
    if found:
        return 1
    print(f"test_reference_notes: every explanation and why_tolerance within {NOTE_LIMIT} characters; every "
          "reference/*.md names a declared target")
    return 0


if __name__ == "__main__":
    sys.exit(main())
