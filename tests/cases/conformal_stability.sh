# Stability of the conformal flow's forward Euler step rho = -2 tau H (crane2013 Sec. 4: mu -> (1 - 2 tau) mu, stable
# for tau < 1): on the bumpy stretched level-4 icosphere W falls at every step at tau = 0.95, and at tau = 1.3 it
# grows above the input's W within 8 steps.
# The discrete step responds to rho with a factor c <= 1 (mu -> (1 - 2 c tau) mu; docs/conformal_flow.md
# "Stability"), so the paper's criterion holds for the effective step c tau: on the level-4 sphere bumped with
# sin(6x) sin(6y) sin(6z) (amplitude 0.01), c measured from one step at tau = 0.1 (|v| -> (1 - 2 c tau)|v|; 0.880),
# W falls at every one of 6 steps at tau = 0.95/c and grows at every step at tau = 1.05/c.
# nprocs: 1
source tests/lib.sh
run() { timeout 120 $MPIEXEC "$CS_BIN" -task flow -flow_type conformal -gen icosphere -gen_level 4 -gen_deform_bump 0.2 -gen_deform_stretch 1.5,1,0.8 -flow_max_it 8 -flow_rtol 0 "$@"; }
run -flow_tau 0.95 -history_csv "$TMP/a.csv" > "$TMP/log1"
run -flow_tau 1.3 -history_csv "$TMP/b.csv" > "$TMP/log2"
mode() { timeout 120 $MPIEXEC "$CS_BIN" -task flow -flow_type conformal -gen icosphere -gen_level 4 -gen_deform_bump 0.01 -gen_deform_bump_freq 6 -flow_rtol 0 "$@"; }
mode -flow_tau 0.1 -flow_max_it 1 -history_csv "$TMP/c.csv" > "$TMP/log3"
c=$(python3 -c "import csv,sys; r=list(csv.DictReader(open(sys.argv[1]))); print((1 - float(r[1]['vnorm']) / float(r[0]['vnorm'])) / 0.2)" "$TMP/c.csv")
mode -flow_tau "$(python3 -c "print(0.95 / $c)")" -flow_max_it 6 -history_csv "$TMP/below.csv" > "$TMP/log4"
mode -flow_tau "$(python3 -c "print(1.05 / $c)")" -flow_max_it 6 -history_csv "$TMP/above.csv" > "$TMP/log5"
python3 - "$TMP" "$c" <<'PY'
import sys, csv
t, c = sys.argv[1], float(sys.argv[2])
a = [float(r['willmore']) for r in csv.DictReader(open(t + '/a.csv'))]
b = [float(r['willmore']) for r in csv.DictReader(open(t + '/b.csv'))]
ok = all(y < x for x, y in zip(a, a[1:]))
print(("ok   " if ok else "FAIL ") + "tau 0.95: W falls at every step: " + " ".join(f"{w:.3f}" for w in a))
g = max(b) > 2 * b[0]
print(("ok   " if g else "FAIL ") + "tau 1.3: W grows above 2x the input's: " + " ".join(f"{w:.3f}" for w in b))
ok &= g
m = 0.5 < c < 1
print(("ok   " if m else "FAIL ") + f"response of the sin 6 mode on level 4: c = {c:.4f} (in (0.5, 1)): threshold 1/c = {1 / c:.3f}")
ok &= m
for name, sign, word in (('below', -1, 'falls'), ('above', 1, 'grows')):
    r = list(csv.DictReader(open(t + f'/{name}.csv')))
    w = [float(x['willmore']) for x in r]
    q = [float(y['vnorm']) / float(x['vnorm']) for x, y in zip(r, r[1:])]
    d = len(w) == 7 and all(sign * (y - x) > 0 for x, y in zip(w, w[1:]))
    print(("ok   " if d else "FAIL ") + f"tau = {'0.95' if sign < 0 else '1.05'}/c = {float(r[1]['tau']):.4f}: W {word} at every step: W/4pi - 1 " + " ".join(f"{x / 12.566370614359172 - 1:.5f}" for x in w) + "; |v| ratios " + " ".join(f"{x:.3f}" for x in q))
    ok &= d
sys.exit(0 if ok else 1)
PY
