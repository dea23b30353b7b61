#!/usr/bin/env python3
"""The golden suite's Willmore flow cases (cgd, gd, pgd and the kinds that share their step control) with the
predictive step size (-flow_step_model predictive, the default) against the halving rule: iterations, stop
reason, W, rejections, factorisations and linear solves per case (docs/willmore_flow.md "The step size model").

  python3 runs/golden_step_compare.py [--np 1] [--bin bin/confsurf] [--filter REGEX] [--before ref|run]

--before ref reads the 'before' numbers from tests/golden/ref (stored with the halving rule, which reproduces them
bit for bit); --before run runs each case again with -flow_step_model halving. Not a test: it prints a markdown
table and a line per converged case whose W moved by more than its tolerance or which needs more iterations."""
import argparse
import json
import os
import re
import sys
import tempfile
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tests", "golden"))
import run as golden  # noqa: E402

FLOW = re.compile(r"-task flow(\s|$)")
OTHER_KIND = re.compile(r"-flow_type (bs|conformal|newton|alm|fairing|laplacian|trianglefield)")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--np", default="1")
    ap.add_argument("--bin", default=os.path.join(ROOT, "bin", "confsurf"))
    ap.add_argument("--filter", default="")
    ap.add_argument("--before", default="ref", choices=["ref", "run"])
    a = ap.parse_args()
    a.bin = os.path.abspath(a.bin)
    setups, cases = golden.parse_cases()
    tmp = tempfile.mkdtemp(prefix="stepcmp-")
    for s in setups:
        subprocess.run(golden.subst(s, a.bin, tmp), shell=True, cwd=ROOT, check=True)
    keys = ["iterations", "stop_reason", "energy", "rejections", "pc_setups", "linear_solves"]
    print("| case | iterations | stop | W | rejections | factorisations | linear solves |")
    print("|---|---|---|---|---|---|---|")
    notes = []
    for name, ranks, args in cases:
        if a.np not in ranks or not FLOW.search(args) or OTHER_KIND.search(args) or (a.filter and not re.search(a.filter, name)):
            continue
        if a.before == "ref":
            before = json.load(open(os.path.join(ROOT, "tests", "golden", "ref", "%s.np%s.json" % (name, a.np))))
        else:
            before, err = golden.run_case(name, a.np, args + " -flow_step_model halving", a.bin, tmp)
        after, err = golden.run_case(name, a.np, args, a.bin, tmp)
        if after is None or before is None:
            print("| %s | failed: %s |" % (name, err))
            continue
        if before.get("flow_type") in ("newton", "alm", "trianglefield", "bs", "conformal") or "rejections" not in before:
            continue
        cell = lambda k, f="%s": "%s -> %s" % (f % before.get(k), f % after.get(k))
        print("| %s | %s | %s | %s | %s | %s | %s |" % (name, cell("iterations"), cell("stop_reason"), cell("energy", "%.10g"),
                                                       cell("rejections"), cell("pc_setups"), cell("linear_solves")))
        if before.get("converged"):
            tol = 1e-6 * abs(before["energy"])
            if not after.get("converged"):
                notes.append("%s: converged before, not after (%s)" % (name, after.get("stop_reason")))
            elif abs(after["energy"] - before["energy"]) > tol or after["iterations"] > before["iterations"]:
                notes.append("%s: W %.10g -> %.10g, iterations %d -> %d" % (name, before["energy"], after["energy"], before["iterations"], after["iterations"]))
    for n in notes:
        print("NOTE " + n)


if __name__ == "__main__":
    main()
