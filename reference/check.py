#!/usr/bin/env python3
"""Compare reproduced values with the published numbers in reference/*.csv.

Reference rows (one CSV per target, reference/<target>.csv; '#' lines are comments):
  target, quantity, published, unit, compare, tolerance, why_tolerance, source,
  expect, alt_quantity, analysis_value, explanation, quick
compare:  abs     |reproduced - published| <= tolerance
          rel     |reproduced - published| <= tolerance * |published|
          le      reproduced <= published + tolerance   (a published bound or claim)
          ge      reproduced >= published - tolerance
          abs_le  |reproduced| <= published + tolerance (a bound on a signed error: 'within about 1%')
expect:   match        out of tolerance is a FAIL
          discrepancy  the published number is known not to reproduce; the row is DISCREPANCY when it does
                       not, and FAILs unless both checks of its analysis hold:
                       1. its own value is bounded: the reproduced value lies in own_band ('lo..hi', each end a
                          number or a reproduced quantity of the same target with an optional factor,
                          '1.191*T_theory_H2_mu0.6': a relation the analysis predicts, tested in the same run; an
                          empty end, 'lo..', is open: the analysis predicts one side only, and the value must
                          still be finite), or,
                          where own_band is empty, within the tolerance of analysis_value (the number the analysis
                          predicts; abs for le/ge rows);
                       2. by its kind (column kind):
                          reading  another reading of the same published number reproduces it: alt_quantity (the
                                   same quantity computed by the driver under that reading) must match the
                                   published value within the tolerance;
                          erratum  a closed form: the paper's own equations, evaluated exactly, give our value
                                   (analysis_value) and not the printed one; no alternative;
                          open     no reading we compute reproduces the number: our open question, not the
                                   paper's error; no alternative.
                       reading and erratum rows are the paper's discrepancies, open rows ours; the check table
                       (column kind) and the summary count them apart.
          peer         ours against an independent code running the same scene at the same settings (make
                       peers, issue 44): the reproduced value is <code>_<variant>_over_ours_<quantity>_dp<dp>, the
                       peer's value over ours - 1, from <results>/peers/values_peers.csv (tools/peers/run_peers.py);
                       published is the difference expected (0), the tolerance derived before the peer run from what
                       differs between the two implementations; out of tolerance is a FAIL (our implementation has
                       drifted from the independent one). Peer rows are checked only when that file is present
                       (make peers takes hours; make figures does not run it): otherwise they are skipped and the
                       summary names how many. Each value is a ratio within one case (ours and the peer on the same
                       layout), so cases of different code versions do not mix in a value; the row's note names the
                       code version of ours that it judges, and the checkout's when they differ (make peers takes
                       hours: a peer row of another version is reported, not refused).
quick:    no = not checked in --quick mode (the quick run cannot resolve it); anything else = checked.
settings  (optional column) parameters a row accepts set on the command line, separated by spaces.
kind, own_band  (columns a file needs only when it has discrepancy rows) see expect.

What a value was computed with counts too (the header of its values file, written by the driver frame):
a row FAILs, by the name of the file and the setting, when the run that wrote the file did not complete (its
driver's completion record timing_<driver>.csv, written last, is missing or of another code version), when the
file records parameters set on the command line ('# given = ...') other than the target's own arguments in experiments/targets.mk, --quick in --quick
mode, and the row's settings; when the file is a --quick run and the check is not; when the file has no
'given' record (results older than it: rerun); and when the values files of one target come from different
code versions (stale results mixed with new ones), and when a values file is not of the checkout's code version
(git describe, as the build records it: stale results; --any-version checks old results on purpose, --code-version
names another). The quantities a row reads besides its own (a reading's alternative, an end of its own band) go
through the same refusals and must be finite. A reproduced value that is not finite FAILs every row, a
discrepancy row too.

The targets are those declared in experiments/targets.mk: a reference file of an undeclared target, or a
declared target without its reference file, stops the check (exit 1) before anything is compared.

Reproduced values come from results/<target>/values_*.csv (quantity,value,note) written by the drivers.
Writes <results>/check.csv with columns target,quantity,published,reproduced,tolerance,status,kind,source,note,
prints the table and a summary, and exits 1 on any FAIL.
"""
import argparse
import csv
import glob
import math
import os
import subprocess
import sys

import pandas as pd

sys.dont_write_bytecode = True
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "experiments"))
import targets as declaration  # noqa: E402  (experiments/targets.py: the reader of experiments/targets.mk)

