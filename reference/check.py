#!/usr/bin/env python3
"""Compare reproduced values with the published numbers in reference/*.csv.

Reference rows (one CSV per target, reference/<target>.csv; '#' lines are comments):
  target, quantity, published, unit, compare, tolerance, why_tolerance, source,
  expect, alt_quantity, analysis_value, explanation, quick
compare:  abs  |reproduced - published| <= tolerance
          rel  |reproduced - published| <= tolerance * |published|
          le   reproduced <= published + tolerance   (a published bound or claim)
          ge   reproduced >= published - tolerance
expect:   match        out of tolerance is a FAIL
          discrepancy  the published number is known not to reproduce; the row is DISCREPANCY when it does
                       not, and still FAILs unless the analysis holds: alt_quantity (a value the driver
                       computes under the reading that does reproduce the published number) must match
                       the published value, or, where no reading reproduces it, the reproduced value must
                       match analysis_value (the number the analysis predicts) within the tolerance.
quick:    no = not checked in --quick mode (the quick run cannot resolve it); anything else = checked.
settings  (optional column) parameters a row accepts set on the command line, separated by spaces.

What a value was computed with counts too (the header of its values file, written by the driver frame):
a row FAILs, by the name of the file and the setting, when the file records parameters set on the command
line ('# given = ...') other than the target's own arguments in experiments/targets.mk, --quick in --quick
mode, and the row's settings; when the file is a --quick run and the check is not; when the file has no
'given' record (results older than it: rerun); and when the values files of one target come from different
code versions (stale results mixed with new ones). A reproduced value that is not finite FAILs every row,
a discrepancy row too.

The targets are those declared in experiments/targets.mk: a reference file of an undeclared target, or a
declared target without its reference file, stops the check (exit 1) before anything is compared.

Reproduced values come from results/<target>/values_*.csv (quantity,value,note) written by the drivers.
Writes <results>/check.csv with columns target,quantity,published,reproduced,tolerance,status,source,note,
prints the table and a summary, and exits 1 on any FAIL.
"""
import argparse
import csv
import glob
import math
import os
import sys

import pandas as pd

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "experiments"))
import targets as declaration  # noqa: E402  (experiments/targets.py: the reader of experiments/targets.mk)

OUT_COLUMNS = ["target", "quantity", "published", "reproduced", "tolerance", "status", "source", "note"]
REF_COLUMNS = ["target", "quantity", "published", "unit", "compare", "tolerance", "why_tolerance", "source",
               "expect", "alt_quantity", "analysis_value", "explanation", "quick"]


def declared_targets():
    try:
        return declaration.read().names
    except declaration.DeclarationError as e:
        sys.exit(f"check: {e}")


def load_reference(ref_dir):
    paths = sorted(glob.glob(os.path.join(ref_dir, "*.csv")))
    declared = declared_targets()
    have = {os.path.basename(p)[:-len(".csv")] for p in paths}
    undeclared = sorted(have - set(declared))
    if undeclared:
        sys.exit(f"check: reference files for targets not declared in experiments/targets.mk: "
                 f"{', '.join(os.path.join(ref_dir, t + '.csv') for t in undeclared)}")
    lacking = [t for t in declared if t not in have]
    if lacking:
        sys.exit(f"check: declared targets (experiments/targets.mk) without a reference file in {ref_dir}: "
                 f"{', '.join(lacking)}")
    frames = []
    for path in paths:
        df = pd.read_csv(path, comment="#", dtype=str, keep_default_na=False, skipinitialspace=True)
        missing = [c for c in REF_COLUMNS if c not in df.columns]
        if missing:
            sys.exit(f"check: {path} lacks columns {missing}")
        df["ref_file"] = os.path.basename(path)
        frames.append(df)
    if not frames:
        sys.exit(f"check: no reference files in {ref_dir}")
    ref = pd.concat(frames, ignore_index=True).fillna("")  # a column only some files have (settings): ""
    dup = ref[ref.duplicated(["target", "quantity"], keep=False)]
    if len(dup):
        sys.exit(f"check: duplicate reference rows:\n{dup[['target', 'quantity']]}")
    return ref


