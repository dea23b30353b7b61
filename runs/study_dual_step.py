#!/usr/bin/env python3
"""Table and plot of runs/study_dual_step.sh: usage study_dual_step.py OUTDIR ITS NP "INPUTS" "RULES".
Per input and rule: W at ITS iterations (from the history; the last row if the run stopped before), the end of the
run (iterations, stop reason, W, scaled EL residual, violation), the work (rejections, linear solves, KSP iterations)
and the wall seconds (under load). Under each input the ranking at equal iterations of the runs that hold the class
there (conformal violation < 1e-5). The plot, one column per input: W against iteration, and W relative to PGD's at the
same iteration (the class change, which PGD cannot do: relative to r1e3, the old default)."""
import csv, datetime, json, os, subprocess, sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

HOLD = 1e-5


def history(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def at(h, it):
    rows = [r for r in h if r["it"] <= it]
    return rows[-1] if rows else None


def load(out, name):
    try:
        return json.load(open(os.path.join(out, name + ".json"))), history(os.path.join(out, name + ".csv"))
    except (OSError, ValueError):
        return None, None


def main():
    out, its, nproc, inputs, rules = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4].split(), sys.argv[5].split()
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    print("# CGD's dual step t_mu against PGD (issue 39, soliman2021 Fig. 7), %s UTC, commit %s, NP=%s" %
          (datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M"), commit, nproc))
    print("\nW@it, viol@it: W and the conformal violation after ITS = %d iterations (equal iterations; fewer where a run "
          "stopped earlier at the resolution guard: the ranking line says where), then the end of the run (to the EL "
          "tolerance or the input's iteration cap). Seconds: wall time under load on the shared machine.\n" % its)
    fig, axes = plt.subplots(2, len(inputs), figsize=(3.6 * len(inputs), 6.4), squeeze=False)
    for ax, inp in zip(axes[0], inputs):
        print("## %s\n" % inp)
        print("| rule | W@it | viol@it | iterations | stop | W end | EL scaled end | violation end | rejections | "
              "linear solves | KSP its | seconds |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|")
        runs, ranked = [], []
        loaded = {r: load(out, "%s_%s" % (inp, r)) for r in rules}
        # equal iterations: ITS, or fewer when a run stopped before (the resolution guard), so that all compare at one
        # iteration; a converged run stays at its last state
        eq = min([its] + [int(h[-1]["it"]) for s, h in loaded.values() if h and s["stop_reason"] not in
                          ("converged", "stationary")])
        for r in rules:
            s, h = loaded[r]
            if s is None or not h:
                print("| %s | (no run) |||||||||||" % r)
                continue
            a = at(h, eq)
            runs.append((r, h))
            print("| %s | %.4f | %.1e | %d | %s | %.4f | %.2e | %.1e | %d | %d | %d | %.1f |" % (
                r, a["energy"], a["conformal_violation"], s["iterations"], s["stop_reason"], s["energy"],
                s["el_residual_scaled"], s["conformal_violation"], s["rejections"], s["linear_solves"],
                s["ksp_iterations"], s["seconds"]))
            if a["conformal_violation"] < HOLD:
                ranked.append((a["energy"], r))
        print("\nEqual iterations (%d%s), holding the class (< %g): %s\n" %
              (eq, "" if eq == its else ", a run stopped there", HOLD, " < ".join("%s %.4f" % (r, w) for w, r in sorted(ranked))))
        if not runs:
            continue
        ref = dict(runs).get("pgd") or dict(runs).get("r1e3")
        refname = "pgd" if "pgd" in dict(runs) else "r1e3"
        lo, hi = [], []
        for i, (r, h) in enumerate(runs):
            style = dict(label=r, color=plt.cm.tab10(i % 10), lw=2.0 if r in ("pgd", "r1e5") else 1.2,
                         ls="--" if r == "pgd" else "-")
            ax.plot([row["it"] for row in h], [row["energy"] for row in h], **style)
            if r != "paper":
                lo.append(min(row["energy"] for row in h))
                hi.append(at(h, 3)["energy"])
            # a reference that stopped converged stays at its last state
            n = len(h) if loaded[refname][0]["stop_reason"] in ("converged", "stationary") else min(len(h), len(ref))
            rel = [(h[j]["energy"] - ref[min(j, len(ref) - 1)]["energy"]) / ref[min(j, len(ref) - 1)]["energy"]
                   for j in range(n)]
            ax2 = axes[1][list(inputs).index(inp)]
            ax2.plot(range(n), rel, **style)
        ax.set_ylim(min(lo) - 0.02 * (max(hi) - min(lo)), max(hi))
        ax.axvline(eq, color="0.6", lw=0.8, ls=":")
        ax.set_title("%s: W" % inp, fontsize=10)
        ax.ticklabel_format(axis="y", useOffset=False)
        ax.grid(alpha=0.3)
        ax2.set_yscale("symlog", linthresh=1e-4)
        ax2.axvline(eq, color="0.6", lw=0.8, ls=":")
        ax2.axhline(0, color="k", lw=0.6)
        ax2.set_title("%s: (W - W_%s) / W_%s" % (inp, refname, refname), fontsize=9)
        ax2.set_xlabel("iteration")
        ax2.grid(alpha=0.3)
    axes[0][0].set_ylabel("W")
    axes[1][0].set_ylabel("relative to PGD (target: r1e3)")
    axes[0][0].legend(fontsize=7)
    fig.suptitle("CGD's dual step t_mu against PGD: W per iteration and relative to PGD (below zero: CGD lower; dotted: the equal-iteration point)", fontsize=11)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "dual_step.png"), dpi=90)


if __name__ == "__main__":
    main()
