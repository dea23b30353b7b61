# The Step and Solve events of every flow (issue 37 point 1; registered in CSInitializePackage, class
# "confsurf flow"): -log_view counts one <Flow>Solve per run and one <Flow>Step per step tried. CSFlowLoop logs
# them for the curve, conformal and BS flows, so a rejected step is a Step event too (BS semi: accepted +
# rejected); the Willmore loop logs one Step per outer iteration plus the last one that evaluates and stops.
# The BS run rejects more steps (5) than -bs_max_it (4): the loop must leave the semi scheme's rejections to it.
# nprocs: 1 2
source tests/lib.sh
SPHERE="-gen icosphere -gen_level 2 -gen_deform_stretch 1.3,1,1"
run() { local name=$1; shift; timeout 60 $MPIEXEC "$CS_BIN" "$@" -summary "$TMP/$name.json" -log_view > "$TMP/$name.log" 2>&1 || { tail -20 "$TMP/$name.log"; exit 1; }; }
run curve -task curveflow -gen_curve noisy -gen_curve_n 200 -gen_curve_noise 1e-3 -curve_max_it 3
run conformal -task flow -flow_type conformal $SPHERE -flow_max_it 2
run bs -task flow -flow_type bs $SPHERE -bs_max_it 4 -bs_dt_rel 1000
run willmore -task flow -flow_type cgd $SPHERE -flow_max_it 3
python3 - "$TMP" <<'PY'
import json, re, sys
t = sys.argv[1]; ok = True
def count(name, event):  # the Count column of -log_view (the largest over the ranks)
    m = re.search(r'^%s\s+(\d+)\s' % event, open(f'{t}/{name}.log').read(), re.M)
    return int(m.group(1)) if m else -1
for name, flow, extra in (('curve', 'Curve', 0), ('conformal', 'Conformal', 0), ('bs', 'BS', None), ('willmore', 'Willmore', 1)):
    s = json.load(open(f'{t}/{name}.json'))
    want = s['iterations'] + (s['rejected'] if extra is None else extra)
    step, solve = count(name, f'CS{flow}Step'), count(name, f'CS{flow}Solve')
    good = step == want and solve == 1
    print(('ok  ' if good else 'BAD ') + f'{name}: CS{flow}Step {step} (want {want}), CS{flow}Solve {solve} (want 1)')
    ok &= good
s = json.load(open(f'{t}/bs.json'))
good = s['iterations'] == 4 and s['rejected'] == 5 and s['stop_reason'] == 'max_it'
print(('ok  ' if good else 'BAD ') + f"bs: {s['iterations']} steps, {s['rejected']} rejected, stop_reason {s['stop_reason']} (want 4, 5, max_it)")
ok &= good
sys.exit(0 if ok else 1)
PY
