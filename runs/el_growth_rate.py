#!/usr/bin/env python3
"""The growth rate of the EL residual along a flow (issue 35, docs/real_meshes.md "Issue 35" section 4): the
least-squares slope of log EL against the iteration over the last two thirds of a -history_csv, with EL and W at
both ends and the final vertex-area spread. Positive: the run moves away from a critical point (a drift, or a
mode leaving a saddle); negative: it converges at that rate.
  usage: runs/el_growth_rate.py H1.csv [H2.csv ...]"""
import csv
import math
import sys


def main():
    for p in sys.argv[1:]:
        r = list(csv.DictReader(open(p)))
        if len(r) < 60:
            print("%s: %d rows, too short" % (p, len(r)))
            continue
        it = [int(x["it"]) for x in r]
        el = [float(x["el_residual"]) for x in r]
        a, b = len(r) // 3, len(r) - 1
        xs, ys = it[a:b + 1], [math.log(e) for e in el[a:b + 1]]
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        s = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
        print("%s: its %d-%d, EL %.2e -> %.2e, d log EL / d it = %+.5f, W %.9f -> %.9f, area spread %s"
              % (p, it[a], it[b], el[a], el[b], s, float(r[a]["energy"]), float(r[b]["energy"]), r[b]["area_spread"]))


if __name__ == "__main__":
    main()
