#!/usr/bin/env python3
"""reference/check.py fails or refuses what it must: a NaN, a missing values file, a missing row, a parameter
set on the command line that nothing names, a stale code version (mixed in a target, or not the checkout's; a
reading's alternative or a band end too, and one that is not finite), a --quick run checked as a full one,
results that do not record their settings, and a run that did not complete (no completion record); a peer row
(ours against an independent code) out of tolerance, missing, not finite or unreadable; and passes the same values when nothing is wrong (so that each
failure below is the one it names, not a broken fixture). A malformed reference file (a missing column, a
duplicated row, a non-numeric tolerance, an unknown compare mode) stops it, naming file and line.

The fixture is one target's values file, written in the drivers' format (experiments/frame/driver.cpp) into
a temporary results folder, with values that satisfy the target's reference rows (its published numbers:
this tests the checker, not a result) and each defect in turn. Run by ctest.
"""
import csv
import io
import math
import os
import subprocess
import sys
import tempfile
import unittest

import pandas as pd

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CHECK = os.path.join(ROOT, "reference", "check.py")
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(ROOT, "reference"))
import check  # noqa: E402

TARGET = "H-gauss"  # every row a 'match' row, checked in --quick mode too


def reference_rows():
    df = pd.read_csv(os.path.join(ROOT, "reference", TARGET + ".csv"), comment="#", dtype=str,
                     keep_default_na=False, skipinitialspace=True)
    assert (df["expect"].replace("", "match") == "match").all(), "the fixture needs match rows only"
    return list(zip(df["quantity"], df["published"].astype(float)))


def write_values(folder, rows, name="values_fixture.csv", version="abc123", given="", quick=False,
                 completed_as=""):
    """A values file, and the completion record of its run (of code version `completed_as`, by default the
    file's own; None: the run did not complete)."""
    os.makedirs(os.path.join(folder, TARGET), exist_ok=True)
    if completed_as is not None:
        with open(os.path.join(folder, TARGET, "timing_" + name[len("values_"):]), "w") as f:
            f.write(f"# driver = fixture\n# code_version = {completed_as or version}\n"
                    f"target,driver,wall_s,particle_steps,threads\n{TARGET},fixture,1,0,1\n")
    with open(os.path.join(folder, TARGET, name), "w", newline="") as f:
        f.write(f"# driver = fixture\n# target = {TARGET}\n# code_version = {version}\n# date = 2026-01-01T00:00:00Z\n"
                f"# param.quick = {'true' if quick else 'false'}\n")
        if given is not None:
            f.write(f"# given = {given}\n")
        w = csv.writer(f)
        w.writerow(["quantity", "value", "note"])
        for q, v in rows:
            w.writerow([q, repr(v), "fixture"])


def run_check(folder, quick=False, version="abc123"):
    """(exit code, {quantity: (status, note)}) of check.py on the fixture's target, the checkout taken to be of code
    version `version` (the fixture's; None: --any-version)."""
    cmd = [sys.executable, CHECK, "--results", folder, "--targets", TARGET] + (["--quick"] if quick else []) + \
        (["--code-version", version] if version else ["--any-version"])
    out = subprocess.run(cmd, capture_output=True, text=True)
    path = os.path.join(folder, "check.csv")
    table = pd.read_csv(path, dtype=str, keep_default_na=False) if os.path.exists(path) else pd.DataFrame()
    return out.returncode, {r["quantity"]: (r["status"], r["note"]) for _, r in table.iterrows()}


