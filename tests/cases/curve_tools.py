"""Helpers of the curve_*.sh tests (plain python3, no numpy): read curve text files and history CSVs."""
import csv, json, math, sys

def points(path):
    """x, y (and kappa when present) of a text curve; a closed curve's repeated first point is dropped."""
    pts = [list(map(float, l.split())) for l in open(path) if l.strip() and not l.startswith('#')]
    if len(pts) > 1 and pts[0][:2] == pts[-1][:2]:
        pts.pop()
    return pts

def lengths(pts, closed=True):
    n = len(pts)
    return [math.dist(pts[i][:2], pts[(i + 1) % n][:2]) for i in range(n if closed else n - 1)]

def history(path):
    return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(path))]

def summary(path):
    return json.load(open(path))

def report(ok, msg):
    print(("ok  " if ok else "BAD ") + msg)
    return ok