# note: the row's text (why_tolerance, a discrepancy's explanation, or why it failed); evidence: the numbers a
# DISCREPANCY or peer verdict rests on, computed by this check (the own value's band, the reading's alternative
# value, the code version of a peer comparison), kept apart so that the note stays the reference's own words.
OUT_COLUMNS = ["target", "quantity", "published", "reproduced", "tolerance", "status", "kind", "source", "note",
               "evidence"]
KINDS = {"reading": "paper", "erratum": "paper", "open": "open"}  # kind -> whose discrepancy it is
COMPARES = ("abs", "rel", "le", "ge", "abs_le")
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
        lines = data_lines(path)
        try:
            df = pd.read_csv(path, comment="#", dtype=str, keep_default_na=False, skipinitialspace=True)
        except (pd.errors.ParserError, pd.errors.EmptyDataError) as e:
            sys.exit(f"check: {path}: not a CSV table ({e})")
        if not lines:
            sys.exit(f"check: {path}: no header line")
        missing = [c for c in REF_COLUMNS if c not in df.columns]
        if missing:
            sys.exit(f"check: {path}:{lines[0]}: the header lacks columns {missing}")
        if len(lines) != len(df) + 1:  # a '#' inside a field, or a quoted line break: rows cannot be located
            sys.exit(f"check: {path}: {len(df)} rows read from {len(lines) - 1} data lines ('#' is a comment "
                     f"anywhere on a line; quoted line breaks are not allowed)")
        df["ref_file"] = os.path.basename(path)
        df["ref_line"] = lines[1:]
        frames.append(df)
    if not frames:
        sys.exit(f"check: no reference files in {ref_dir}")
    ref = pd.concat(frames, ignore_index=True).fillna("")  # a column only some files have (settings): ""
    for col in ("kind", "own_band"):
        if col not in ref.columns:
            ref[col] = ""
    problems = [p for _, r in ref.iterrows() for p in row_problems(r)]
    if problems:
        sys.exit("check: malformed reference rows:\n  " + "\n  ".join(problems))
    dup = ref[ref.duplicated(["target", "quantity"], keep=False)]
    if len(dup):
        sys.exit("check: duplicate reference rows:\n  " + "\n  ".join(
            f"reference/{r['ref_file']}:{r['ref_line']} {r['target']}/{r['quantity']}" for _, r in dup.iterrows()))
    return ref


def data_lines(path):
    """The 1-based line numbers of a reference file's header and rows, as pandas reads it with comment='#'
    (lines that are blank or start with '#' are skipped), so that a refusal can name the line."""
    with open(path) as f:
        return [i for i, line in enumerate(f, 1) if line.strip() and not line.lstrip().startswith("#")]


def parse_bound(text, open_end):
    """One end of an own_band: a number, or a reproduced quantity of the same target with an optional factor
    ('1.191*T_theory_H2_mu0.6'): (factor, quantity or None, number); empty: open, (1, None, open_end).
    Raises ValueError if malformed."""
    if not text.strip():
        return 1.0, None, open_end
    factor, star, name = text.strip().partition("*")
    if not star:
        try:
            number = float(factor)
        except ValueError:
            number, factor, name = None, "1", factor
        if number is not None:
            if not math.isfinite(number):  # 'inf' or 'nan' would read as a bound; an open end is written empty
                raise ValueError(f"own_band end '{text}' is not finite (leave the end empty for an open band)")
            return 1.0, None, number
    name = name.strip()
    if not name or any(c in name for c in " ,*"):
        raise ValueError(f"own_band end '{text}' is neither a number nor [factor*]quantity")
    return float(factor), name, 0.0


def parse_band(text):
    """'lo..hi' -> (lo, hi), each end as parse_bound gives it (an empty end open: -inf or +inf); None if empty.
    Raises ValueError if malformed."""
    if not text:
        return None
    lo, sep, hi = text.partition("..")
    if not sep:
        raise ValueError(f"own_band '{text}' is not 'lo..hi'")
    if not lo.strip() and not hi.strip():
        raise ValueError(f"own_band '{text}' bounds nothing: at least one end must be given")
    band = parse_bound(lo, -math.inf), parse_bound(hi, math.inf)
    if band[0][1] is None and band[1][1] is None and band[0][2] > band[1][2]:
        raise ValueError(f"own_band '{text}' is not 'lo..hi' with lo <= hi")
    return band


