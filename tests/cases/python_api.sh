# The Python interface (python/confsurf, docs/python.md) against bin/confsurf on the same input: info, flow (cgd,
# bs), conformal_flow, spin (rho as an array vs -rho FILE) and curve_flow give the same positions (to 1e-12; they
# agree to the bit), the same summary keys and values (all but the timings and the input's name) and the same
# history columns, serially and with the arrays on rank 0 under mpirun -n 2 (tests/cases/python_tools.py equal).
# cgd runs twice, first and last: a later call in the same process gives the same bits. (It did not on 2 ranks, 1.2e-11
# apart after 3 iterations, until PT-Scotch's random generator was reset before each partition: each call partitioned
# the same mesh differently; src/mesh/mesh_create.c.)
# nprocs: 1 2
source tests/lib.sh
export PYTHONPATH=$CS_ROOT/python
D=$TMP
"$CS_BIN" -task info -gen torus -gen_n 16 -gen_m 8 -gen_deform_bump 0.1 -o "$D/torus.obj" > /dev/null
"$CS_BIN" -task info -gen icosphere -gen_level 2 -gen_deform_bump 0.2 -o "$D/sphere.obj" > /dev/null
/usr/bin/python3 - "$D" <<'PY'
import sys, numpy as np
d = sys.argv[1]
V = np.array([[float(x) for x in l.split()[1:4]] for l in open(d + "/sphere.obj") if l.startswith("v ")])
np.savetxt(d + "/rho.txt", 0.5 * np.exp(-np.sum((V - [0, 0, 1]) ** 2, axis=1) / 0.3 ** 2), fmt="%.17g")
t = np.arange(60) * 2 * np.pi / 60
r = 1 + 0.3 * np.cos(5 * t)
P = np.c_[r * np.cos(t), r * np.sin(t)]
np.savetxt(d + "/star.txt", np.vstack([P, P[:1]]), fmt="%.17g")
PY
cli() { name=$1; shift; timeout 120 $MPIEXEC "$CS_BIN" "$@" -summary "$D/$name.json" > "$D/$name.log" 2>&1 || { cat "$D/$name.log"; echo "BAD: bin/confsurf $*"; exit 1; }; }
cli info -task info -mesh "$D/torus.obj" -o "$D/info.obj"
cli flow -task flow -mesh "$D/torus.obj" -flow_type cgd -flow_max_it 3 -o "$D/flow.obj" -history_csv "$D/flow.csv"
cli bs -task flow -mesh "$D/torus.obj" -flow_type bs -bs_max_it 3 -o "$D/bs.obj" -history_csv "$D/bs.csv"
cli conformal -task flow -flow_type conformal -mesh "$D/sphere.obj" -flow_max_it 2 -o "$D/conformal.obj" -history_csv "$D/conformal.csv"
cli spin -task spin -mesh "$D/sphere.obj" -rho "$D/rho.txt" -o "$D/spin.obj"
cli curve -task curveflow -curve "$D/star.txt" -curve_max_it 5 -o "$D/curve.txt" -history_csv "$D/curve.csv"
timeout 300 $MPIEXEC /usr/bin/python3 "$CS_ROOT/tests/cases/python_tools.py" equal "$D"
