#!/usr/bin/env python3
"""Run every options file whose header states measured figures and compare the run with its header (issue 39), so
that the headers cannot drift from the code. `make check-docs` runs it (CI: .ci/run, after `make test`).

The figures are stated in a machine-readable header line (the prose above it says the same in words):
  # expect: iterations=34 converged=true el_residual<1e-8 energy=23.1186529 q_mean=1.054±0.002
  # expect-slow: ...      the same, for a file too slow for CI (more than ~1 min): run only with --slow
  # check-args: ARGS      appended after -options_file (a cheaper variant: only when the expect line is for it)
  # check-setup: CMD      a shell command run first (from the repository root), e.g. making an input mesh
Keys are the keys of the run's -summary JSON. A comparison is KEY=VALUE (an integer, true/false or a word: equal;
a decimal number: equal to the digits written, i.e. within half a unit of its last digit: energy=12.50680 accepts
[12.506795, 12.506805]), KEY=VALUE±TOL (absolute) or KEY=VALUE±P% (relative), KEY<VALUE, KEY>VALUE, KEY<=VALUE,
KEY>=VALUE; KEY# is the length of a list (eigenvalues#=444). In ARGS and CMD, @T is the run's temporary
directory. The options file's own outputs (-o, -summary, -history_csv, -viewer_dir, the spin prefixes) are
redirected into @T. A run that fails (non-zero exit: bad or unused options are refused by the driver) fails its file.

  python3 runs/check_options_headers.py [--slow] [--np N] [--bin bin/confsurf] [--timeout S] [FILE ...]
  python3 runs/check_options_headers.py --measure FILE ...   (run, print the summary; no comparison)
First, without running anything long: every option named in a command line quoted in a header (`#   bin/confsurf
-options_file ... -bs_scheme tao`) must be one that `-help` lists for some task and flow type (PETSc's solver
options excepted); a file with an unknown name counts as failed (--names-only does only this).
Prints one line per comparison and per file, and `N passed, N failed, N skipped (slow)`; exit status 1 if any
failed."""
import argparse
import glob
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUTPUTS = ("-o", "-summary", "-history_csv", "-viewer_dir", "-spectrum_reconstruct_prefix", "-spin_interpolate_prefix")
TOKEN = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*#?)(<=|>=|=|<|>)(.+)$")


def header(path):
    """The expect tokens, whether slow, the extra arguments and the setup commands of an options file."""
    exp, slow, args, setup = [], False, [], []
    for line in open(path):
        if not line.startswith("#"):
            continue
        m = re.match(r"#\s*(expect|expect-slow|check-args|check-setup):\s*(.*)$", line.rstrip("\n"))
        if not m:
            continue
        kind, rest = m.group(1), m.group(2).strip()
        if kind in ("expect", "expect-slow"):
            exp += rest.split()
            slow = slow or kind == "expect-slow"
        elif kind == "check-args":
            args += rest.split()
        else:
            setup.append(rest)
    return exp, slow, args, setup


def parse_number(s):
    try:
        return float(s)
    except ValueError:
        return None


def half_unit(lit):
    """Half a unit in the last written digit of a decimal literal (1.054 -> 5e-4, 4.3e-9 -> 5e-11, 34 -> 0.5)."""
    m = re.match(r"^[+-]?(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d+))?$", lit)
    if not m:
        return 0.0
    decimals = len(m.group(2) or "")
    exp = int(m.group(3) or 0)
    return 0.5 * 10.0 ** (exp - decimals)