def band_end(bound, target, values):
    """The value of one end of an own_band (None if it names a quantity the driver did not write)."""
    factor, name, number = bound
    if name is None:
        return number
    v = values.get((target, name))
    return None if v is None else factor * v


def finite_number(text):
    try:
        return math.isfinite(float(text))
    except ValueError:
        return False


def row_problems(r):
    """What makes a reference row uncheckable (its file and quantity named), as a list of messages."""
    line = f":{r['ref_line']}" if r.get("ref_line", "") != "" else ""
    where = f"reference/{r['ref_file']}{line} {r['target']}/{r['quantity']}"
    out = []
    if not finite_number(r["published"]):
        out.append(f"{where}: published must be a finite number, not '{r['published']}'")
    if r["tolerance"] and not finite_number(r["tolerance"]):  # empty: 0
        out.append(f"{where}: tolerance must be a finite number, not '{r['tolerance']}'")
    elif float(r["tolerance"] or 0) < 0:
        out.append(f"{where}: tolerance must not be negative")
    if r["target"] != r["ref_file"][:-len(".csv")]:
        out.append(f"{where}: the row's target is not its file's ({r['ref_file']})")
    if r["compare"] not in COMPARES:
        out.append(f"{where}: compare must be one of {', '.join(COMPARES)}, not '{r['compare']}'")
    expect = r["expect"] or "match"
    if expect in ("match", "peer"):
        if r["kind"] or r["own_band"]:
            out.append(f"{where}: kind and own_band belong to discrepancy rows")
        if expect == "peer" and r["quick"].strip().lower() != "no":
            out.append(f"{where}: a peer row is not checked in --quick mode (quick must be no)")
        return out
    if expect != "discrepancy":
        return out + [f"{where}: expect must be match, discrepancy or peer, not '{expect}'"]
    if r["kind"] not in KINDS:
        out.append(f"{where}: a discrepancy row needs kind reading, erratum or open, not '{r['kind']}'")
    if r["kind"] == "reading" and not r["alt_quantity"]:
        out.append(f"{where}: a reading row needs alt_quantity (the reading that reproduces the number)")
    if r["kind"] in ("erratum", "open") and r["alt_quantity"]:
        out.append(f"{where}: an {r['kind']} row has no alternative reading (alt_quantity must be empty)")
    if r["kind"] == "erratum" and not r["analysis_value"]:
        out.append(f"{where}: an erratum row needs analysis_value (the exact value of the paper's equations)")
    try:
        band = parse_band(r["own_band"])
        if band is None and not r["analysis_value"]:
            out.append(f"{where}: a discrepancy row must bound its own value (own_band or analysis_value)")
        if r["analysis_value"]:
            float(r["analysis_value"])
    except ValueError as e:
        out.append(f"{where}: {e}")
    return out


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

    def __init__(self, path, meta, completion=None):
        self.path = path
        self.code_version = meta.get("code_version", "")
        self.given = None if "given" not in meta else set(meta["given"].split())
        self.quick = meta.get("param.quick", "false") == "true"
        # The driver's completion record (timing_<driver>.csv, written last by the driver frame): its header,
        # or None when the run did not complete (it failed, or was interrupted).
        self.completion = completion

    def incomplete(self):
        """Why the run that wrote this file is not known to have completed (None if it is)."""
        record = "timing_" + os.path.basename(self.path)[len("values_"):]
        if self.completion is None:
            return f"{self.path}: its run did not complete (no {record}, which the driver writes last): rerun the target"
        if self.completion.get("code_version", "") != self.code_version:
            return (f"{self.path}: its completion record {record} is of another code version "
                    f"({self.completion.get('code_version', '')}): rerun the target")
        return None


PEER_VALUES = os.path.join("peers", "values_peers.csv")


def load_peer_values(results_dir):
    """({quantity: (value, code version of ours)}, why the peer rows cannot be checked or None) from
    <results>/peers/values_peers.csv; (None, None) when there is no such file (the peer rows are then skipped)."""
    path = os.path.join(results_dir, PEER_VALUES)
    if not os.path.exists(path):
        return None, None
    try:
        df = pd.read_csv(path, comment="#", dtype=str, keep_default_na=False)
        if not {"quantity", "value", "ours_code_version"} <= set(df.columns):
            raise ValueError("no quantity,value,ours_code_version header")
        values = {r["quantity"]: (float(r["value"]) if r["value"] != "" else math.nan, r["ours_code_version"])
                  for _, r in df.iterrows()}
    except (pd.errors.ParserError, pd.errors.EmptyDataError, ValueError) as e:
        return {}, f"{PEER_VALUES} unreadable ({e})"
    return values, None


