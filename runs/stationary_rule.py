#!/usr/bin/env python3
"""When would the drift rule stop a run? (issue 35: the fat-class drift, docs/real_meshes.md "Issue 35";
docs/willmore_flow.md "Drift"). Replays willmore_stop.c CSWFCheckDrift on flow histories (-history_csv: it, energy,
el_residual_scaled, the violations) and reports per history the first iteration k at which
   (a) max over the last w steps of |W_j - W_{j-1}| / |W_j|  <=  WTOL              (W stationary),
   (b) EL_j >= RISE * min_{1 <= i <= j} EL_i for each of the last m steps j <= k   (a sustained rise: m = -steps),
       and EL_k >= EL at the first of these risen steps                        (still rising, not a spike decaying),
   (c) the violation max(conformal, constraint) < CTOL (-ctol 0: not tested, as the offline rule of issue 35)
hold together, and the values it sees: the largest relative W change per iteration in the window, EL_k against the
run's smallest EL (the input, iteration 0, excluded as in the code). (b) with m = 1 is the rule before the spike fix
(one risen residual was enough: a single spike of a converging run stopped it). (b) separates the drift (EL rises
steadily after its minimum) from a converging run (EL falls to -flow_rtol); (a) keeps a run that is still making
progress (a squeeze: W falls fast) running. -el absolute replays on el_residual (the tables of issue 35).
  usage: runs/stationary_rule.py [-w 50] [-wtol 2e-7] [-rise 1.5] [-steps 10] [-ctol 0] [-el scaled] H1.csv ..."""
import argparse
import csv


def first_stop(path, w, wtol, rise, steps, ctol, col):
    rows = list(csv.DictReader(open(path)))
    W = [float(r["energy"]) for r in rows]
    EL = [float(r[col]) for r in rows]
    viol = [max(float(r.get("conformal_violation") or 0), float(r.get("constraint_violation") or 0)) for r in rows]
    it = [int(r["it"]) for r in rows]
    elmin, kmin, risen, longest, el0 = float("inf"), 0, 0, 0, 0
    for k in range(1, len(rows)):
        if EL[k] < elmin:
            elmin, kmin = EL[k], k
        if EL[k] >= rise * elmin:
            el0 = EL[k] if risen == 0 else el0
            risen += 1
        else:
            risen = 0
        longest = max(longest, risen)
        if k < w or risen < steps or EL[k] < el0 or (ctol > 0 and not viol[k] < ctol):
            continue
        dw = max(abs(W[j] - W[j - 1]) / abs(W[j]) for j in range(k - w + 1, k + 1))
        if dw <= wtol:
            return "stops at %d (EL %.2e = %.2f x the smallest %.2e at %d, risen for %d steps from %.2e; largest rel. dW/it in the window %.1e; W %.10f)" % (
                it[k], EL[k], EL[k] / elmin, elmin, it[kmin], risen, el0, dw, W[k])
    k = len(rows) - 1
    dw = max(abs(W[j] - W[j - 1]) / abs(W[j]) for j in range(max(1, k - w + 1), k + 1)) if k else 0
    return "never (last it. %d: EL %.2e, smallest %.2e at %d; longest rise above %g x the smallest %d steps; largest rel. dW/it in the last window %.1e)" % (
        it[k], EL[k], elmin, it[kmin], rise, longest, dw)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("-w", type=int, default=50)
    ap.add_argument("-wtol", type=float, default=2e-7)
    ap.add_argument("-rise", type=float, default=1.5)
    ap.add_argument("-steps", type=int, default=10)
    ap.add_argument("-ctol", type=float, default=0)
    ap.add_argument("-el", choices=["scaled", "absolute"], default="scaled")
    ap.add_argument("csv", nargs="+")
    a = ap.parse_args()
    col = "el_residual_scaled" if a.el == "scaled" else "el_residual"
    for p in a.csv:
        print("%s: %s" % (p, first_stop(p, a.w, a.wtol, a.rise, a.steps, a.ctol, col)))


if __name__ == "__main__":
    main()
