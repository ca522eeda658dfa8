#!/usr/bin/env python3
"""Assemble the reproduction report: one self-contained HTML page.

For every target declared in experiments/targets.mk, in its order: its description from paper/targets.csv
(choices made where the papers are silent; one row per declared target and no other, else the build
stops), its figures (figures/<target>*.png, embedded; none is fine), the analysis its rows share
(reference/<target>.md, plain paragraphs, written once; none is fine), and the table of published against
reproduced values from results/check.csv, each row's note only what is particular to it. HTML rather than LaTeX: the
report then needs nothing beyond the Python already used for the plots (TeX Live is ~1 GB of packages),
opens in any browser, and is a single file that can be attached to a paper's supplementary material.
"""
import argparse
import base64
import glob
import html
import os
import subprocess
import sys

import pandas as pd

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "experiments"))
import targets as declaration  # noqa: E402  (experiments/targets.py: the reader of experiments/targets.mk)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "reference"))
import check as reference_check  # noqa: E402  (reference/check.py: whose discrepancy each kind is, KINDS)

KIND_LABEL = {"reading": "the paper's: another reading", "erratum": "the paper's: erratum", "open": "open",
              "peer": "ours against an independent code"}
STATUS_COLOUR = {"PASS": "#1a7f37", "DISCREPANCY": "#9a6700", "FAIL": "#cf222e"}