def check_peer_row(row, peer_values, why_not, checkout=None):
    q, published, tol, compare = row["quantity"], float(row["published"]), float(row["tolerance"] or 0), row["compare"]
    reproduced, version = peer_values.get(q, (None, ""))
    out = {"target": row["target"], "quantity": q, "published": row["published"], "kind": "peer",
           "reproduced": "" if reproduced is None else f"{reproduced:.6g}",
           "tolerance": describe_tolerance(compare, tol), "source": row["source"]}
    if why_not:
        return {**out, "status": "FAIL", "note": f"refused: {why_not}"}
    if reproduced is None:
        return {**out, "status": "FAIL", "note": f"no such value in {PEER_VALUES} (make peers did not run this case)"}
    if not math.isfinite(reproduced):
        return {**out, "status": "FAIL", "note": "the peer's or our value is not finite"}
    ok = within(compare, reproduced, published, tol)
    note = row["why_tolerance"] if ok else f"out of tolerance: our implementation and the peer's differ; {row['why_tolerance']}"
    other = f"; the checkout is {checkout}: make peers --force reruns them" if checkout and version != checkout else ""
    return {**out, "status": "PASS" if ok else "FAIL", "note": note,
            "evidence": f"ours at {version}{other}"}


def load_values(results_dir):
    """{(target, quantity): value}, {(target, quantity): Source} and {target: why some of its values could not
    be read} (a values file cut short by an interrupted run: its rows then FAIL naming it)."""
    values, sources, unreadable = {}, {}, {}
    for path in sorted(glob.glob(os.path.join(results_dir, "*", "values_*.csv"))):
        target = os.path.basename(os.path.dirname(path))
        if target == "peers":  # load_peer_values: no target of its own
            continue
        record = os.path.join(os.path.dirname(path), "timing_" + os.path.basename(path)[len("values_"):])
        source = Source(os.path.relpath(path, results_dir), read_header(path),
                        read_header(record) if os.path.exists(record) else None)
        try:
            df = pd.read_csv(path, comment="#", dtype={"quantity": str, "note": str}, keep_default_na=False)
            if not {"quantity", "value"} <= set(df.columns):
                raise ValueError("no quantity,value header")
        except (pd.errors.ParserError, pd.errors.EmptyDataError, ValueError) as e:
            unreadable.setdefault(target, []).append(f"{source.path} unreadable ({e})" +
                                                     (f"; {source.incomplete()}" if source.incomplete() else ""))
            continue
        for _, r in df.iterrows():
            key = (target, r["quantity"])
            if key in values:
                sys.exit(f"check: {target}/{r['quantity']} written twice ({path})")
            values[key] = float(r["value"])
            sources[key] = source
    # A run interrupted after its first value leaves only the values file's temporary (outputs appear whole or not
    # at all, src/io/atomic_output.hpp): its target's rows then FAIL naming the file and the missing record.
    for part in sorted(glob.glob(os.path.join(results_dir, "*", "values_*.csv.part"))):
        path = part[:-len(".part")]
        if not os.path.exists(path):
            record = "timing_" + os.path.basename(path)[len("values_"):]
            unreadable.setdefault(os.path.basename(os.path.dirname(path)), []).append(
                f"{os.path.relpath(path, results_dir)} is not there, only its .part: its run did not complete "
                f"(no {record}, which the driver writes last): rerun the target")
    return values, sources, unreadable


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


def checkout_version():
    """The code version of this checkout, as the build records it (cmake/version.cmake: git describe)."""
    try:
        out = subprocess.run(["git", "describe", "--always", "--dirty", "--abbrev=12"], cwd=ROOT, capture_output=True,
                             text=True)
        return out.stdout.strip() if out.returncode == 0 and out.stdout.strip() else "unknown (not a git checkout)"
    except OSError:
        return "unknown (not a git checkout)"


def refusal(row, source, allowed, quick_mode, mixed, checkout=None):
    """Why a value must not be checked against this row (None if it may). checkout: the code version the results
    must be of (None: any)."""
    target = row["target"]
    unfinished = source.incomplete()
    if unfinished:
        return unfinished
    if target in mixed:
        return f"values of {target} from different code versions ({', '.join(mixed[target])}): stale results, rerun the target"
    if checkout is not None and source.code_version != checkout:
        return (f"{source.path} is of code version {source.code_version}, the checkout is {checkout}: stale results, "
                f"rerun them (make figures), or check them on purpose with --any-version")
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
    if compare == "abs_le":
        return abs(reproduced) <= published + tol
    raise ValueError(f"unknown compare '{compare}'")


