#!/usr/bin/env python3
"""When would a stationarity rule stop a run? (issue 35: the fat-class drift, docs/real_meshes.md "Issue 35").
Reads flow histories (-history_csv: it, energy, el_residual, ...) and, for a window of w iterations, reports per
history the first iteration k at which
   (a) max over the window of |W_j - W_{j-1}| / |W_j|  <  WTOL          (W stationary), and
   (b) EL_k >= RISE * min_{j <= k} EL_j                                (the residual has turned and risen)
hold together, and the values it sees: the largest relative W change per iteration in the window, EL_k against the
run's smallest EL so far. (b) alone separates the drift (EL rises steadily after its minimum) from a converging
run (EL falls to -flow_rtol); (a) keeps a run that is still making progress (a squeeze: W falls fast) running.
  usage: runs/stationary_rule.py [-w 50] [-wtol 1e-6] [-rise 1.5] H1.csv [H2.csv ...]"""
import argparse
import csv


def first_stop(path, w, wtol, rise):
    rows = list(csv.DictReader(open(path)))
    W = [float(r["energy"]) for r in rows]
    EL = [float(r["el_residual"]) for r in rows]
    it = [int(r["it"]) for r in rows]
    elmin, kmin = EL[0], 0
    for k in range(1, len(rows)):
        if EL[k] < elmin:
            elmin, kmin = EL[k], k
        if k < w:
            continue
        dw = max(abs(W[j] - W[j - 1]) / abs(W[j]) for j in range(k - w + 1, k + 1))
        if dw < wtol and EL[k] >= rise * elmin:
            return "stops at %d (EL %.2e = %.1f x the smallest %.2e at %d; largest rel. dW/it in the window %.1e; W %.8f)" % (
                it[k], EL[k], EL[k] / elmin, elmin, it[kmin], dw, W[k])
    k = len(rows) - 1
    dw = max(abs(W[j] - W[j - 1]) / abs(W[j]) for j in range(max(1, k - w + 1), k + 1)) if k else 0
    return "never (last it. %d: EL %.2e, smallest %.2e at %d; largest rel. dW/it in the last window %.1e)" % (
        it[k], EL[k], elmin, it[kmin], dw)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("-w", type=int, default=50)
    ap.add_argument("-wtol", type=float, default=1e-6)
    ap.add_argument("-rise", type=float, default=1.5)
    ap.add_argument("csv", nargs="+")
    a = ap.parse_args()
    for p in a.csv:
        print("%s: %s" % (p, first_stop(p, a.w, a.wtol, a.rise)))


if __name__ == "__main__":
    main()