def read_header(path):
    """The '# key = value' lines at the top of a results file, as a dict."""
    meta = {}
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            key, sep, value = line[2:].rstrip("\n").partition(" = ")
            if sep:
                meta[key.strip()] = value
    return meta


class Source:
    """Where a value comes from: its values file and what the file's header records about the run."""

    def __init__(self, path, meta):
        self.path = path
        self.code_version = meta.get("code_version", "")
        self.given = None if "given" not in meta else set(meta["given"].split())
        self.quick = meta.get("param.quick", "false") == "true"


def load_values(results_dir):
    """{(target, quantity): value} and {(target, quantity): Source}."""
    values, sources = {}, {}
    for path in sorted(glob.glob(os.path.join(results_dir, "*", "values_*.csv"))):
        target = os.path.basename(os.path.dirname(path))
        source = Source(os.path.relpath(path, results_dir), read_header(path))
        df = pd.read_csv(path, comment="#", dtype={"quantity": str, "note": str}, keep_default_na=False)
        for _, r in df.iterrows():
            key = (target, r["quantity"])
            if key in values:
                sys.exit(f"check: {target}/{r['quantity']} written twice ({path})")
            values[key] = float(r["value"])
            sources[key] = source
    return values, sources


def target_arguments():
    """{target: the parameter names its experiments/targets.mk arguments set}."""
    return {t.name: {a[2:].split("=", 1)[0] for a in t.args.split() if a.startswith("--")}
            for t in declaration.read().targets}


def mixed_versions(sources):
    """{target: sorted code versions} for the targets whose values files disagree on the code version."""
    versions = {}
    for (target, _), src in sources.items():
        versions.setdefault(target, set()).add(src.code_version)
    return {t: sorted(v) for t, v in versions.items() if len(v) > 1}


def refusal(row, source, allowed, quick_mode, mixed):
    """Why a value must not be checked against this row (None if it may)."""
    target = row["target"]
    if target in mixed:
        return f"values of {target} from different code versions ({', '.join(mixed[target])}): stale results, rerun the target"
    if source.given is None:
        return f"{source.path} does not record which parameters were set (results older than the check): rerun"
    if source.quick and not quick_mode:
        return f"{source.path} is a --quick run, checked as a full one"
    accepted = allowed | set(row.get("settings", "").split()) | ({"quick"} if quick_mode else set())
    extra = sorted(source.given - accepted)
    if extra:
        return (f"{source.path} was run with {' '.join('--' + e for e in extra)} set, which neither "
                f"experiments/targets.mk nor the reference row names")
    return None


def within(compare, reproduced, published, tol):
    if not math.isfinite(reproduced):
        return False
    if compare == "abs":
        return abs(reproduced - published) <= tol
    if compare == "rel":
        return abs(reproduced - published) <= tol * abs(published)
    if compare == "le":
        return reproduced <= published + tol
    if compare == "ge":
        return reproduced >= published - tol
    raise ValueError(f"unknown compare '{compare}'")


def describe_tolerance(compare, tol):
    return {"abs": f"abs {tol:g}", "rel": f"rel {tol:g}", "le": f"<= published + {tol:g}",
            "ge": f">= published - {tol:g}"}[compare]