def check(tok, summary):
    """(ok, message) of one comparison against the summary."""
    m = TOKEN.match(tok)
    if not m:
        return False, "cannot parse %r" % tok
    key, op, val = m.groups()
    if key.rstrip("#") not in summary:
        return False, "%s: not in the summary" % key
    got = summary[key.rstrip("#")]
    if key.endswith("#"):  # the length of a list (eigenvalues#=444)
        if not isinstance(got, list):
            return False, "%s: %s is not a list" % (key, key.rstrip("#"))
        got = len(got)
    if op == "=":
        if isinstance(got, bool) or val in ("true", "false"):
            ok = str(got).lower() == val.lower()
            return ok, "%s = %s (header %s)" % (key, str(got).lower(), val)
        if "±" in val:
            v, tol = val.split("±")
            ref = float(v)
            t = abs(ref) * float(tol[:-1]) / 100 if tol.endswith("%") else float(tol)
        else:
            ref = parse_number(val)
            if ref is None:
                ok = str(got) == val
                return ok, "%s = %s (header %s)" % (key, got, val)
            t = half_unit(val)
            if isinstance(got, int) and re.match(r"^[+-]?\d+$", val):
                t = 0
        if not isinstance(got, (int, float)):
            return False, "%s = %.60s is not a number (header %s)" % (key, repr(got), val)
        ok = abs(got - ref) <= t * (1 + 1e-12)
        return ok, "%s = %.10g (header %s)" % (key, got, val)
    ref = float(val)
    if not isinstance(got, (int, float)) or isinstance(got, bool):
        return False, "%s = %.60s is not a number (header %s%s)" % (key, repr(got), op, val)
    ok = {"<": got < ref, ">": got > ref, "<=": got <= ref, ">=": got >= ref}[op]
    return ok, "%s = %.6g (header %s%s)" % (key, got, op, val)


def command(path, args, tmp, binary, np):
    """The run of an options file with its outputs redirected into tmp and its summary in tmp/summary.json."""
    given = set()
    for line in open(path):
        if line.startswith("#"):
            continue
        for tok in line.split()[:1]:
            given.add(tok)
    cmd = [binary, "-options_file", os.path.relpath(path, ROOT)] + [a.replace("@T", tmp) for a in args]
    for opt in OUTPUTS:
        if opt in given and opt != "-summary":
            name = {"-o": "out.obj", "-history_csv": "history.csv"}.get(opt, opt.lstrip("-"))
            cmd += [opt, os.path.join(tmp, name)]
    cmd += ["-summary", os.path.join(tmp, "summary.json")]
    if np > 1:
        cmd = ["mpirun", "-n", str(np), "--oversubscribe"] + cmd
    return cmd


def run_file(path, a):
    exp, slow, args, setup = header(path)
    name = os.path.basename(path)
    if not exp and not a.measure:
        return None
    if slow and not a.slow and not a.measure:
        print("skip %-40s (expect-slow; --slow runs it)" % name)
        return "skip"
    tmp = tempfile.mkdtemp(prefix="cs-headers-")
    # the golden suite's kernels (docs/reproducibility.md): the headers' numbers are those of any AVX2+ machine
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    env.setdefault("OPENBLAS_CORETYPE", "Haswell")
    try:
        for s in setup:
            r = subprocess.run(s.replace("@T", tmp), shell=True, cwd=ROOT, env=env, capture_output=True, text=True)
            if r.returncode:
                print("FAIL %-40s setup failed: %s\n%s" % (name, s, (r.stdout + r.stderr)[-600:]))
                return False
        cmd = command(path, args, tmp, a.bin, a.np)
        t0 = time.time()
        try:
            r = subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True, timeout=a.timeout)
        except subprocess.TimeoutExpired:
            print("FAIL %-40s timed out after %g s" % (name, a.timeout))
            return False
        dt = time.time() - t0
        if r.returncode:
            print("FAIL %-40s exit %d (%.1f s): %s" % (name, r.returncode, dt, " ".join(cmd)))
            print("\n".join("     " + l for l in (r.stdout + r.stderr).strip().splitlines()[-6:]))
            return False
        try:
            summary = json.load(open(os.path.join(tmp, "summary.json")))
        except (OSError, ValueError) as e:
            print("FAIL %-40s no summary (%s)" % (name, e))
            return False
        if a.save:
            os.makedirs(a.save, exist_ok=True)
            shutil.copy(os.path.join(tmp, "summary.json"), os.path.join(a.save, name.replace(".opts", ".json")))
        if a.measure:
            keys = ("iterations", "converged", "stop_reason", "energy", "willmore", "el_residual", "rejections",
                    "ksp_iterations", "q_mean", "q_max", "pinch_edges", "pinch_vertices", "area", "volume")
            print("MEAS %-40s %.1f s %s" % (name, dt, json.dumps({k: summary[k] for k in keys if k in summary})))
            return True
        bad = 0
        for tok in exp:
            ok, msg = check(tok, summary)
            bad += not ok
            print("  %s %s" % ("ok " if ok else "BAD", msg))
        print("%s %-40s %.1f s%s" % ("PASS" if not bad else "FAIL", name, dt, " (slow)" if slow else ""))
        return not bad
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


