# bobenko-schroeder2005 Sec. 3.2, -bs_singular single: where exactly one beta at a vertex vanishes, the paper's
# steepest descent direction instead of the eps heuristic. On the twice linearly subdivided coarse torus (flat
# subdivided quads: vanishing betas) the rule changes the flow (W after 3 steps 184.2 against 202.3 with the
# heuristic), and the distributed computation (each vertex of a vanishing diamond counted by one rank) gives the
# same history on 1 and 2 ranks. Not checked: that the direction is the exact steepest descent (docs/bs_flow.md).
# nprocs: 1
source tests/lib.sh
M=tests/data/bs_torus_coarse2.obj
"$CS_BIN" -task flow -flow_type bs -mesh $M -bs_max_it 3 -history_csv "$TMP/h.csv" > /dev/null
"$CS_BIN" -task flow -flow_type bs -mesh $M -bs_max_it 3 -bs_singular single -history_csv "$TMP/s1.csv" > /dev/null
mpirun -n 2 "$CS_BIN" -task flow -flow_type bs -mesh $M -bs_max_it 3 -bs_singular single -history_csv "$TMP/s2.csv" > /dev/null
python3 - "$TMP" <<'PY'
import sys
d = sys.argv[1]
W = lambda f: [float(l.split(",")[1]) for l in list(open(d + "/" + f))[1:]]
h, s1, s2 = W("h.csv"), W("s1.csv"), W("s2.csv")
bad = 0
for ok, msg in ((len(s1) == 4 and abs(s1[-1] - h[-1]) > 1e-3 * h[-1], "the rule acts: W %.6g (single) vs %.6g (heuristic)" % (s1[-1], h[-1])),
                (len(s1) == len(s2) and max(abs(a - b) for a, b in zip(s1, s2)) < 1e-9 * s1[0], "1 and 2 ranks agree (max diff %.1e)" % max(abs(a - b) for a, b in zip(s1, s2))),
                (all(s1[i + 1] < s1[i] for i in range(3)), "W falls: " + " ".join("%.5g" % w for w in s1))):
    print(("ok  " if ok else "BAD ") + msg); bad += not ok
sys.exit(bad)
PY