def describe_tolerance(compare, tol):
    return {"abs": f"abs {tol:g}", "rel": f"rel {tol:g}", "le": f"<= published + {tol:g}",
            "ge": f">= published - {tol:g}", "abs_le": f"|x| <= published + {tol:g}"}[compare]


def own_value_bounded(row, reproduced, compare, tol, values):
    """(ok, description) of a discrepancy row's own value against the band its analysis predicts."""
    band = parse_band(row["own_band"])
    if band:
        lo, hi = (band_end(b, row["target"], values) for b in band)
        if lo is None or hi is None:
            return False, f"{row['own_band']} (a quantity of the band was not computed)"
        # A named end must have been computed finite; a number end is finite or deliberately open (empty).
        finite_ends = all(math.isfinite(v) for v, b in zip((lo, hi), band) if b[1])
        ok = lo <= reproduced <= hi and finite_ends and math.isfinite(reproduced)
        named = any(b[1] for b in band)
        text = f"[{lo:.6g}, {hi:.6g}]".replace("-inf", "open").replace("inf", "open")
        return ok, text + (f" = {row['own_band']}" if named else "")
    a = float(row["analysis_value"])
    mode = {"le": "abs", "ge": "abs", "abs_le": "abs"}.get(compare, compare)
    return within(mode, reproduced, a, tol if tol else 1e-9), f"{a:g} ({describe_tolerance(mode, tol)})"


def quantity_refusal(row, name, values, sources, allowed, quick_mode, mixed, checkout):
    """Why a quantity other than the row's own (its reading's alternative, or an end of its band) must not be used:
    the refusals of its own values file, and a value that is not finite; None if it may."""
    key = (row["target"], name)
    if key not in values:
        return None  # reported by the caller as not computed
    why = refusal(row, sources[key], allowed, quick_mode, mixed, checkout)
    if why:
        return f"'{name}' refused: {why}"
    if not math.isfinite(values[key]):
        return f"'{name}' = {values[key]} is not finite"
    return None


def check_row(row, values, sources, allowed, quick_mode, mixed, unreadable=None, checkout=None):
    target, q = row["target"], row["quantity"]
    published, tol, compare = float(row["published"]), float(row["tolerance"] or 0), row["compare"]
    reproduced = values.get((target, q))
    out = {"target": target, "quantity": q, "published": row["published"], "kind": "",
           "reproduced": "" if reproduced is None else f"{reproduced:.6g}",
           "tolerance": describe_tolerance(compare, tol), "source": row["source"]}
    if reproduced is None:
        why = "; ".join((unreadable or {}).get(target, [])) or "driver did not write it"
        return {**out, "status": "FAIL", "note": f"no reproduced value ({why})"}
    why = refusal(row, sources[(target, q)], allowed, quick_mode, mixed, checkout)
    if why:
        return {**out, "status": "FAIL", "note": f"refused: {why}"}
    if not math.isfinite(reproduced):
        return {**out, "status": "FAIL", "note": "reproduced value is not finite"}
    ok = within(compare, reproduced, published, tol)
    expect = row["expect"] or "match"
    if expect == "match":
        note = row["why_tolerance"] if ok else f"out of tolerance; {row['why_tolerance']}"
        return {**out, "status": "PASS" if ok else "FAIL", "note": note}
    if ok:
        return {**out, "status": "PASS",
                "note": "recorded as a discrepancy but now reproduces: review reference/" + row["ref_file"]}
    # The discrepancy must be explained by checks that can themselves fail: our own value inside the band
    # the analysis predicts, and, for a reading, the same number under that reading.
    kind = row["kind"]
    band_names = [b[1] for b in (parse_band(row["own_band"]) or ()) if b[1]]
    for name in band_names + ([row["alt_quantity"]] if kind == "reading" and row["alt_quantity"] else []):
        why = quantity_refusal(row, name, values, sources, allowed, quick_mode, mixed, checkout)
        if why:
            return {**out, "status": "FAIL", "kind": kind, "note": why}
    bounded, band = own_value_bounded(row, reproduced, compare, tol, values)
    if not bounded:
        return {**out, "status": "FAIL", "kind": kind,
                "note": f"reproduced value outside the band its analysis predicts, {band}"}
    if kind == "reading":
        alt = row["alt_quantity"]
        alt_value = values.get((target, alt))
        if alt_value is None:
            return {**out, "status": "FAIL", "kind": kind, "note": f"discrepancy reading '{alt}' not computed"}
        if not within(compare, alt_value, published, tol):
            return {**out, "status": "FAIL", "kind": kind,
                    "note": f"discrepancy reading '{alt}' = {alt_value:.6g} does not reproduce the published value either"}
        return {**out, "status": "DISCREPANCY", "kind": kind,
                "note": row["explanation"], "evidence": f"{alt} = {alt_value:.6g}; own value in {band}"}
    return {**out, "status": "DISCREPANCY", "kind": kind, "note": row["explanation"], "evidence": f"own value in {band}"}