def check_row(row, values, sources, allowed, quick_mode, mixed):
    target, q = row["target"], row["quantity"]
    published, tol, compare = float(row["published"]), float(row["tolerance"] or 0), row["compare"]
    reproduced = values.get((target, q))
    out = {"target": target, "quantity": q, "published": row["published"],
           "reproduced": "" if reproduced is None else f"{reproduced:.6g}",
           "tolerance": describe_tolerance(compare, tol), "source": row["source"]}
    if reproduced is None:
        return {**out, "status": "FAIL", "note": "no reproduced value (driver did not write it)"}
    why = refusal(row, sources[(target, q)], allowed, quick_mode, mixed)
    if why:
        return {**out, "status": "FAIL", "note": f"refused: {why}"}
    if not math.isfinite(reproduced):
        return {**out, "status": "FAIL", "note": "reproduced value is not finite"}
    ok = within(compare, reproduced, published, tol)
    expect = row["expect"] or "match"
    if expect == "match":
        note = row["why_tolerance"] if ok else f"out of tolerance; {row['why_tolerance']}"
        return {**out, "status": "PASS" if ok else "FAIL", "note": note}
    if expect != "discrepancy":
        raise ValueError(f"{target}/{q}: expect must be match or discrepancy, not '{expect}'")
    if ok:
        return {**out, "status": "PASS",
                "note": "recorded as a discrepancy but now reproduces: review reference/" + row["ref_file"]}
    # The discrepancy must be explained by a check that can itself fail.
    alt, analysis = row["alt_quantity"], row["analysis_value"]
    if alt:
        alt_value = values.get((target, alt))
        if alt_value is None:
            return {**out, "status": "FAIL", "note": f"discrepancy reading '{alt}' not computed"}
        if not within(compare, alt_value, published, tol):
            return {**out, "status": "FAIL",
                    "note": f"discrepancy reading '{alt}' = {alt_value:.6g} does not reproduce the published value either"}
        return {**out, "status": "DISCREPANCY", "note": f"{row['explanation']} [{alt} = {alt_value:.6g}]"}
    if analysis:
        a = float(analysis)
        if not within("abs" if compare in ("le", "ge") else compare, reproduced, a, tol if tol else 1e-9):
            return {**out, "status": "FAIL", "note": f"reproduced differs from the analysis value {a:g}"}
        return {**out, "status": "DISCREPANCY", "note": row["explanation"]}
    raise ValueError(f"{target}/{q}: a discrepancy row needs alt_quantity or analysis_value")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--results", default="results")
    ap.add_argument("--reference", default=os.path.dirname(os.path.abspath(__file__)))
    ap.add_argument("--quick", action="store_true", help="skip rows marked quick=no")
    ap.add_argument("--targets", nargs="*", help="only these targets")
    args = ap.parse_args()

    ref = load_reference(args.reference)
    values, sources = load_values(args.results)
    arguments, mixed = target_arguments(), mixed_versions(sources)
    rows = []
    for _, r in ref.iterrows():
        if args.targets and r["target"] not in args.targets:
            continue
        if args.quick and r["quick"].strip().lower() == "no":
            continue
        rows.append(check_row(r, values, sources, arguments.get(r["target"], set()), args.quick, mixed))
    out_path = os.path.join(args.results, "check.csv")
    os.makedirs(args.results, exist_ok=True)
    with open(out_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=OUT_COLUMNS)
        w.writeheader()
        w.writerows(rows)

    table = pd.DataFrame(rows, columns=OUT_COLUMNS)
    with pd.option_context("display.max_rows", None, "display.max_colwidth", 60, "display.width", 250):
        print(table[["target", "quantity", "published", "reproduced", "tolerance", "status"]].to_string(index=False))
    referenced = {(r["target"], r["quantity"]) for r in rows} | {
        (t, a) for t, a in zip(ref["target"], ref["alt_quantity"]) if a}
    unreferenced = sorted(k for k in values if k not in referenced and (not args.targets or k[0] in args.targets))
    counts = table["status"].value_counts()
    n = {s: int(counts.get(s, 0)) for s in ("PASS", "DISCREPANCY", "FAIL")}
    print(f"\ncheck: {len(rows)} rows: {n['PASS']} PASS, {n['DISCREPANCY']} DISCREPANCY, {n['FAIL']} FAIL"
          f"  ({len(unreferenced)} further reproduced values without a published counterpart) -> {out_path}")
    for _, r in table[table.status == "FAIL"].iterrows():
        print(f"  FAIL {r.target}/{r.quantity}: {r.note}")
    return 1 if n["FAIL"] else 0


if __name__ == "__main__":
    sys.exit(main())