TASKS = ("info", "spin", "spectrum", "curveflow")
FLOWS = ("cgd", "pgd", "gd", "newton", "alm", "trianglefield", "emcf", "cmcf", "bs", "conformal")
# PETSc's own options and its solvers' (read lazily or by PETSc itself, not listed by -help of the tasks)
PETSC_NAMES = re.compile(r"^-(n|np|options_file|help|log_view.*|malloc_.*|.*_(ksp|pc|eps|st|mat|snes|tao)_.*)$")


def option_names(binary):
    """Every option name that -help lists for some task and flow type."""
    names = set()
    runs = [["-task", t] for t in TASKS] + [["-task", "flow", "-flow_type", f] for f in FLOWS]
    for r in runs:
        out = subprocess.run([binary] + r + ["-help"], cwd=ROOT, capture_output=True, text=True).stdout
        names |= set(re.findall(r"^\s*(-[A-Za-z][A-Za-z0-9_]*)", out, re.M))
    return names


def check_names(files, binary):
    """The option names of the command lines quoted in the headers (# ... bin/confsurf ...) exist: a renamed option
    leaves no stale command in a header. Returns the number of files with an unknown name."""
    known, bad = option_names(binary), 0
    for f in files:
        unknown = []
        for line in open(f):
            if line.startswith("#") and "bin/confsurf" in line:
                cmd = line.split("bin/confsurf", 1)[1]
                unknown += [t for t in re.findall(r"(?<!\S)(-[A-Za-z][A-Za-z0-9_]*)", cmd)
                            if t not in known and not PETSC_NAMES.match(t)]
        if unknown:
            bad += 1
            names = " ".join(sorted(set(unknown)))
            print("FAIL %-40s header command names unknown options: %s" % (os.path.basename(f), names))
    print("header option names: %d of %d files with an unknown name" % (bad, len(files)))
    return bad


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("files", nargs="*")
    ap.add_argument("--slow", action="store_true", help="also the files marked expect-slow")
    ap.add_argument("--measure", action="store_true", help="run and print the summary, compare nothing")
    ap.add_argument("--save", metavar="DIR", help="keep each run's summary as DIR/NAME.json")
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--bin", default=os.path.join(ROOT, "bin", "confsurf"))
    ap.add_argument("--timeout", type=float, default=1800)
    ap.add_argument("--names-only", action="store_true", help="only the option names of the headers' commands")
    a = ap.parse_args()
    files = [os.path.abspath(f) for f in a.files] or sorted(glob.glob(os.path.join(ROOT, "options", "*.opts")))
    t0 = time.time()
    named = 0 if a.measure else check_names(files, a.bin)
    res = [] if a.names_only else [run_file(f, a) for f in files]
    passed, failed, skipped = res.count(True), res.count(False) + named, res.count("skip")
    print("%d passed, %d failed, %d skipped (slow) in %.0f s" % (passed, failed, skipped, time.time() - t0))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