def discrepancy_kinds(table):
    """'x the paper's (a reading or an erratum), y open' for the DISCREPANCY rows of a check table."""
    kinds = table[table.status == "DISCREPANCY"]["kind"].map(KINDS).value_counts()
    return f"{int(kinds.get('paper', 0))} the paper's, {int(kinds.get('open', 0))} open"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--results", default="results")
    ap.add_argument("--reference", default=os.path.dirname(os.path.abspath(__file__)))
    ap.add_argument("--quick", action="store_true", help="skip rows marked quick=no")
    ap.add_argument("--targets", nargs="*", help="only these targets")
    ap.add_argument("--code-version", default=None,
                    help="the code version the results must be of (default: this checkout's, git describe)")
    ap.add_argument("--any-version", action="store_true",
                    help="check results of another code version than the checkout's, on purpose (e.g. an archive)")
    args = ap.parse_args()
    checkout = None if args.any_version else (args.code_version or checkout_version())

    ref = load_reference(args.reference)
    values, sources, unreadable = load_values(args.results)
    arguments, mixed = target_arguments(), mixed_versions(sources)
    peer_values, peers_refused = load_peer_values(args.results)
    rows, skipped_peer = [], []
    for _, r in ref.iterrows():
        if args.targets and r["target"] not in args.targets:
            continue
        if args.quick and r["quick"].strip().lower() == "no":
            continue
        if r["expect"] == "peer":
            if peer_values is None:
                skipped_peer.append(f"{r['target']}/{r['quantity']}")
            else:
                rows.append(check_peer_row(r, peer_values, peers_refused, checkout))
            continue
        rows.append(check_row(r, values, sources, arguments.get(r["target"], set()), args.quick, mixed, unreadable,
                              checkout))
    out_path = os.path.join(args.results, "check.csv")
    os.makedirs(args.results, exist_ok=True)
    with open(out_path + ".part", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=OUT_COLUMNS, restval="")
        w.writeheader()
        w.writerows(rows)

    os.replace(out_path + ".part", out_path)  # whole or not at all (issue 47): a killed run leaves the previous file
    table = pd.DataFrame(rows, columns=OUT_COLUMNS).fillna("")
    with pd.option_context("display.max_rows", None, "display.max_colwidth", 60, "display.width", 250):
        print(table[["target", "quantity", "published", "reproduced", "tolerance", "status"]].to_string(index=False))
    referenced = {(r["target"], r["quantity"]) for r in rows} | {
        (t, a) for t, a in zip(ref["target"], ref["alt_quantity"]) if a}
    unreferenced = sorted(k for k in values if k not in referenced and (not args.targets or k[0] in args.targets))
    counts = table["status"].value_counts()
    n = {s: int(counts.get(s, 0)) for s in ("PASS", "DISCREPANCY", "FAIL")}
    print(f"\ncheck: {len(rows)} rows: {n['PASS']} PASS, {n['DISCREPANCY']} DISCREPANCY "
          f"({discrepancy_kinds(table)}), {n['FAIL']} FAIL"
          f"  ({len(unreferenced)} further reproduced values without a published counterpart) -> {out_path}")
    peer_rows = table[table.kind == "peer"]
    if len(peer_rows) or skipped_peer:
        print(f"check: peer rows (ours against independent codes): {len(peer_rows)} checked"
              f" ({int((peer_rows.status == 'PASS').sum())} PASS), {len(skipped_peer)} skipped"
              + (f" (no {os.path.join(args.results, PEER_VALUES)}: make peers)" if skipped_peer else ""))
    for _, r in table[table.status == "FAIL"].iterrows():
        print(f"  FAIL {r.target}/{r.quantity}: {r.note}")
    return 1 if n["FAIL"] else 0


if __name__ == "__main__":
    sys.exit(main())