def code_version(root):
    try:
        return subprocess.run(["git", "-C", root, "describe", "--always", "--dirty", "--abbrev=12"],
                              capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def figure_html(path):
    with open(path, "rb") as f:
        data = base64.b64encode(f.read()).decode()
    name = os.path.basename(path)
    return f'<figure><img src="data:image/png;base64,{data}" alt="{name}"><figcaption>{name}</figcaption></figure>'


def table_html(rows):
    head = "".join(f"<th>{c}</th>" for c in ["quantity", "published", "reproduced", "tolerance", "status", "source", "note"])
    body = []
    for _, r in rows.iterrows():
        colour = STATUS_COLOUR.get(r.status, "black")
        label = r.status + (f" ({KIND_LABEL[r.kind]})" if r.get("kind", "") in KIND_LABEL else "")
        status = f'<b style="color:{colour}">{html.escape(label)}</b>'
        if r.get("evidence", ""):  # the numbers a DISCREPANCY or peer verdict rests on (reference/check.py)
            status += f'<br><small>{html.escape(r.evidence)}</small>'
        cells = [html.escape(str(c)) for c in (r.quantity, r.published, r.reproduced, r.tolerance)]
        cells += [status, html.escape(r.source), html.escape(r.note)]
        body.append("<tr>" + "".join(f"<td>{c}</td>" for c in cells) + "</tr>")
    return f"<table><tr>{head}</tr>{''.join(body)}</table>"


def analysis_html(reference, target):
    """The analysis a target's rows share, reference/<target>.md, as plain paragraphs (blank-line separated, escaped;
    no markup is interpreted), or nothing if the target has none."""
    path = os.path.join(reference, f"{target}.md")
    if not os.path.exists(path):
        return ""
    with open(path) as f:
        paragraphs = [" ".join(p.split()) for p in f.read().split("\n\n") if p.strip()]
    return "".join(f"<p>{html.escape(p)}</p>" for p in paragraphs)


def timings_html(path):
    """The run-time table of make figures / make test (tools/timings.py), if the results have one."""
    if not os.path.exists(path):
        return "<p>No run-time table (results/timings.csv) in these results.</p>"
    t = pd.read_csv(path, dtype=str, keep_default_na=False)
    total = sum(float(w) for w in t.wall_s)
    cols = ["target", "driver", "wall_s", "particle_steps", "particle_steps_per_s", "threads"]
    head = "".join(f"<th>{c}</th>" for c in cols)
    body = "".join("<tr>" + "".join(f"<td>{html.escape(str(r[c]))}</td>" for c in cols) + "</tr>" for _, r in t.iterrows())
    return (f"<p>Wall time of every driver of these results, longest first: {total:.0f} s in all "
            f"({total / 60:.1f} min; build, plots and check not included).</p><table><tr>{head}</tr>{body}</table>")


def fmt(x, rel=False):
    """A compare.csv number for the table: 6 significant digits, a relative difference as a signed percentage."""
    try:
        v = float(x)
    except (TypeError, ValueError):
        return str(x)
    if v != v:
        return ""
    return f"{100 * v:+.2f}%" if rel else f"{v:.6g}"


def peers_html(results):
    """Ours beside the independent codes of make peers (results/peers/compare.csv, tools/peers/run_peers.py):
    one table per scene, published | theory | ours | peer with the differences and the speed per force
    evaluation."""
    path = os.path.join(results, "peers", "compare.csv")
    if not os.path.exists(path):
        return ("<p>No results of the independent codes in these results (<code>make peers</code> writes "
                "<code>results/peers/compare.csv</code>; it takes hours and <code>make figures</code> does not run it).</p>")
    t = pd.read_csv(path, comment="#", dtype=str, keep_default_na=False)
    cols = [("case", "case", False), ("quantity", "quantity", False), ("published", "published", False),
            ("theory", "theory", False), ("ours", "ours", False), ("code", "peer code", False), ("variant", "variant", False),
            ("peer", "peer", False), ("peer_over_ours", "peer / ours - 1", True), ("ours_over_theory", "ours / theory - 1", True),
            ("ours_over_peer_per_force_eval", "ours / peer, particle-evaluations per s", False)]
    out = ["<p>Each peer runs our layout with our settings where it accepts them; its trace is measured by our "
           "measurement code (<code>build/bin/peer_&lt;scene&gt; --action measure</code>), and ours is our own driver "
           "at the same resolution. Variants and what differs between the codes: <code>tools/peers/scene_*.py</code>.</p>"]
    for scene, rows in t.groupby("scene", sort=False):
        head = "".join(f"<th>{html.escape(label)}</th>" for _, label, _ in cols)
        body = "".join("<tr>" + "".join(f"<td>{html.escape(fmt(r[c], rel) if c not in ('case', 'quantity', 'code', 'variant') else r[c])}</td>"
                                        for c, _, rel in cols) + "</tr>" for _, r in rows.iterrows())
        out.append(f"<h3>{html.escape(scene)}</h3><table><tr>{head}</tr>{body}</table>")
    return "".join(out)


def studies_html(results):
    """The sensitivity tables of make studies (results/studies/<study>_sensitivity.csv, tools/studies.py): per
    row, its value under each of the paper's unstated choices beside the published number."""
    paths = sorted(glob.glob(os.path.join(results, "studies", "*_sensitivity.csv")))
    if not paths:
        return ("<p>No sensitivity tables in these results (<code>make studies</code> writes "
                "<code>results/studies/&lt;study&gt;_sensitivity.csv</code>; <code>make figures</code> does not run it).</p>")
    out = ["<p>One choice the paper does not state varied at a time, everything else at make figures' settings "
           "(<code>tools/studies.py</code> lists them); a row's value under each, its difference from the published "
           "number, and whether that lies within the row's tolerance.</p>"]
    for path in paths:
        t = pd.read_csv(path, dtype=str, keep_default_na=False)
        variants = list(dict.fromkeys(t.variant))
        choices = dict(zip(t.variant, t.choice))
        head = "<th>row</th><th>kind</th><th>published</th>" + "".join(
            f'<th title="{html.escape(choices[v])}">{html.escape(v)}</th>' for v in variants)
        body = []
        for (target, quantity), rows in t.groupby(["target", "quantity"], sort=False):
            by = {r.variant: r for r in rows.itertuples()}
            first = rows.iloc[0]
            cells = "".join(
                f"<td>{html.escape(by[v].value)} ({html.escape(by[v].difference)}){' *' if by[v].within == 'true' else ''}</td>"
                if v in by else "<td></td>" for v in variants)
            body.append(f"<tr><td>{html.escape(target)} {html.escape(quantity)}</td><td>{html.escape(first.kind)}</td>"
                        f"<td>{html.escape(first.published)}</td>{cells}</tr>")
        name = os.path.basename(path)[: -len("_sensitivity.csv")]
        out.append(f"<h3>{html.escape(name)}</h3><p>* within the row's tolerance. Choices: "
                   + "; ".join(f"<b>{html.escape(v)}</b>: {html.escape(choices[v])}" for v in variants)
                   + f"</p><table><tr>{head}</tr>{''.join(body)}</table>")
    return "".join(out)


def driver_seconds(path):
    """{target: seconds of driver time} from results/timings.csv (a split target's runs, labelled T/<run>, summed into T)."""
    out = {}
    if os.path.exists(path):
        for _, r in pd.read_csv(path, dtype=str, keep_default_na=False).iterrows():
            t = r["target"].split("/")[0]
            out[t] = out.get(t, 0.0) + float(r["wall_s"] or 0)
    return out


def overview_html(targets, check, seconds):
    """The table at the top: every target with its title, its rows by status, and its driver time, each linked to
    its section."""
    head = ("<tr><th>target</th><th>what</th><th>work</th><th>rows</th><th>PASS</th><th>DISCREPANCY (the paper's / "
            "open)</th><th>FAIL</th><th>peer rows</th><th>driver time</th></tr>")
    body = []
    for _, t in targets.iterrows():
        rows = check[check.target == t.target]
        own = rows[rows.get("kind", pd.Series(dtype=str)) != "peer"] if len(rows) else rows
        peer = rows[rows.get("kind", pd.Series(dtype=str)) == "peer"] if len(rows) else rows
        disc = own[own.status == "DISCREPANCY"] if len(own) else own
        paper = int((disc["kind"].map(reference_check.KINDS) == "paper").sum()) if len(disc) else 0
        fail = int((own.status == "FAIL").sum()) if len(own) else 0
        colour = STATUS_COLOUR["FAIL"] if fail else STATUS_COLOUR["DISCREPANCY"] if len(disc) else STATUS_COLOUR["PASS"]
        secs = seconds.get(t.target)
        cells = [f'<a href="#{t.target}"><b style="color:{colour}">{html.escape(t.target)}</b></a>', html.escape(t.title),
                 html.escape(t.work.split(",")[0]), str(len(own)), str(int((own.status == "PASS").sum()) if len(own) else 0),
                 f"{paper} / {len(disc) - paper}", str(fail),
                 f"{int((peer.status == 'PASS').sum())}/{len(peer)} PASS" if len(peer) else "",
                 f"{secs:.0f} s" if secs is not None else ""]
        body.append("<tr>" + "".join(f"<td>{c}</td>" for c in cells) + "</tr>")
    return f"<table>{head}{''.join(body)}</table>"


def report_targets(path):
    """paper/targets.csv's rows in the order of experiments/targets.mk; exits on any mismatch between the two."""
    try:
        declared = declaration.read().names
    except declaration.DeclarationError as e:
        sys.exit(f"build_report: {e}")
    rows = pd.read_csv(path, dtype=str, keep_default_na=False)
    dup = sorted(set(rows.target[rows.target.duplicated()]))
    if dup:
        sys.exit(f"build_report: paper/targets.csv has several rows for {', '.join(dup)}")
    missing = [t for t in declared if t not in set(rows.target)]
    if missing:
        sys.exit(f"build_report: paper/targets.csv has no row for the declared target(s) {', '.join(missing)} "
                 "(experiments/targets.mk)")
    extra = [t for t in rows.target if t not in declared]
    if extra:
        sys.exit(f"build_report: paper/targets.csv has rows for {', '.join(extra)}, not declared in "
                 "experiments/targets.mk")
    return rows.set_index("target", drop=False).loc[declared].reset_index(drop=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--results", default="results")
    ap.add_argument("--figures", default="figures")
    ap.add_argument("--reference", default=os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                                        "reference"),
                    help="the reference folder: its <target>.md files are the analyses the report's sections show")
    ap.add_argument("--out", default="paper/build/index.html")
    args = ap.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

    check_path = os.path.join(args.results, "check.csv")
    if not os.path.exists(check_path):
        sys.exit(f"build_report: {check_path} missing: run make figures (or make check) first")
    check = pd.read_csv(check_path, dtype=str, keep_default_na=False)
    targets = report_targets(os.path.join(root, "paper", "targets.csv"))
    counts = check.status.value_counts()
    kinds = check[check.status == "DISCREPANCY"].get("kind", pd.Series(dtype=str)).map(reference_check.KINDS).value_counts()

    parts = [f"""<!doctype html><html><head><meta charset="utf-8"><title>SPH elastic dynamics: reproduction report</title>
<style>body{{font-family:sans-serif;max-width:1200px;margin:auto;padding:1em;line-height:1.4}}
table{{border-collapse:collapse;font-size:0.85em;margin:0.5em 0}}td,th{{border:1px solid #ccc;padding:3px 6px;vertical-align:top}}
th{{background:#f3f3f3}}figure{{display:inline-block;margin:0.5em}}img{{max-width:100%}}figcaption{{font-size:0.75em;color:#666}}
.summary{{font-size:1.1em}}</style></head><body>
<h1>SPH for elastic solids: reproduction report</h1>
<p>Gray, Monaghan &amp; Swift 2001; Hoover, Hoover &amp; Merritt 2004; Ismail 2009. Code version
<code>{html.escape(code_version(root))}</code>. Every number below was computed by the drivers in
<code>experiments/</code> and compared by <code>reference/check.py</code> with the published values in
<code>reference/</code>. PASS: within the stated tolerance. DISCREPANCY: the published number does not reproduce, and
our own value lies in the band its analysis predicts (checked); of two kinds: <i>the paper's</i>, where another reading of
the same number, computed and checked, reproduces it, or the paper's own closed form gives our value (an erratum), and
<i>open</i>, where no reading we compute reproduces it: our open question, not the paper's error. FAIL: any check of a
row that does not hold.</p>
<p class="summary">{len(check)} checks: {counts.get('PASS', 0)} PASS, {counts.get('DISCREPANCY', 0)} DISCREPANCY,
{counts.get('FAIL', 0)} FAIL; of the discrepancies {kinds.get('paper', 0)} the paper's, {kinds.get('open', 0)} open.</p>"""]
    parts.append("<h2>The targets</h2>" + overview_html(targets, check, driver_seconds(os.path.join(args.results, "timings.csv"))))
    parts.append("<h2>Contents</h2><ul>" + "".join(
        f'<li><a href="#{t.target}">{html.escape(t.target)}: {html.escape(t.title)}</a></li>' for _, t in targets.iterrows())
                 + '<li><a href="#peers">Independent codes</a></li><li><a href="#studies">Unstated choices</a></li>'
                 + '<li><a href="#timings">Run times</a></li></ul>')
    for _, t in targets.iterrows():
        parts.append(f'<h2 id="{t.target}">{html.escape(t.target)}: {html.escape(t.title)}</h2>')
        parts.append(f"<p><i>{html.escape(t.work)}</i></p><p>{html.escape(t.description)}</p>")
        for fig in sorted(glob.glob(os.path.join(args.figures, f"{t.target}.png"))) + \
                sorted(glob.glob(os.path.join(args.figures, f"{t.target}_*.png"))):
            parts.append(figure_html(fig))
        parts.append(analysis_html(args.reference, t.target))
        rows = check[check.target == t.target]
        parts.append(table_html(rows) if len(rows) else "<p>No published numbers are checked for this target.</p>")
    parts.append('<h2 id="peers">Independent codes on our scenes (make peers)</h2>' + peers_html(args.results))
    parts.append('<h2 id="studies">The paper\'s unstated choices (make studies)</h2>' + studies_html(args.results))
    parts.append('<h2 id="timings">Run times</h2>' + timings_html(os.path.join(args.results, "timings.csv")))
    parts.append("</body></html>")
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    with open(args.out + ".part", "w") as f:
        f.write("\n".join(parts))
    os.replace(args.out + ".part", args.out)  # whole or not at all (issue 47): a killed run leaves the previous file
    print(f"build_report: wrote {args.out} ({len(targets)} targets, {len(check)} checks)")


if __name__ == "__main__":
    main()