class CheckRefuses(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        self.rows = reference_rows()

    def tearDown(self):
        self.tmp.cleanup()

    def assert_every_row_fails_saying(self, code, st, *parts):
        self.assertEqual(code, 1)
        self.assertEqual(len(st), len(self.rows))  # every row of the target reported, none silently dropped
        for status, note in st.values():
            self.assertEqual(status, "FAIL")
            for part in parts:
                self.assertIn(part, note)

    def test_good_values_pass(self):
        write_values(self.dir, self.rows)
        code, st = run_check(self.dir)
        self.assertEqual(code, 0, st)
        self.assertEqual({s for s, _ in st.values()}, {"PASS"})
        self.assertEqual(set(st), {q for q, _ in self.rows})

    def test_nan_fails(self):
        bad = [(q, math.nan if i == 0 else v) for i, (q, v) in enumerate(self.rows)]
        write_values(self.dir, bad)
        code, st = run_check(self.dir)
        self.assertEqual(code, 1)
        self.assertEqual(st[bad[0][0]][0], "FAIL")
        self.assertIn("not finite", st[bad[0][0]][1])
        self.assertTrue(all(st[q][0] == "PASS" for q, _ in self.rows[1:]))

    def test_missing_file_fails_every_row(self):
        os.makedirs(os.path.join(self.dir, TARGET))
        code, st = run_check(self.dir)
        self.assertEqual(code, 1)
        self.assertEqual({s for s, _ in st.values()}, {"FAIL"})
        self.assertEqual(len(st), len(self.rows))

    def test_missing_row_fails(self):
        write_values(self.dir, self.rows[1:])
        code, st = run_check(self.dir)
        self.assertEqual(code, 1)
        self.assertEqual(st[self.rows[0][0]][0], "FAIL")
        self.assertIn("no reproduced value", st[self.rows[0][0]][1])

    def test_overridden_parameter_is_refused_by_name(self):
        write_values(self.dir, self.rows, given="dp")
        self.assert_every_row_fails_saying(*run_check(self.dir), "refused", "--dp", "values_fixture.csv")

    def test_stale_code_version_is_refused(self):
        half = len(self.rows) // 2
        write_values(self.dir, self.rows[:half], name="values_one.csv", version="new111")
        write_values(self.dir, self.rows[half:], name="values_two.csv", version="old000")
        self.assert_every_row_fails_saying(*run_check(self.dir, version="new111"), "different code versions", "old000")

    def test_results_of_another_version_than_the_checkout_are_refused_unless_asked(self):
        write_values(self.dir, self.rows, version="old000")
        self.assert_every_row_fails_saying(*run_check(self.dir, version="new111"), "old000", "the checkout is new111",
                                           "--any-version")
        code, st = run_check(self.dir, version=None)
        self.assertEqual(code, 0, st)

    def test_quick_run_is_refused_as_full_but_checked_as_quick(self):
        write_values(self.dir, self.rows, given="quick", quick=True)
        self.assert_every_row_fails_saying(*run_check(self.dir), "--quick run")
        code, st = run_check(self.dir, quick=True)
        self.assertEqual(code, 0, st)

    def test_a_run_that_did_not_complete_is_refused(self):
        write_values(self.dir, self.rows, completed_as=None)
        self.assert_every_row_fails_saying(*run_check(self.dir), "did not complete", "values_fixture.csv")
        write_values(self.dir, self.rows, completed_as="old000")  # the record of an earlier run
        self.assert_every_row_fails_saying(*run_check(self.dir), "another code version", "old000")

    def test_results_without_the_given_record_are_refused(self):
        write_values(self.dir, self.rows, given=None)
        self.assert_every_row_fails_saying(*run_check(self.dir), "does not record")

    def test_a_targets_own_arguments_and_a_rows_settings_are_accepted(self):
        self.assertEqual(check.target_arguments()["G-tab2"], {"table"})
        src = check.Source("G-tab2/values.csv", {"code_version": "x", "given": "table"}, {"code_version": "x"})
        self.assertIsNone(check.refusal({"target": "G-tab2"}, src, {"table"}, False, {}))
        src = check.Source("G-tab2/values.csv", {"code_version": "x", "given": "table dp"}, {"code_version": "x"})
        self.assertIn("--dp", check.refusal({"target": "G-tab2"}, src, {"table"}, False, {}))
        self.assertIsNone(check.refusal({"target": "G-tab2", "settings": "dp"}, src, {"table"}, False, {}))


def discrepancy_row(**kw):
    """A reference row as load_reference gives it: published 10 (rel 0.01), our value expected near 12."""
    row = {"target": "T", "quantity": "q", "published": "10", "unit": "", "compare": "rel", "tolerance": "0.01",
           "why_tolerance": "w", "source": "s", "expect": "discrepancy", "alt_quantity": "", "analysis_value": "",
           "explanation": "e", "quick": "", "kind": "open", "own_band": "11..13", "ref_file": "T.csv"}
    row.update(kw)
    return row


def check_one(row, values):
    src = check.Source("T/values.csv", {"code_version": "x", "given": ""}, {"code_version": "x"})
    return check.check_row(row, values, {k: src for k in values}, set(), False, {})


class DiscrepancyContract(unittest.TestCase):
    """A DISCREPANCY row bounds its own value, and a reading reproduces the published number."""

    def test_open_row_in_its_band_is_a_discrepancy_of_its_kind(self):
        out = check_one(discrepancy_row(), {("T", "q"): 12.0})
        self.assertEqual((out["status"], out["kind"]), ("DISCREPANCY", "open"))
        # the note is the reference's explanation alone; the numbers the verdict rests on are the evidence
        self.assertEqual((out["note"], out["evidence"]), ("e", "own value in [11, 13]"))

    def test_own_value_outside_the_band_fails_whatever_the_kind(self):
        for kw in ({}, {"kind": "reading", "alt_quantity": "q_alt"}, {"own_band": "", "analysis_value": "12"}):
            out = check_one(discrepancy_row(**kw), {("T", "q"): 20.0, ("T", "q_alt"): 10.0})
            self.assertEqual(out["status"], "FAIL", kw)
            self.assertIn("outside the band", out["note"])

    def test_a_band_may_name_quantities_of_the_same_run(self):
        row = discrepancy_row(own_band="theory..1.2*theory")
        self.assertEqual(check_one(row, {("T", "q"): 12.0, ("T", "theory"): 11.0})["status"], "DISCREPANCY")
        self.assertEqual(check_one(row, {("T", "q"): 12.0, ("T", "theory"): 9.0})["status"], "FAIL")  # 12 > 10.8
        out = check_one(row, {("T", "q"): 12.0})
        self.assertEqual(out["status"], "FAIL")
        self.assertIn("not computed", out["note"])
        self.assertTrue(any("neither a number" in p for p in check.row_problems(discrepancy_row(own_band="a b..2"))))

    def test_an_open_end_bounds_one_side_and_still_needs_a_finite_value(self):
        row = discrepancy_row(own_band="11..")
        self.assertEqual(check_one(row, {("T", "q"): 1e6})["status"], "DISCREPANCY")
        self.assertEqual(check_one(row, {("T", "q"): 10.5})["status"], "FAIL")  # below the given end
        for bad in (math.inf, math.nan):
            self.assertEqual(check_one(row, {("T", "q"): bad})["status"], "FAIL", bad)
        self.assertEqual(check_one(discrepancy_row(own_band="..13"), {("T", "q"): 12.0})["status"], "DISCREPANCY")
        for text, message in (("..", "bounds nothing"), ("11..inf", "not finite"), ("nan..13", "not finite")):
            problems = check.row_problems(discrepancy_row(own_band=text))
            self.assertTrue(any(message in p for p in problems), (text, problems))

    def test_a_reading_must_reproduce_the_published_number(self):
        row = discrepancy_row(kind="reading", alt_quantity="q_alt")
        out = check_one(row, {("T", "q"): 12.0, ("T", "q_alt"): 10.05})
        self.assertEqual((out["status"], out["note"]), ("DISCREPANCY", "e"))
        self.assertEqual(out["evidence"], "q_alt = 10.05; own value in [11, 13]")
        out = check_one(row, {("T", "q"): 12.0, ("T", "q_alt"): 11.0})
        self.assertEqual(out["status"], "FAIL")
        self.assertIn("does not reproduce", out["note"])
        self.assertEqual(check_one(row, {("T", "q"): 12.0})["status"], "FAIL")  # the reading not computed

    def test_a_reading_or_a_band_end_that_is_not_finite_or_refused_fails(self):
        row = discrepancy_row(kind="reading", alt_quantity="q_alt")
        out = check_one(row, {("T", "q"): 12.0, ("T", "q_alt"): math.nan})
        self.assertEqual(out["status"], "FAIL")
        self.assertIn("'q_alt' = nan is not finite", out["note"])
        out = check_one(discrepancy_row(own_band="theory.."), {("T", "q"): 12.0, ("T", "theory"): math.inf})
        self.assertEqual(out["status"], "FAIL")
        self.assertIn("not finite", out["note"])
        # a reading of another code version than the checkout's is refused as a primary value is
        src = check.Source("T/values.csv", {"code_version": "x", "given": ""}, {"code_version": "x"})
        old = check.Source("T/alt.csv", {"code_version": "y", "given": ""}, {"code_version": "y"})
        out = check.check_row(row, {("T", "q"): 12.0, ("T", "q_alt"): 10.0}, {("T", "q"): src, ("T", "q_alt"): old},
                              set(), False, {}, checkout="x")
        self.assertEqual(out["status"], "FAIL")
        self.assertIn("'q_alt' refused", out["note"])

    def test_a_nan_fails_a_discrepancy_row_even_when_its_reading_holds(self):
        row = discrepancy_row(kind="reading", alt_quantity="q_alt")
        self.assertEqual(check_one(row, {("T", "q"): math.nan, ("T", "q_alt"): 10.0})["status"], "FAIL")

    def test_abs_le_bounds_the_size_of_a_signed_error(self):
        self.assertTrue(check.within("abs_le", -0.012, 0.01, 0.005))
        self.assertFalse(check.within("abs_le", -0.02, 0.01, 0.005))
        self.assertTrue(check.within("le", -0.02, 0.01, 0.005))  # why a signed error needs abs_le

    def test_malformed_discrepancy_rows_are_named(self):
        cases = {"kind": ("", "needs kind"), "alt_quantity": ("x", "no alternative"),
                 "own_band": ("13..11", "lo <= hi")}
        for col, (value, message) in cases.items():
            problems = check.row_problems(discrepancy_row(**{col: value}))
            self.assertTrue(any(message in p and "reference/T.csv T/q" in p for p in problems), (col, problems))
        self.assertTrue(any("must bound its own value" in p for p in check.row_problems(discrepancy_row(own_band=""))))
        self.assertTrue(any("needs alt_quantity" in p for p in check.row_problems(discrepancy_row(kind="reading"))))
        self.assertEqual(check.row_problems(discrepancy_row()), [])


def peer_row(**kw):
    """A reference row of expect = peer: the peer's value over ours - 1 within 0.005 of 0."""
    row = {"target": "T", "quantity": "pysph_v_over_ours_T_sph_x_dp0.1", "published": "0", "unit": "1",
           "compare": "abs_le", "tolerance": "0.005", "why_tolerance": "w", "source": "s", "expect": "peer",
           "alt_quantity": "", "analysis_value": "", "explanation": "", "quick": "no", "kind": "", "own_band": "",
           "ref_file": "T.csv"}
    row.update(kw)
    return row


def write_peer_values(folder, rows, version="abc123"):
    os.makedirs(os.path.join(folder, "peers"), exist_ok=True)
    with open(os.path.join(folder, "peers", "values_peers.csv"), "w", newline="") as f:
        f.write("# written_by = fixture\n")
        w = csv.writer(f)
        w.writerow(["quantity", "value", "ours_code_version", "note"])
        for q, v in rows:
            w.writerow([q, repr(v), version, "fixture"])


class PeerRows(unittest.TestCase):
    """A peer row (ours against an independent code, make peers) is checked against results/peers/values_peers.csv
    when it is present: within its tolerance PASS, out of it, missing or not finite FAIL, an unreadable file FAILs
    every row; without the file it is skipped, never counted as a pass; the note names the code version of ours."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        self.q = peer_row()["quantity"]

    def tearDown(self):
        self.tmp.cleanup()

    def check(self):
        values, why = check.load_peer_values(self.dir)
        return values, check.check_peer_row(peer_row(), values, why) if values is not None else None

    def test_absent_peer_results_skip_the_row(self):
        self.assertEqual(self.check(), (None, None))

    def test_within_and_out_of_tolerance(self):
        for value, status in ((0.004, "PASS"), (-0.0049, "PASS"), (0.006, "FAIL"), (-0.02, "FAIL")):
            write_peer_values(self.dir, [(self.q, value)])
            self.assertEqual(self.check()[1]["status"], status, value)

    def test_missing_nonfinite_and_unreadable_fail(self):
        write_peer_values(self.dir, [("other", 0.0)])
        self.assertIn("no such value", self.check()[1]["note"])
        write_peer_values(self.dir, [(self.q, math.nan)])
        self.assertIn("not finite", self.check()[1]["note"])
        write_peer_values(self.dir, [(self.q, 0.0)], version="def456")
        out = self.check()[1]
        self.assertEqual(out["status"], "PASS")
        self.assertIn("ours at def456", out["evidence"])
        with open(os.path.join(self.dir, "peers", "values_peers.csv"), "w") as f:
            f.write("quantity,value\n" + self.q + ",0\n")  # an older file without the version column
        out = self.check()[1]
        self.assertEqual(out["status"], "FAIL")
        self.assertIn("unreadable", out["note"])

    def test_a_peer_row_checked_in_quick_mode_is_malformed(self):
        self.assertEqual(check.row_problems(peer_row()), [])
        self.assertTrue(any("quick must be no" in p for p in check.row_problems(peer_row(quick=""))))
        self.assertTrue(any("belong to discrepancy rows" in p for p in check.row_problems(peer_row(kind="open"))))


def csv_line(fields):
    out = io.StringIO()
    csv.writer(out, lineterminator="\n").writerow(fields)
    return out.getvalue()


class ReferenceFilesRefused(unittest.TestCase):
    """A malformed reference file stops the check, naming the file and the line: a missing column, a
    duplicated row, a tolerance that is not a number, an unknown compare mode."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.ref = self.tmp.name
        for name in os.listdir(os.path.join(ROOT, "reference")):
            if name.endswith(".csv"):
                with open(os.path.join(ROOT, "reference", name)) as f, open(os.path.join(self.ref, name), "w") as g:
                    g.write(f.read())
        with open(os.path.join(self.ref, TARGET + ".csv")) as f:
            self.lines = f.read().splitlines(True)
        self.header = next(i for i, l in enumerate(self.lines) if l.strip() and not l.startswith("#"))
        self.first = next(i for i, l in enumerate(self.lines) if i > self.header and l.strip() and not l.startswith("#"))

    def tearDown(self):
        self.tmp.cleanup()

    def refusal(self, lines):
        with open(os.path.join(self.ref, TARGET + ".csv"), "w") as f:
            f.writelines(lines)
        with self.assertRaises(SystemExit) as e:
            check.load_reference(self.ref)
        return str(e.exception.code)

    def edit_first_row(self, column, value):
        cols = next(csv.reader([self.lines[self.header]]))
        row = next(csv.reader([self.lines[self.first]]))
        row[cols.index(column)] = value
        lines = list(self.lines)
        lines[self.first] = csv_line(row)
        return lines

    def test_the_unchanged_copy_loads(self):
        self.assertGreater(len(check.load_reference(self.ref)), 0)

    def test_a_missing_column(self):
        cols = next(csv.reader([self.lines[self.header]]))
        i = cols.index("compare")
        lines = [csv_line([c for j, c in enumerate(next(csv.reader([l]))) if j != i])
                 if k >= self.header and l.strip() and not l.startswith("#") else l for k, l in enumerate(self.lines)]
        msg = self.refusal(lines)
        self.assertIn(f"{TARGET}.csv:{self.header + 1}", msg)
        self.assertIn("compare", msg)

    def test_a_duplicated_row(self):
        lines = self.lines + [self.lines[self.first]]
        msg = self.refusal(lines)
        self.assertIn("duplicate", msg)
        self.assertIn(f"{TARGET}.csv:{self.first + 1} ", msg)
        self.assertIn(f"{TARGET}.csv:{len(lines)} ", msg)

    def test_a_tolerance_that_is_not_a_number(self):
        msg = self.refusal(self.edit_first_row("tolerance", "0.0x1"))
        self.assertIn(f"{TARGET}.csv:{self.first + 1} ", msg)
        self.assertIn("tolerance must be a finite number", msg)

    def test_an_unknown_compare_mode(self):
        msg = self.refusal(self.edit_first_row("compare", "relative"))
        self.assertIn(f"{TARGET}.csv:{self.first + 1} ", msg)
        self.assertIn("compare must be one of", msg)


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
